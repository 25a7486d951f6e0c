#pragma once
// A held object against the ground (the height-span paper, 2.2 and 2.3):
// the collision test uses the HS map's lowest span bottoms as the object's
// underside (the ground model's Z-buffer from below), and the material the
// object meets goes two ways:
//   - the ground above the top of the lowest span (and above each higher
//     span's top, up to the span above it) goes onto that span: the object
//     scoops it (a bucket pressed into sand or dragged through it fills);
//     ground reaching into a higher span's solid is pushed onto that span's
//     top (material never lies inside the object);
//     While the object moves sideways, what it scoops does not stay on the
//     span where it came in: it is pushed back into the object, away from
//     the motion, along the cells behind (as far as no solid stands in the
//     way at its level), filling them from the farthest forward, each up to
//     the level it came in at (the ground's height there); what finds no
//     room stays where it came in. So a dragged bucket fills from its back,
//     as the DEM's grains are rammed in by those behind them, rather than
//     heaping at its lip (departure: the paper leaves the material on the
//     span that met it). Along the motion's main axis (x or y) only;
//     While it moves sideways, the lowest span's top takes in at most
//     intake_layer_m of the ground it meets in a cell (the mouth admits one
//     layer as it advances), and of that at most intake_fraction of the
//     ground above its top (a lip that admits a share of whatever depth it
//     cuts: the DEM's fill is a fixed share of the cut's depth, see
//     Intake); the ground above what it takes in is pushed ahead,
//     onto the first ground cell in front of the object along the motion
//     (no span of the map over it): the wedge a bucket drives ahead of its
//     lip, which the DEM shows and which spills around the bucket rather
//     than into it (issue 12; departure from the paper). Without a cell
//     ahead on the ground grid it goes in. Pressing (no sideways motion)
//     takes in everything;
//     With a lip wedge (heightspan.wedge_source: lip, both or split; drag_wedge.h), its
//     fraction of what is pushed ahead goes into the object's wedge instead
//     of onto the cell ahead (only where there is a cell ahead, as above);
//   - what is left between the lowest span's bottom and top is the ground
//     model's intersection, compressed and displaced as the ground model
//     does (models/ground/displacement.h), by the caller.
// Departure: the map samples the object at its own cell centres, which lie
// within half a cell of the ground's (the map moves with the object); each
// map cell stands for the ground cell holding its centre.

#include <array>
#include <limits>

#include "models/ground/collision.h"
#include "models/heightspan/span_map.h"

namespace repose {

struct DragWedge;
struct GroundModel;
struct GroundState;

// Where the ground pushed ahead of a lip goes (drag_wedge.h): `fraction` of
// it into `wedge` (none when null), the rest onto the cell ahead.
struct LipWedge {
  DragWedge* wedge = nullptr;
  double fraction = 0.0;  // [0, 1]
};

// What the lowest span's top takes in of the ground above it, per cell it
// advances into while the object moves sideways: fraction × that ground, at
// most layer_m; the rest is pushed ahead. The DEM's scoops hold a fixed share
// of the cut: at the end of the drag (t = 0.8 s) the seeds' mean held mass is
// 0.71, 0.71 and 0.70 of the bed (1500 kg/m^3) in a box the bucket's inside
// width (7 cm) wide, its drag (9 cm) long and its lowest edge's depth deep
// (12.5, 10 and 7.5 mm; data/ref_scoop, ref_scoop_medium, ref_scoop_shallow),
// so the fill is proportional to the depth. A layer limit takes the same
// layer from every cut deeper than the layer, and a model fitted with one to
// the deep and middle scoops under-fills the shallow one by 6.7 % (issue 12).
// With the fraction, the lip's push-ahead split into the wedge
// (heightspan.wedge_source: split) and the over-lip share, fitted to the same
// two scoops, it holds the shallow one within the 6 % at every stage
// (experiments/heightspan_scoop_fit.yaml; its report.md has the numbers).
struct Intake {
  double layer_m = std::numeric_limits<double>::infinity();  // (0, inf]
  double fraction = 1.0;                                      // (0, 1]
};

// The ground cell holding map cell (i, j)'s centre is (i + di, j + dj).
struct CellOffset {
  int di = 0, dj = 0;
};
CellOffset ground_offset(const Grid& map, const Grid& ground);

// The cell step opposite to the object's horizontal motion along its main
// axis, x or y ({0, 0} when it does not move sideways).
std::array<int, 2> back_step(const Eigen::Vector3d& motion_m);

// The lowest span bottoms over the ground cells the map covers, lowered by
// shear_layer_m (heightspan.shear_layer_m: the grains beneath the object's
// bottom that it drags along meet it as its own solid); empty when the map
// has no span over the grid. top_m: the object's highest point.
Underside underside_of(const SpanMap& map, const Grid& ground, double top_m, double shear_layer_m = 0.0);

// Moves the ground above the spans' tops onto them (see above); returns
// the volume moved (m^3). Cells that changed join the erosion memory.
// motion_m: the object's move this substep; ground scooped while it moves
// sideways is pushed back into it (ground_contact.cpp: push_back_into).
// intake: what is taken in per cell while moving sideways (above); lip:
// where what is pushed ahead goes.
double take_up_ground(const GroundModel& model, SpanMap* map, GroundState* state,
                      const Eigen::Vector3d& motion_m = Eigen::Vector3d::Zero(), Intake intake = {}, LipWedge lip = {});

}  // namespace repose
