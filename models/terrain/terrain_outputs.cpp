#include "models/terrain/terrain_outputs.h"

#include <filesystem>

#include "models/core/io/height_field_io.h"
#include "models/core/io/mesh_io.h"
#include "models/core/io/npy_io.h"

namespace repose {

namespace {

ArrayXXdR contour_rows(const ContourSet& set) {
  Eigen::Index n = 0;
  for (const TerrainContour& c : set.contours) n += static_cast<Eigen::Index>(c.polygon_m.size());
  ArrayXXdR rows(n, 5);
  Eigen::Index r = 0;
  for (std::size_t k = 0; k < set.contours.size(); ++k) {
    const TerrainContour& c = set.contours[k];
    for (const Point2& p : c.polygon_m) {
      rows.row(r++) << static_cast<double>(k), p.x(), p.y(), c.height_m, c.is_key ? 1.0 : 0.0;
    }
  }
  return rows;
}

}  // namespace

std::vector<std::string> write_terrain_outputs(const std::string& directory, const Terrain& terrain,
                                               const std::vector<PlacedElement>& elements,
                                               const std::vector<BuildingPart>& parts) {
  const std::filesystem::path dir(directory);
  std::vector<std::string> written;
  auto path = [&](const char* name) {
    written.emplace_back(name);
    return (dir / name).string();
  };
  write_obj(path("terrain_mesh.obj"), terrain.mesh);
  write_ply(path("terrain_mesh.ply"), terrain.mesh);
  write_height_field_npy(path("terrain_height.npy"), terrain.height_field);
  write_npy_2d(path("contours.npy"), contour_rows(terrain.contours));
  if (!terrain.contours.summits.empty()) {
    ArrayXXdR rows(static_cast<Eigen::Index>(terrain.contours.summits.size()), 3);
    for (std::size_t i = 0; i < terrain.contours.summits.size(); ++i) {
      const SummitPoint& s = terrain.contours.summits[i];
      rows.row(static_cast<Eigen::Index>(i)) << s.point_m.x(), s.point_m.y(), s.height_m;
    }
    write_npy_2d(path("summits.npy"), rows);
  }
  if (!elements.empty()) {
    ArrayXXdR rows(static_cast<Eigen::Index>(elements.size()), 5);
    for (std::size_t i = 0; i < elements.size(); ++i) {
      const PlacedElement& e = elements[i];
      rows.row(static_cast<Eigen::Index>(i)) << e.centre_m.x(), e.centre_m.y(), e.centre_m.z(), e.radius_m,
          static_cast<double>(e.layer);
    }
    write_npy_2d(path("elements.npy"), rows);
  }
  if (!parts.empty()) {
    TriangleMesh all;
    for (const BuildingPart& p : parts) all = merged(all, prism_mesh(p.footprint_m, p.bottom_m, p.top_m));
    write_obj(path("buildings.obj"), all);
  }
  return written;
}

}  // namespace repose
