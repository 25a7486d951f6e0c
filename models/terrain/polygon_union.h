#pragma once
// The union of simple polygons, as the closed loops that bound it (outer
// boundaries and the boundaries of enclosed holes), by CGAL's 2-D Boolean
// operations on exact coordinates. Used for the contours where the ground
// rising from a key contour meets the skirt of a nested key contour
// (inner_contours.h).

#include <vector>

#include "models/terrain/polygon_2d.h"

namespace repose {

// polygons: simple, counter-clockwise. Returns every boundary loop of their
// union, each counter-clockwise (a hole's loop too: a contour is a loop).
std::vector<Polygon2> union_boundaries(const std::vector<Polygon2>& polygons);

}  // namespace repose
