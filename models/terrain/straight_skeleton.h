#pragma once
// The interior straight skeleton of a simple polygon and its inward offsets
// (seed paper 003, sec. 3.1: every edge moves inward parallel to itself at
// unit speed; edge events and split events change the topology). CGAL 5.5
// computes both, events included; this file keeps CGAL out of every other
// translation unit (it is slow to compile).
//
// Departure from the paper: the paper builds its own skeleton (an event loop
// over eq. (1) distances and bisector/edge crossing tests); CGAL's is exact in
// its predicates. eq. (1) is kept in edge_event.h and checked against this
// skeleton in the tests.

#include <memory>
#include <vector>

#include "models/terrain/polygon_2d.h"

namespace repose {

// A vertex of the skeleton inside the polygon: where edges met, and the
// offset distance (m) at which they met.
struct SkeletonNode {
  Point2 point_m;
  double time_m = 0.0;
};

class StraightSkeleton {
 public:
  // polygon: simple, counter-clockwise. Throws InputError if CGAL cannot
  // build the skeleton (a degenerate polygon).
  explicit StraightSkeleton(const Polygon2& polygon);
  ~StraightSkeleton();
  StraightSkeleton(StraightSkeleton&&) noexcept;
  StraightSkeleton& operator=(StraightSkeleton&&) noexcept;

  const std::vector<SkeletonNode>& nodes() const { return nodes_; }
  // The latest event: the offset distance at which the polygon vanishes.
  double vanish_time_m() const { return vanish_time_m_; }
  // The polygon shrunk by distance_m (> 0): zero or more simple,
  // counter-clockwise polygons (split events give several).
  std::vector<Polygon2> offset(double distance_m) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<SkeletonNode> nodes_;
  double vanish_time_m_ = 0.0;
};

}  // namespace repose
