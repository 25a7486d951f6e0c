#pragma once
// Key contours to terrain, the whole pipeline of seed paper 003 (sec. 3-4):
// validate and nest the key contours, shrink them by their straight
// skeletons into contours at the chosen interval, smooth them with
// B-splines, triangulate all contour points (constrained Delaunay), and
// sample the mesh into a height field for the heuristic models.

#include <vector>

#include "models/core/geometry/height_field.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/terrain/inner_contours.h"
#include "models/terrain/key_contour.h"
#include "models/terrain/terrain_options.h"

namespace repose {

struct TerrainSummary {
  int key_contour_count = 0;
  int contour_count = 0;  // key and generated
  int summit_point_count = 0;
  int triangle_count = 0;
  double min_height_m = 0.0;
  double max_height_m = 0.0;
  double relief_m() const { return max_height_m - min_height_m; }
};

struct Terrain {
  std::vector<KeyContour> keys;  // counter-clockwise, validated
  ContourNesting nesting;
  ContourSet contours;
  TriangleMesh mesh;          // faces counter-clockwise seen from above
  HeightField height_field;   // cells outside the outer key contours: their lowest height
  TerrainSummary summary;
};

// Throws InputError for invalid options or key contours (one line naming the
// field or the contour).
Terrain build_terrain(std::vector<KeyContour> keys, const TerrainOptions& options);

}  // namespace repose
