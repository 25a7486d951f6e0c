#pragma once
// Splitting a building footprint into convex pieces (seed paper 003, sec. 4
// and 5.2: collision detection needs convex parts, so a concave part is
// decomposed into "a set of convex hulls"). CGAL's optimal convex partition
// (Greene's dynamic programme, O(n^4)) gives the fewest pieces; above
// kOptimalPartitionMaxVertices vertices the Hertel-Mehlhorn approximation
// (at most four times the optimum) keeps it fast. A rectilinear footprint
// splits into rectangles (a convex rectilinear polygon is a rectangle).

#include <vector>

#include "models/terrain/polygon_2d.h"

namespace repose {

inline constexpr std::size_t kOptimalPartitionMaxVertices = 64;

// polygon: simple, counter-clockwise. Returns counter-clockwise convex pieces
// whose union is the polygon and whose interiors are disjoint.
std::vector<Polygon2> convex_partition(const Polygon2& polygon);

}  // namespace repose
