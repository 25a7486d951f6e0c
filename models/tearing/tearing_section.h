#pragma once
// The paper-tearing solver's section of a scene (`tearing:`): the sheet
// (sheet_spec.h), its fibres (fibre_options.h), how it is held and pulled,
// the scene's values of the fitted parameters, and the integrator.
//
//   tearing:
//     width_m: 0.1                  # sheet size
//     height_m: 0.1
//     grammage_kg_per_m2: 0.08      # 80 g/m^2
//     cells_x: 50                   # square cells across the width
//     bending_stiffness_n_m: 3.0e-4
//     twist_stiffness: false        # true: a twist term per cell, the plate isotropic (sheet_model.h)
//     stiffness_density_exponent: 3 # springs ~ fibre density^exponent
//     tear_strain_density_exponent: 1
//     damping_per_s: 2000
//     stiffness_damping_s: 0        # Rayleigh beta: dashpots beta k in the springs (sheet_spec.h)
//     gravity_m_per_s2: [0, -9.81, 0]
//     notch_length_m: 0.004         # a cut down from the top edge at notch_x_m
//     notch_x_m: 0.05
//     stiffness_n_per_m: 4.0e5      # E t; parameter stiffness_scale
//     tear_strain: 0.02             # parameter tear_strain (tear_rule: strain)
//     tear_rule: strain             # strain (the seed's, default) | energy (tear_limit.h) | cohesive (cohesive_law.h)
//     tear_energy_j_per_m: 0.16     # parameter tear_energy (tear_rule: energy)
//     fibre_anisotropy: 0           # parameter fibre_anisotropy: springs along the grain (1 + a) stiffer
//     isotropic_tear_energy: false  # true: springs' tear strains scaled so each tears at one energy (sheet_spec.h)
//     integrator: explicit          # explicit | implicit
//     time_step_fraction: 0.9       # of the explicit stable step (implicit: may exceed 1)
//     stop_at_depth_m: 0.06         # stop once the tear is this deep (0: run time.duration_s)
//     fibres: {layers: 3, grain_direction_deg: 0, grain_spread_deg: 20, ...}
//     twist: {grip_depth_m: 0.01, gap_m: 0.01, speed_m_per_s: 4}   # the seed's pull, or:
//     grips: [{x_min_m: 0, x_max_m: 0.045, y_min_m: 0.09, y_max_m: 0.1,
//              velocity_m_per_s: [0, 0, -4], hold_x: true, hold_y: true, hold_z: true}, ...]
//     # or a tensile test of the uncut strip along x (tensile_test.h; the run
//     # is the test, not a tear):
//     tensile: {speed_m_per_s: 0.5, max_strain: 0.2, stiffness_strain_fraction: 0.5}
//
// The common scene still needs its ground and time: time.duration_s is the
// pull's length; the ground grid is not used (a tearing scene gives a small
// flat one).

#include <optional>

#include "models/core/config/scene.h"
#include "models/core/config/scene_section.h"
#include "models/core/config/yaml_reader.h"
#include "models/tearing/sheet_params.h"
#include "models/tearing/sheet_spec.h"
#include "models/tearing/tear_run.h"
#include "models/tearing/tensile_test.h"

namespace repose {

class TearingSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "tearing";

  SheetSpec sheet;
  SheetParams params;  // the scene's values of the fitted parameters
  // integrator, time_step_fraction, stop_at_depth_m; duration_s is the
  // scene's time.duration_s
  TearRunOptions run;
  // Set when the scene is a tensile test (its grips are then tensile_grips());
  // its time_step_fraction is run.time_step_fraction.
  std::optional<TensileOptions> tensile;

  void write_yaml(YAML::Emitter& out) const override;
  std::string summary() const override;
};

std::shared_ptr<const SceneSection> read_tearing_section(const YamlValue& value, const Scene& common);
SectionType tearing_section_type();

}  // namespace repose
