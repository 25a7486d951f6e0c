#pragma once
// The ground a dragged object's sides carry along (issue 12; departure from
// the paper, an option: heightspan.side_cut_m, default 0).
//
// Behind the fitted bucket the LIGGGHTS trench is deeper across its whole
// width, most on its flanks: averaged over the three beds of the deep scoop
// (x 0.05-0.11 m), 3-4 mm lower than the two-depth fit's
// (experiments/heightspan_scoop_fit_two_depths_wedge_split.yaml) at 5-30 mm
// from the side walls and 1-2 mm at the centre, as if each flank were shifted
// outwards by about a grain (4.5 mm); its trench is 75-80 mm wide against the
// model's 70-72.5, and the DEM digs 21-24 cm^3 more than the model at every
// depth (the calibration report's surface table). Grains in contact with a
// side wall are dragged along by it and, with those resting on them, fail
// ahead of the lip with the wedge; the height-span model's spans only meet
// the ground under their own footprint.
//
// With side_cut_m w > 0, while a held object drags (drags(), drag_wedge.h),
// the ground beside each of its two outermost lanes across the drag's main
// axis (x or y), within w of the lane, is cut down to the object's lowest
// span bottom (the depth its lip cuts to), in the ground column of the
// lane's frontmost span, where the lip meets new ground. The cut goes into
// the object's wedge (drag_wedge.h), laid ahead of the object when it stops
// dragging. A cell partly within w is cut by the fraction within. Erosion
// then settles the trench wall the cut leaves.
//
// Fitted with the compression wedge to the deep and middle scoops on each of
// their first three LIGGGHTS beds (experiments/heightspan_scoop_fit_two_depths_
// side_cut*.yaml, four starts) the cut is 2.1-4.1 mm, the lowest cost keeps
// 2.9 mm, and cross-validated between those two depths the cut predicts the
// left-out depth better than none (experiments/heightspan_scoop_side_cut_cv_*.yaml).
// On all seven beds per depth the fit keeps 0.6 mm at the cost without it
// (..._side_cut_seven_beds_nested.yaml): seven beds do not select the cut.

#include "models/heightspan/drag_wedge.h"

namespace repose {

// Cuts the ground beside `map`'s sides (above) into `wedge` when `motion_m`
// is a drag and width_m > 0; the cut cells join the erosion memory. Returns
// the volume cut (m^3).
double cut_beside(const GroundModel& model, const SpanMap& map, double width_m, const Eigen::Vector3d& motion_m,
                  DragWedge* wedge, GroundState* state);

}  // namespace repose
