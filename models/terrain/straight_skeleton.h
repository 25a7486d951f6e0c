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
  // The roof over p: the distance at which the shrinking boundary passes p
  // (the distance from p to the line of the edge whose skeleton face holds
  // it); 0 outside the polygon.
  double roof_time_m(const Point2& p) const;

 private:
  struct Face {
    Polygon2 outline;
    Point2 edge_from, edge_to;  // the polygon edge the face belongs to
  };
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<SkeletonNode> nodes_;
  std::vector<Face> faces_;
  double vanish_time_m_ = 0.0;
};

// Outward offsets of a simple polygon by its exterior straight skeleton
// (mitred corners: the dilation in the skeleton's own distance, the same
// distance the interior roof uses).
class ExteriorSkeleton {
 public:
  // polygon: simple, counter-clockwise; offsets up to max_distance_m (> 0).
  ExteriorSkeleton(const Polygon2& polygon, double max_distance_m);
  ~ExteriorSkeleton();
  ExteriorSkeleton(ExteriorSkeleton&&) noexcept;
  ExteriorSkeleton& operator=(ExteriorSkeleton&&) noexcept;

  double max_distance_m() const { return max_distance_m_; }
  // The outer boundary of the polygon grown by distance_m in (0,
  // max_distance_m), counter-clockwise. Pockets the growth encloses (inner
  // boundaries, where a concave polygon's arms grow together) are filled.
  Polygon2 offset(double distance_m) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double max_distance_m_ = 0.0;
};

}  // namespace repose
