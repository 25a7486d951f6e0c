#pragma once
// The snow model's fixed description, built once from a scene (as MuJoCo
// compiles mjModel): the snow grid, one snow map per group, every group's
// geometry (what casts the shadows), the options and the time line. The
// changing part is SnowState (snow_state.h), the fitted part SnowParams.

#include <cstdint>
#include <string>
#include <vector>

#include "models/core/config/scene.h"
#include "models/core/geometry/height_field.h"
#include "models/snow/snow_map.h"
#include "models/snow/snow_options.h"

namespace repose {

struct SnowModel {
  SnowOptions options;
  TimeSpec time;
  std::uint64_t seed = 0;  // draws the snowfall directions
  Grid grid;               // shared by every map
  std::vector<SnowMap> maps;             // one per group, in options.groups order
  std::vector<TriangleMesh> occluders;   // every group's geometry, world coordinates
  std::vector<int> occluder_map;         // the map (group) of each occluder
  int ground_map = -1;                   // the ground group's map, -1 when none
};

// What a group is made of: the ground height field, or meshes in world coordinates.
struct SnowGroupGeometry {
  std::string name;
  const HeightField* ground = nullptr;  // the ground group (not owned)
  std::vector<TriangleMesh> meshes;     // an object group
};

// Validates the options; builds the maps on `grid`.
SnowModel build_snow_model(const std::vector<SnowGroupGeometry>& groups, const Grid& grid, const SnowOptions& options,
                           const TimeSpec& time, std::uint64_t seed);

// From a scene: the ground from its initial heights, each group's objects
// posed at t = 0; the grid spans the ground with options.cell_size_m (0: the
// ground's). Throws InputError for a group naming an unknown object.
SnowModel build_snow_model(const Scene& scene, const SnowOptions& options);

}  // namespace repose
