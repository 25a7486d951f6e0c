#pragma once
// The terrain surface: a constrained Delaunay triangulation (CGAL) of every
// contour point, with each contour's edges as constraints so no triangle
// crosses a contour, and of the summit points (seed paper 003, sec. 4 step
// (8): Delaunay triangles over the points of the B-spline contours). Each
// vertex carries its contour's height, so the mesh interpolates every
// contour exactly; triangles outside the outermost key contours are
// dropped. Being a planar triangulation lifted vertically, the mesh is a
// height field: every vertical line inside the outer contours meets it once.
//
// Departure from the paper: the paper triangulates the points without
// constraints (its own VB.NET Delaunay); without them a triangle could join
// two points of the same contour across a valley and flatten it.

#include "models/core/geometry/triangle_mesh.h"
#include "models/terrain/inner_contours.h"

namespace repose {

// Faces are counter-clockwise seen from above (+z); a face belongs to the
// terrain when at least one contour encloses it (all contours lie inside the
// outermost key contours). A contour crossing another is an internal error
// (the construction in inner_contours.h rules it out).
TriangleMesh triangulate_contours(const ContourSet& contours);

}  // namespace repose
