#pragma once
// Height queries on the terrain mesh: a triangle mesh whose xy projection is
// a planar triangulation (contour_triangulation.h), with a uniform bucket
// grid over the triangles' xy boxes so a query looks at a few triangles.

#include <optional>
#include <vector>

#include "models/core/geometry/height_field.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/terrain/polygon_2d.h"

namespace repose {

class TerrainSurface {
 public:
  explicit TerrainSurface(TriangleMesh mesh);

  const TriangleMesh& mesh() const { return mesh_; }
  // Height (m) of the mesh above (x, y); nullopt outside every triangle.
  std::optional<double> height_at(const Point2& p) const;
  // Indices of the faces whose xy box meets the box [lo, hi] (each once).
  std::vector<int> faces_near(const Point2& lo, const Point2& hi) const;

 private:
  int bucket_x(double x) const;
  int bucket_y(double y) const;

  TriangleMesh mesh_;
  Point2 lo_ = Point2::Zero();
  double bucket_m_ = 1.0;
  int nx_ = 1;
  int ny_ = 1;
  std::vector<std::vector<int>> buckets_;  // ny_ rows by nx_ columns
};

// The mesh sampled at the centres of the cells of `grid` (bilinear within a
// triangle, i.e. the mesh's own height); cells outside the mesh get
// outside_height_m (the plain around the outermost key contour).
HeightField sample_height_field(const TerrainSurface& surface, const Grid& grid, double outside_height_m);

// A grid of cell_size_m covering the mesh's xy box plus one cell all round.
Grid covering_grid(const TriangleMesh& mesh, double cell_size_m);

}  // namespace repose
