#pragma once
// What displacement (displacement.cpp) and the routing of its excess
// (excess_routing.cpp) share about one contact: the contact cells over the
// footprint, the material each carries, and the direction of a drag.
// Internal to the ground model; not a public interface.

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "models/ground/collision.h"
#include "models/ground/received.h"

namespace repose {

inline constexpr std::array<std::array<int, 2>, 4> kNeighbours = {{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};

// The in-plane direction of a drag, with negligible components snapped to
// exactly 0, so that a neighbour offset is forward, lateral (o . d == 0
// exactly) or backward, the same for a motion and its mirror image.
struct DragDirection {
  static constexpr double kEps = 1e-9;
  bool active = false;
  double dx = 0.0, dy = 0.0;
  double along(int oi, int oj) const { return oi * dx + oj * dy; }
  bool backward(int oi, int oj) const { return active && along(oi, oj) < -kEps; }
  bool forward(int oi, int oj) const { return active && along(oi, oj) > kEps; }
};

DragDirection drag_direction(const Eigen::Vector3d& motion_m, double cell_size_m);

// Local arrays over the footprint of one contact.
struct ContactRegion {
  Footprint fp;
  std::vector<int> dist;  // 0: free cell; >= 1: contact cell, distance to the border
  std::vector<double> carry;
  std::vector<int> cells;  // local indices of contact cells
  int local(int i, int j) const { return (j - fp.j0) * fp.ni + (i - fp.i0); }
  int gi(int l) const { return fp.i0 + l % fp.ni; }
  int gj(int l) const { return fp.j0 + l / fp.ni; }
  bool is_contact(int i, int j) const { return fp.contains(i, j) && dist[local(i, j)] != 0; }
};


}  // namespace repose
