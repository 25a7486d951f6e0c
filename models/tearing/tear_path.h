#pragma once
// The tear measured (the seed paper's section 4 compares along- and
// across-grain tears by eye: "across the grain the tear curves more and its
// edge is rougher"). Here the tear is the largest 8-connected set of torn
// cells (the notch counts as torn; on a tie in size the set holding the
// notch, else the one holding the lowest cell index), so a tear that starts
// at a grip's corner instead of the notch is still the tear; its
// path is the centroid of that set in each row of cells it crosses, from the
// top row down. The tear is assumed to run from the top edge downwards, as
// between seed_twist_grips; a tear that turns sideways is under-counted
// (one point per row).

#include <vector>

#include <Eigen/Core>

#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_state.h"

namespace repose {

struct TearPath {
  // Path points (x, y) in rest coordinates (m), top row first; empty when
  // nothing is torn.
  std::vector<Eigen::Vector2d> points;
  int tear_cells = 0;   // cells in the tear (the notch included)
  int stray_cells = 0;  // torn cells not connected to it (e.g. at a grip)
  bool holds_notch = false;  // whether the tear runs from the notch
  // Depth reached from the top edge (m): rows crossed x cell size.
  double depth_m = 0.0;
  // Length of the path polyline (m) from its first to its last point.
  double path_length_m = 0.0;
  // path_length / distance between its ends; 1 for a straight tear, 1 also
  // for a single point.
  double tortuosity = 1.0;
  // RMS distance (m) of the points from their least-squares line x = a + b y:
  // how rough the tear is about its own direction.
  double roughness_m = 0.0;
  // RMS of x - x_top (m): how far the tear strays from straight down.
  double deviation_m = 0.0;
};

TearPath measure_tear_path(const SheetModel& model, const SheetState& state);

}  // namespace repose
