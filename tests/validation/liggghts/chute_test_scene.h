#pragma once
// A tiny chute for the chute tests, as inline scene YAML: 20 cm long and
// 12 mm wide (3 grain diameters), a block of ~330 grains of radius 2 mm
// (4 cm long, 4 cm deep) released down a rough floor at slope_deg onto a
// wall whose upstream face is at x = 0.18 m; the flow is measured 1-5 cm
// upstream of it.

#include <string>

#include <fmt/format.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/config/scene_loader.h"

namespace repose::testing {

inline std::string chute_scene_yaml(double slope_deg, double impact_window_m = 0.04) {
  return fmt::format(R"(name: tiny_chute
seed: 5
time: {{step_s: 0.01, duration_s: 0.5}}
ground:
  extent_m: [0.2, 0.012]
  cell_size_m: 0.004
  origin_m: [0.0, 0.0]
  initial_height: {{kind: flat, height_m: 0.0}}
objects:
  - name: wall
    shape: box
    half_extents_m: [0.005, 0.0059, 0.05]
    motion: [{{time_s: 0, position_m: [0.185, 0.006, 0.0501]}}]
dem:
  grain_radius_m: 0.002
  radius_spread: 0.1
  youngs_modulus_pa: 1.0e7
  time_step_s: 2.0e-5
  settle_kinetic_energy_j: 1.0e-6
  dump_interval_s: 0.01
  initial: column
  column_shape: slot
  column_width_m: 0.04
  column_height_m: 0.04
  floor: rough
  slope_deg: {}
  impact_window_m: {}
  impact_window_gap_m: 0.01
)",
                     slope_deg, impact_window_m);
}

inline Scene chute_scene(double slope_deg, double impact_window_m = 0.04) {
  return load_scene_from_string(chute_scene_yaml(slope_deg, impact_window_m), "tiny_chute.yaml",
                                solver_registry().sections());
}

}  // namespace repose::testing
