#pragma once
// The snow surface of one map as a triangle mesh (the snow paper 2.5: the
// snow shape as polygons, rendered with the scene): one vertex per covered
// cell centre at base z + snow depth, two triangles per square of four
// covered neighbouring centres. Cells with less than min_depth_m of snow are
// left out, so bare ground does not hide under a sheet at its own height.
// For OBJ output (models/core/io/mesh_io.h) and figures.

#include "models/core/geometry/height_field.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/snow/snow_map.h"

namespace repose {

TriangleMesh snow_surface_mesh(const SnowMap& map, const ArrayXXdR& depth_m, double min_depth_m = 0.0);

}  // namespace repose
