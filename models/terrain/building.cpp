#include "models/terrain/building.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/terrain/convex_partition.h"

namespace repose {

void BuildingFootprint::validate() const {
  const std::string label = fmt::format("terrain: building '{}'", name);
  if (polygon_m.size() < 3 || !is_simple(polygon_m)) {
    throw InputError(fmt::format("{}: footprint_m must be a simple polygon of at least 3 vertices", label));
  }
  if (storeys < 1) throw InputError(fmt::format("{}: storeys = {} must be >= 1", label, storeys));
  if (!(std::isfinite(storey_height_m) && storey_height_m > 0.0)) {
    throw InputError(fmt::format("{}: storey_height_m = {} must be > 0", label, storey_height_m));
  }
  if (!(gap_m >= 0.0 && gap_m < storey_height_m)) {
    throw InputError(fmt::format("{}: gap_m = {} must lie in [0, storey_height_m)", label, gap_m));
  }
  if (!(std::isfinite(bulk_density_kg_m3) && bulk_density_kg_m3 > 0.0)) {
    throw InputError(fmt::format("{}: bulk_density_kg_m3 = {} must be > 0", label, bulk_density_kg_m3));
  }
  if (!(std::isfinite(joint_break_force_n) && joint_break_force_n > 0.0)) {
    throw InputError(fmt::format("{}: joint_break_force_n = {} must be > 0", label, joint_break_force_n));
  }
}

namespace {

// where segment [a, b] crosses segment [c, d] (a point), if it does properly
std::optional<Point2> crossing(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const Point2 r = b - a, s = d - c;
  const double denom = r.x() * s.y() - r.y() * s.x();
  if (denom == 0.0) return std::nullopt;
  const Point2 ac = c - a;
  const double t = (ac.x() * s.y() - ac.y() * s.x()) / denom;
  const double u = (ac.x() * r.y() - ac.y() * r.x()) / denom;
  if (t < 0.0 || t > 1.0 || u < 0.0 || u > 1.0) return std::nullopt;
  return a + t * r;
}

}  // namespace

std::optional<double> highest_ground_m(const TerrainSurface& surface, const Polygon2& polygon) {
  const TriangleMesh& mesh = surface.mesh();
  std::optional<double> best;
  auto take = [&](const Point2& p) -> bool {
    const std::optional<double> h = surface.height_at(p);
    if (h && (!best || *h > *best)) best = h;
    return h.has_value();
  };
  Eigen::AlignedBox2d box;
  for (const Point2& p : polygon) {
    box.extend(p);
    if (!take(p)) return std::nullopt;
  }
  for (int f : surface.faces_near(box.min(), box.max())) {
    for (int k = 0; k < 3; ++k) {
      const Point2 a(mesh.V(mesh.F(f, k), 0), mesh.V(mesh.F(f, k), 1));
      const Point2 b(mesh.V(mesh.F(f, (k + 1) % 3), 0), mesh.V(mesh.F(f, (k + 1) % 3), 1));
      if (contains_point(polygon, a)) take(a);
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        const std::optional<Point2> x = crossing(polygon[i], polygon[(i + 1) % polygon.size()], a, b);
        if (x) take(*x);
      }
    }
  }
  return best;
}

TriangleMesh prism_mesh(const Polygon2& convex_ccw, double bottom_m, double top_m) {
  const int n = static_cast<int>(convex_ccw.size());
  REPOSE_DEMAND(n >= 3 && top_m > bottom_m);
  TriangleMesh mesh;
  mesh.V.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    mesh.V.row(i) << convex_ccw[i].x(), convex_ccw[i].y(), bottom_m;
    mesh.V.row(n + i) << convex_ccw[i].x(), convex_ccw[i].y(), top_m;
  }
  mesh.F.resize(2 * (n - 2) + 2 * n, 3);
  int f = 0;
  for (int i = 1; i + 1 < n; ++i) {
    mesh.F.row(f++) << 0, i + 1, i;              // bottom, facing down
    mesh.F.row(f++) << n, n + i, n + i + 1;      // top, facing up
  }
  for (int i = 0; i < n; ++i) {
    const int j = (i + 1) % n;
    mesh.F.row(f++) << i, j, n + j;              // sides, facing out
    mesh.F.row(f++) << i, n + j, n + i;
  }
  return mesh;
}

std::vector<BuildingPart> building_parts(const BuildingFootprint& footprint, const TerrainSurface& surface) {
  footprint.validate();
  const Polygon2 polygon = counter_clockwise(footprint.polygon_m);
  const std::optional<double> base_m = highest_ground_m(surface, polygon);
  if (!base_m) {
    throw InputError(fmt::format("terrain: building '{}': the footprint is not entirely over the terrain",
                                 footprint.name));
  }
  const std::vector<Polygon2> pieces = convex_partition(polygon);
  std::vector<BuildingPart> parts;
  for (int s = 0; s < footprint.storeys; ++s) {
    const double bottom = *base_m + s * footprint.storey_height_m;
    const double top = bottom + footprint.storey_height_m - footprint.gap_m;
    for (std::size_t k = 0; k < pieces.size(); ++k) parts.push_back({pieces[k], bottom, top, s, static_cast<int>(k)});
  }
  return parts;
}

}  // namespace repose
