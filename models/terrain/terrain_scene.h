#pragma once
// Everything a terrain scene describes (the scene's `terrain:` section):
// key contours, how to generate the ground from them, the moving elements'
// source region and layers, and the buildings. Fixed once validated; the
// generation is a pure function of it.

#include <optional>
#include <vector>

#include "models/terrain/building.h"
#include "models/terrain/element_layers.h"
#include "models/terrain/terrain.h"

namespace repose {

struct TerrainScene {
  std::vector<KeyContour> key_contours;
  TerrainOptions options;
  std::optional<ElementSource> elements;  // none: no moving elements
  std::vector<BuildingFootprint> buildings;

  // Throws InputError naming the field (options, elements, buildings; the
  // key contours are checked when the terrain is built).
  void validate() const;
};

struct TerrainScenery {
  Terrain terrain;
  ElementLayout elements;
  std::vector<BuildingPart> building_parts;
};

// The terrain, then the elements and buildings placed on it.
TerrainScenery generate_scenery(const TerrainScene& scene);

}  // namespace repose
