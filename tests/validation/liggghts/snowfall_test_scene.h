#pragma once
// A small snowfall scene (dem.initial: snowfall) for the snowfall tests: a
// 6.4 x 4.8 cm grid of 4 mm cells, a plate 4 x 2.4 cm (10 x 6 grain
// diameters) 2 cm up, 2 mm of snow on open ground (~280 grains of radius
// 2 mm) falling straight down with a 10 deg spread over 0.1 s.

#include <string>

#include "models/core/config/scene_loader.h"
#include "models/snow/snow_section.h"
#include "validation/liggghts/liggghts_section.h"
#include "validation/liggghts/snowfall_section.h"
#include "validation/particles/dem_section.h"

namespace repose::testing {

inline const char* kSnowfallSceneText = R"(name: tiny_snowfall
seed: 3
time: {step_s: 0.05, duration_s: 1.0}
ground:
  extent_m: [0.064, 0.048]
  cell_size_m: 0.004
  origin_m: [0.0, 0.0]
  initial_height: {kind: flat, height_m: 0.0}
objects:
  - {name: plate, shape: box, half_extents_m: [0.02, 0.012, 0.002], motion: [{time_s: 0, position_m: [0.032, 0.024, 0.02]}]}
snow:
  groups: [{name: ground, ground: true}, {name: plate, objects: [plate]}]
  direction_tilt_deg: 0
  spread_deg: 10
  direction_count: 16
  snowfall_rate_m_s: 0.004
dem:
  grain_radius_m: 0.002
  radius_spread: 0.1
  time_step_s: 2.0e-5
  cohesion_energy_density_j_m3: 50000
  initial: snowfall
  floor: rough
  surface_probe_radius_m: 0.002
dem_snowfall: {stream_count: 4, fall_speed_m_s: 0.5, insert_time_s: 0.1, max_settle_time_s: 0.5}
)";

inline SectionTypes snowfall_test_sections() {
  return {dem_section_type(), liggghts_section_type(), snowfall_section_type(), snow_section_type()};
}

inline Scene snowfall_test_scene(const std::string& text = kSnowfallSceneText) {
  return load_scene_from_string(text, "/tmp/tiny_snowfall.yaml", snowfall_test_sections());
}

}  // namespace repose::testing
