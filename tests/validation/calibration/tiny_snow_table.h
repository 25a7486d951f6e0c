#pragma once
// A tiny snow scene for the calibration tests, as inline scene YAML: a
// 40 cm square flat ground of 2 cm cells and a 20 cm square table top 10 cm
// above it, snowed on from 8 directions for duration_s; groups "ground" and
// "table", so an entry can compare either snow map (field:).

#include <string>

#include <fmt/format.h>

namespace repose::testing {

inline std::string tiny_snow_table_yaml(double duration_s) {
  return fmt::format(R"(name: tiny_table
seed: 2
time: {{step_s: 1.0, duration_s: {}}}
ground: {{extent_m: [0.4, 0.4], cell_size_m: 0.02, initial_height: {{kind: flat, height_m: 0.0}}}}
objects:
  - {{name: top, shape: box, half_extents_m: [0.1, 0.1, 0.01], motion: [{{time_s: 0, position_m: [0, 0, 0.1]}}]}}
snow:
  groups: [{{name: ground, ground: true}}, {{name: table, objects: [top]}}]
  spread_deg: 5
  direction_count: 8
  snowfall_rate_m_s: 0.01
)",
                     duration_s);
}

}  // namespace repose::testing
