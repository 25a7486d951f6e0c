#pragma once
// The file of experiments/tearing/tearing_paper_fit.cpp: which tensile and
// tear scenes, which seeds, a paper grade's published values (SI units) and
// the fitted parameters (the tearing solver's, in its order:
// stiffness_scale, tear_strain, fibre_anisotropy).
//
//   name: tearing_paper_fit
//   source: "..."                      # where the published values come from
//   tensile_scene: scenes/tearing_tensile.yaml
//   tear_scene: scenes/tearing_across.yaml   # optional: the tear ratio check
//   seeds: [1, 2]                      # tensile seeds, averaged
//   tear_seeds: [1, 2, 3]
//   published:
//     md_stiffness_n_per_m: 6.0e5      # tensile stiffness E t, MD and CD
//     cd_stiffness_n_per_m: 2.8e5
//     md_strength_n_per_m: 5.0e3       # tensile strength, MD and CD
//     cd_strength_n_per_m: 2.5e3
//     tear_cd_over_md: 1.1             # Elmendorf tear resistance CD / MD, or
//     md_tear_mn: 965                  #   the two tear resistances (ISO 1974, mN),
//     cd_tear_mn: 1105                 #   whose ratio it then is
//   parameters:                        # all three, in this order
//     - {name: stiffness_scale, initial: 4.0e5, bounds: [5.0e4, 3.0e6], step: 2.0e4}
//     - ...
//     # optional fourth, a fibre setting (tearing.fibres.background_density)
//     # fitted with the tear ratio CD / MD per path length as a fifth
//     # residual; needs tear_scene:
//     - {name: background_density, initial: 0.4, bounds: [0.05, 0.8], step: 0.03}
//   fit_tear_seeds: [1]                # the fit's tear seeds (default: tear_seeds)
//   starts: 3
//   max_iterations: 20

#include <string>
#include <vector>

namespace repose {

struct PaperFitParameter {
  std::string name;
  double initial = 0.0, lower = 0.0, upper = 0.0, step = 0.0;
};

struct PaperFitSpec {
  std::string source_path, name, source;
  std::string tensile_scene, tear_scene;  // absolute; tear_scene empty when not checked
  std::vector<int> seeds, tear_seeds;
  double md_stiffness_n_per_m = 0.0, cd_stiffness_n_per_m = 0.0;
  double md_strength_n_per_m = 0.0, cd_strength_n_per_m = 0.0;
  double tear_cd_over_md = 0.0;
  double md_tear_mn = 0.0, cd_tear_mn = 0.0;  // 0 when the file gives the ratio only
  std::vector<PaperFitParameter> parameters;  // stiffness_scale, tear_strain, fibre_anisotropy[, background_density]
  std::vector<int> fit_tear_seeds;            // the tear seeds of the fit's ratio residual (4 parameters)
  int starts = 3;
  int max_iterations = 20;
};

// Strict: unknown keys, missing values, bounds that do not hold the initial
// value or a step <= 0 are InputErrors naming FILE:LINE:COL and the key.
PaperFitSpec load_paper_fit_spec(const std::string& path);

}  // namespace repose
