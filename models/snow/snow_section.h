#pragma once
// The snow model's section of a scene (`snow:`): the options of the snow
// paper's method and the scene's values of the fitted parameters.
//
//   snow:
//     groups:                       # one snow map each, in this order (the paper's Fig. 1)
//       - {name: ground, ground: true}
//       - {name: table, objects: [top, leg_a, leg_b]}   # scene objects, posed at t = 0
//     direction_tilt_deg: 0         # main snowfall direction: tilt from straight down, [0, 85]
//     direction_azimuth_deg: 0      #   drifting towards this azimuth (from +x towards +y)
//     spread_deg: 10                # fitted: std dev of each angular deviation, [0, 180]
//     repose_angle_deg: 45          # fitted: the snow angle of repose, [0, 90]
//     snowfall_scale: 1             # fitted: settled depth per depth of snowfall, (0, 100]
//     direction_count: 64           # shadow maps per probability, [1, 65536]
//     cell_size_m: 0                # snow-map cell; 0: the ground's
//     shadow_oversampling: 1        # shadow-map pixels per map cell, [1, 16]
//     shadow_bias_cells: 1          # shadow_map.h, [0, 16]
//     snowfall_rate_m_s: 0.001      # constant M(t), metres of snow per second on open ground
//     snowfall: [{time_s: 0, rate_m_s: 0}, {time_s: 10, rate_m_s: 0.002}]   # or keyframed
//     moved_fraction: 0.2           # stabilisation, (0, 0.25]
//     max_stabilisation_passes: 50  # per time step
//     settle_tolerance_m: 1e-6
//     edge_hold_m: 0                # fitted: snow an edge cell keeps against falling off its map, [0, 1]
//     renderer: cpu                 # cpu | osmesa
//     probability: shadow_maps      # shadow_maps | ray_cast (the Table 1 baseline)
//     picture_times_s: [10, 60]     # pictures/snow_t<time>s.png at these times (snow_picture_options.h)
//     frame_count: 0                # animation frames/frame_NNNN.png from t = 0 to the end
//     picture_width_px: 640         # [16, 4096]
//     picture_height_px: 480
//     view_elevation_deg: 35        # orthographic camera above the horizontal, [5, 90]
//     view_azimuth_deg: -60
//
// Only scenes with this section run under `--solver snow`.

#include <memory>
#include <string>

#include "models/core/config/scene.h"
#include "models/core/config/scene_section.h"
#include "models/core/config/fields.h"
#include "models/core/config/yaml_reader.h"
#include "models/snow/snow_options.h"
#include "models/snow/snow_params.h"

namespace repose {

// The section's fixed options and the scene's parameter values.
struct SnowSpec {
  SnowOptions options;
  SnowParams params;
};

template <class Visitor>
void snow_fields(Visitor& v, SnowSpec& s) {
  v.angle_deg("direction_tilt_deg", s.options.main_direction.tilt_rad, Range::any());
  v.angle_deg("direction_azimuth_deg", s.options.main_direction.azimuth_rad, Range::any());
  v.angle_deg("spread_deg", s.params.direction_spread_rad, Range::any());
  v.angle_deg("repose_angle_deg", s.params.repose_angle_rad, Range::any());
  v.number("snowfall_scale", s.params.snowfall_scale, Range::any());
  v.integer("direction_count", s.options.direction_count, IntRange{});
  v.number("cell_size_m", s.options.cell_size_m, Range::any());
  v.integer("shadow_oversampling", s.options.shadow_oversampling, IntRange{});
  v.number("shadow_bias_cells", s.options.shadow_bias_cells, Range::any());
  v.number("moved_fraction", s.options.moved_fraction, Range::any());
  v.integer("max_stabilisation_passes", s.options.max_stabilisation_passes, IntRange{});
  v.number("settle_tolerance_m", s.options.settle_tolerance_m, Range::any());
  v.number("edge_hold_m", s.params.edge_hold_m, Range::any());
  v.choice("renderer", s.options.renderer,
           ChoiceTable<SnowRenderer>{{"cpu", SnowRenderer::kCpu}, {"osmesa", SnowRenderer::kOsmesa}});
  using P = SnowOptions::Probability;
  v.choice("probability", s.options.probability, ChoiceTable<P>{{"shadow_maps", P::kShadowMaps}, {"ray_cast", P::kRayCast}});
  v.integer("frame_count", s.options.pictures.frame_count, IntRange{});
  v.integer("picture_width_px", s.options.pictures.width_px, IntRange{});
  v.integer("picture_height_px", s.options.pictures.height_px, IntRange{});
  v.angle_deg("view_elevation_deg", s.options.pictures.view_elevation_rad, Range::any());
  v.angle_deg("view_azimuth_deg", s.options.pictures.view_azimuth_rad, Range::any());
}

class SnowSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "snow";

  SnowSpec spec;

  void write_yaml(YAML::Emitter& out) const override;
  std::string summary() const override;
};

// Reads `snow:`; checks that every object a group names is in the scene.
std::shared_ptr<const SceneSection> read_snow_section(const YamlValue& value, const Scene& common);
SectionType snow_section_type();

// A copy of the scene with this snow section (scenes made in code, tests).
Scene with_snow(Scene scene, const SnowSpec& spec);

}  // namespace repose
