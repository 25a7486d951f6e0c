#pragma once
// Closed polygons in the horizontal plane and the few predicates the terrain
// pipeline needs. A Polygon2 lists its vertices once (the closing edge from
// the last vertex back to the first is implied); outer boundaries are kept
// counter-clockwise (positive signed area).

#include <Eigen/Core>
#include <vector>

namespace repose {

using Point2 = Eigen::Vector2d;
using Polygon2 = std::vector<Point2>;

// Shoelace area (m^2): positive when counter-clockwise.
double signed_area_m2(const Polygon2& polygon);
// The same polygon, counter-clockwise.
Polygon2 counter_clockwise(Polygon2 polygon);

// True when p lies strictly inside (even-odd rule; points on an edge may go
// either way, callers keep clear of edges).
bool contains_point(const Polygon2& polygon, const Point2& p);

// Closed segments [a, b] and [c, d] share a point.
bool segments_intersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d);
double segment_distance_m(const Point2& a, const Point2& b, const Point2& c, const Point2& d);
double point_segment_distance_m(const Point2& p, const Point2& a, const Point2& b);

// No two non-adjacent edges meet and no edge has zero length (O(n^2)).
bool is_simple(const Polygon2& polygon);
// Some edge of a meets some edge of b.
bool boundaries_cross(const Polygon2& a, const Polygon2& b);
// Smallest distance between the boundaries of a and b (0 when they cross).
double boundary_distance_m(const Polygon2& a, const Polygon2& b);
// a lies strictly inside b: the boundaries do not meet and a vertex of a is inside b.
bool nested_inside(const Polygon2& a, const Polygon2& b);

// Inserts vertices on every edge so that no edge is longer than spacing_m;
// the original vertices are kept (a key contour's corners stay exact).
Polygon2 densified(const Polygon2& polygon, double spacing_m);

}  // namespace repose
