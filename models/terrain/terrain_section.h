#pragma once
// The scene file's `terrain:` section (terrain_solver.h reads it), read into
// a TerrainScene. SI units; the slope in degrees at the file edge only.
//
//   terrain:
//     key_contours:                    # or key_contours_file: hills.geojson (key_contour_file.h)
//       - {name: foot, height_m: 0, points_m: [[0, 0], [100, 0], [100, 80], [0, 80]]}
//     contour_interval_m: 1            # TerrainOptions' defaults and rules
//     slope_deg: 30
//     smoothing_tolerance_m: 0.5
//     sample_spacing_m: 1
//     cell_size_m: 1
//     elements:                        # optional (element_layers.h)
//       region_m: [[10, 10], [30, 10], [30, 30], [10, 30]]
//       gap_fraction: 0.01
//       radius_spread: 0.2             # optional, a random bed drawn from the scene's seed
//       position_jitter: 1             # optional (both 0 by default: a regular lattice)
//       layers: [{name: bed, radius_m: 1, rows: 2, friction: 0.6, restitution: 0.1, density_kg_m3: 2500,
//                 rolling_friction: 0.1}]   # the last two: rigid engines only
//     buildings:                       # optional (building.h)
//       - {name: house, footprint_m: [[...]], storeys: 2, storey_height_m: 3, gap_m: 0.02,
//          bulk_density_kg_m3: 300, joint_break_force_n: 1.0e7}   # the last two: rigid engines only
//
// A relative key_contours_file is taken from the scene file's folder. The
// section writes itself back with the key contours inline.

#include <memory>

#include "models/core/config/scene_section.h"
#include "models/core/config/yaml_reader.h"
#include "models/terrain/terrain_scene.h"

namespace repose {

struct Scene;

// The options' one field list: reading, writing and the allowed keys.
template <class Visitor>
void terrain_option_fields(Visitor& v, TerrainOptions& o) {
  v.number("contour_interval_m", o.contour_interval_m, Range::any());
  v.angle_deg("slope_deg", o.slope_rad, Range::any());
  v.number("smoothing_tolerance_m", o.smoothing_tolerance_m, Range::any());
  v.number("sample_spacing_m", o.sample_spacing_m, Range::any());
  v.number("cell_size_m", o.cell_size_m, Range::any());
}

class TerrainSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "terrain";

  TerrainScene scene;

  void write_yaml(YAML::Emitter& out) const override;
  std::string summary() const override;
};

// Throws InputError (FILE:LINE:COL: KEY.PATH: ...) for a malformed section,
// and validates the result (TerrainScene::validate).
TerrainScene read_terrain_section(const YamlValue& section);

// The scene's terrain section; InputError naming the scene file when it has none.
const TerrainSection& terrain_section(const Scene& scene);
SectionType terrain_section_type();

}  // namespace repose
