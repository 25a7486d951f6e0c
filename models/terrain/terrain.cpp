#include "models/terrain/terrain.h"

#include <algorithm>
#include <cmath>

#include "models/core/base/error.h"
#include "models/terrain/contour_triangulation.h"
#include "models/terrain/terrain_surface.h"

namespace repose {

Terrain build_terrain(std::vector<KeyContour> keys, const TerrainOptions& options) {
  options.validate();
  Terrain terrain;
  terrain.nesting = validate_key_contours(&keys);
  terrain.keys = std::move(keys);
  terrain.contours = generate_contours(terrain.keys, terrain.nesting, options);

  double plain_height_m = INFINITY;
  for (int r : terrain.nesting.roots) plain_height_m = std::min(plain_height_m, terrain.keys[r].height_m);
  terrain.mesh = triangulate_contours(terrain.contours);
  REPOSE_DEMAND(!terrain.mesh.empty());
  const TerrainSurface surface(terrain.mesh);
  terrain.height_field = sample_height_field(surface, covering_grid(terrain.mesh, options.cell_size_m), plain_height_m);

  TerrainSummary& s = terrain.summary;
  s.key_contour_count = static_cast<int>(terrain.keys.size());
  s.contour_count = static_cast<int>(terrain.contours.contours.size());
  s.summit_point_count = static_cast<int>(terrain.contours.summits.size());
  s.triangle_count = static_cast<int>(terrain.mesh.F.rows());
  s.min_height_m = terrain.mesh.V.col(2).minCoeff();
  s.max_height_m = terrain.mesh.V.col(2).maxCoeff();
  return terrain;
}

}  // namespace repose
