#pragma once
// The wedge a held object drives ahead of it while it drags (issue 12;
// departure from the paper, an option: heightspan.wedge_fraction, default 0).
//
// The ground model compresses away (1 - alpha) of what an object's underside
// intersects (models/ground/displacement.h). For a bucket dragged through
// loose sand that loses most of what its lip displaces: at the scoop fit's
// alpha 0.30 the held-out shallow scoop compresses 53 cm^3 of the 82 cm^3 it
// digs, where the LIGGGHTS beds lose 18 cm^3 net and drive the rest ahead
// of the lip as a wedge (experiments/heightspan/scoop_profiles.py). A lower
// compression cannot replace it: what the displacement leaves in front of
// the lip is met again in the next cell and taken in (at alpha 1 the fitted
// bucket holds 15 % (deep) / 45 % (shallow) too much).
//
// With wedge_fraction f > 0, that fraction of what a held object's drag
// compresses is kept instead, as the object's wedge: a volume that travels in
// front of the object, out of the lip's reach (the DEM's wedge spills around
// the bucket rather than into it), so the fill is the same as without it.
// When the object stops dragging (it lifts, presses or stands), the wedge is
// laid on the ground in front of it along the last drag's main axis (x or
// y), in equal shares on the first ground cell ahead of the object's
// frontmost span in every lane (row or column of its span map) that has a
// span; erosion settles it from there. What finds no cell ahead on the grid
// leaves the grid (the ledger's left_grid_m3). The wedge is counted in the
// ledger while carried (heightspan_state.h: accounted_m3).
//
// That wedge comes from the wall band's compression, so it is the same on a
// deep and a shallow cut (31 cm^3 on both scoops), where the DEM's grows with
// the depth (74 / 53 cm^3). With heightspan.wedge_source: lip it is what the
// lip pushes ahead instead (ground_contact.h: the ground above the intake
// layer in each cell the lip advances into): that fraction of it goes into
// the wedge rather than onto the ground cell in front of the object, so the
// wedge grows with the cut's depth, and the drag's compression stays
// compressed; it is laid as above. With wedge_source: both, the wedge keeps
// its fraction of both (the lip's push-ahead and the wall band's compression:
// everything the bucket's front drives). Refitted to the deep scoop, neither
// holds the held-out shallow scoop's mass within 6 % (lip +17 %, both -20 %;
// experiments/heightspan_scoop_fit_lipwedge.yaml, _bothwedge.yaml).
//
// With one fraction for both, a fit that keeps the fill keeps little of
// either (0.18 of each, fitted to two depths), since what the lip's wedge
// takes the bucket does not: the wedge is then too small to make a heap
// for the dump to land on as the DEM's does. With wedge_source: split the
// two parts have their own fractions, wedge_fraction the compression's and
// heightspan.lip_wedge_fraction the lip's, so a fit can keep the wall
// band's compression whole and as much of the lip's push-ahead as the
// depth's trend asks. Fitted to the deep and middle scoops, it keeps none of
// the lip's (experiments/heightspan_scoop_fit_two_depths_wedge_split.yaml),
// and cross-validated between those two depths 0 predicts better than 0.2
// (experiments/heightspan_scoop_lip_cv_*.yaml).
//
// Pressing (heightspan.press_fraction, default 0): lowering the bucket into
// the bed compresses (1 - alpha) of what its underside meets, as the ground
// model does; at the two-depth compression fit that is 39 cm^3 on the deep
// scoop, the whole run's net loss, where the DEM loses 15-17 cm^3 over the
// whole scoop. With press_fraction p > 0 a held object that presses (does
// not drag) displaces alpha + p (1 - alpha) of what it meets around its
// contact instead, so the drag then meets it again. Fitted with the wedge
// to two depths it is 0.25, and neither held-out target is met
// (experiments/heightspan_scoop_fit_two_depths_press.yaml).
//
// Pressed into the wedge (heightspan.press_wedge_fraction, default 0): that
// fraction of what the pressing compresses (after press_fraction) is kept
// in the wedge instead, and the drag that follows drives it ahead and lays
// it where it ends, as the DEM's bucket bulldozes the sand it pushed down
// while being lowered. Without it the fit of experiments/heightspan_scoop_fit.yaml
// at release_speed_m_s compressed 51 cm^3 while lowering the deep scoop's
// bucket, and its dumped heap held 62 cm^3 where the LIGGGHTS beds' holds
// 111 cm^3 (their net loss over the whole scoop is 16 cm^3). A wedge of
// pressed material alone has no direction to be laid along: it waits while
// the object presses or stands and goes back to the compressed volume if
// the object lifts off without dragging.
//
// Over the lip (heightspan.over_lip_fraction, default 0): the DEM's bucket
// fills at a rate that falls with the cut's depth more slowly than the
// model's (from the deep to the shallow scoop, 58 -> 40 g per 0.4 s of drag
// against the two-depth fit's 50 -> 27 g): grains that the lip's face drives
// ahead climb the wedge and roll over the lip into the mouth, whatever the
// depth. With over_lip_fraction g > 0, that fraction of what the drag's
// compression keeps in the wedge each substep (keep_in_wedge) goes into the
// object instead, in equal shares onto the lowest span of every lane's
// frontmost cell (span_lanes.h: where the lip meets new ground); span
// erosion carries it in from there, as it does the take-up. Fitted with
// the rest to the deep and middle scoops on seven beds each (nested in the
// fit without it), the share is small but determined, 0.030 +- 0.007, and
// lowers the cost by 0.9 %; the held-out shallow scoop's masses move 0.6-0.7
// points closer to the DEM's mean (experiments/heightspan_scoop_fit_two_depths_over_lip_nested.yaml).
// Two other starts (0.1, 0.3) end in higher minima. With an intake fraction
// instead of the intake layer (ground_contact.h: Intake) the fit has the
// band's compression (alpha near 0: all of it) kept and about two thirds of
// it rolling over the lip, the depth-independent part of the fill
// (experiments/heightspan_scoop_fit.yaml).

#include <array>

#include <Eigen/Core>

#include "models/heightspan/span_map.h"

namespace repose {

struct GroundModel;
struct GroundState;

struct DragWedge {
  double volume_m3 = 0.0;         // carried in front of the object
  std::array<int, 2> back{0, 0};  // the cell step against the last drag, along its main axis
};

// True when a held object's motion this substep is a drag, as the ground's
// displacement decides it (displacement.h: is_drag); otherwise it presses.
bool drags(const GroundModel& model, const Eigen::Vector3d& motion_m);

// The shares of what a held object compresses that its wedge keeps: of a
// drag's (wedge_fraction, by wedge_source) and of a press's
// (press_wedge_fraction).
struct WedgeFractions {
  double drag = 0.0;   // [0, 1]
  double press = 0.0;  // [0, 1]
};

// After a held object's displacement this substep compressed `compressed_m3`:
// moves `fractions.drag` of it (when `motion_m` is a drag, displacement.h:
// is_drag) or `fractions.press` (when it presses) from the ledger's
// compressed volume into the wedge. A drag also remembers its direction,
// whatever its fraction: it drives what a press kept, which waits in the
// wedge until then (or goes back to the compressed volume if the object
// lifts off first: lay_wedge). Returns the volume kept.
double keep_in_wedge(const GroundModel& model, double compressed_m3, WedgeFractions fractions,
                     const Eigen::Vector3d& motion_m, DragWedge* wedge, GroundState* state);

// Over the lip (above): moves `fraction` of `kept_m3`, what keep_in_wedge
// kept this substep from a drag, from the wedge onto the map's lane fronts. Returns the
// volume moved.
double feed_over_lip(const Grid& ground, double kept_m3, double fraction, DragWedge* wedge, SpanMap* map);

// wedge_source lip: keeps `volume_m3` that the object's lip pushed ahead
// while moving against the cell step `back` (not {0, 0}) in the wedge.
void keep_pushed_ahead(double volume_m3, std::array<int, 2> back, DragWedge* wedge);

// When `motion_m` is not a drag and the wedge holds material, lays it in
// front of the object (above) and empties it; the cells join the erosion
// memory. Returns the volume laid on the ground. A wedge of pressed material
// alone (no drag yet, so no direction to lay it along) waits while the
// object presses or stands, and goes back to the compressed volume when it
// moves up.
double lay_wedge(const GroundModel& model, const SpanMap& map, const Eigen::Vector3d& motion_m, DragWedge* wedge,
                 GroundState* state);

}  // namespace repose
