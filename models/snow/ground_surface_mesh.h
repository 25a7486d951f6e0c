#pragma once
// The ground height field as a triangle mesh for the shadow maps and the ray
// casts: one vertex per cell centre at the cell's height, two triangles per
// square of four neighbouring centres. Its top-down image at the cell
// centres is the heights themselves (the ground's snow map is read from the
// height field directly, not rasterised). A 1-cell-wide field has no
// triangles: it casts no shadow.

#include "models/core/geometry/height_field.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {

TriangleMesh ground_surface_mesh(const HeightField& ground);

}  // namespace repose
