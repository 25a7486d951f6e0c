#include "models/terrain/terrain_scene.h"

#include <algorithm>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/terrain/terrain_surface.h"

namespace repose {

namespace {

bool overlap(const Polygon2& a, const Polygon2& b) {
  return boundaries_cross(a, b) || contains_point(a, b.front()) || contains_point(b, a.front());
}

}  // namespace

void TerrainScene::validate() const {
  options.validate();
  if (elements) elements->validate();
  for (const BuildingFootprint& b : buildings) b.validate();
  for (std::size_t i = 0; i < buildings.size(); ++i) {
    for (std::size_t j = i + 1; j < buildings.size(); ++j) {
      if (overlap(buildings[i].polygon_m, buildings[j].polygon_m)) {
        throw InputError(fmt::format("terrain: buildings '{}' and '{}' overlap", buildings[i].name, buildings[j].name));
      }
    }
  }
  if (!elements) return;
  // a sphere reaches its radius (and the gap) past the region's outline
  double reach_m = 0.0;
  for (const ElementLayer& l : elements->layers) reach_m = std::max(reach_m, l.radius_m * (1.0 + elements->gap_fraction));
  for (const BuildingFootprint& b : buildings) {
    if (overlap(b.polygon_m, elements->region_m) || boundary_distance_m(b.polygon_m, elements->region_m) <= reach_m) {
      throw InputError(fmt::format(
          "terrain: building '{}' lies within {} m (the largest element radius) of the elements' region: move one",
          b.name, reach_m));
    }
  }
}

TerrainScenery generate_scenery(const TerrainScene& scene) {
  scene.validate();
  TerrainScenery out;
  out.terrain = build_terrain(scene.key_contours, scene.options);
  const TerrainSurface surface(out.terrain.mesh);
  if (scene.elements) out.elements = place_element_layers(surface, *scene.elements);
  for (std::size_t b = 0; b < scene.buildings.size(); ++b) {
    for (BuildingPart& part : building_parts(scene.buildings[b], surface)) {
      part.building = static_cast<int>(b);
      out.building_parts.push_back(std::move(part));
    }
  }
  return out;
}

}  // namespace repose
