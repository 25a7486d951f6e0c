#include "models/tearing/tear_limit.h"

#include <cmath>

#include "models/tearing/cohesive_law.h"

namespace repose {

double energy_rule_tear_strain(double stiffness_n_per_m, double tear_energy_j_per_m, double cell_size_m) {
  return std::sqrt(2.0 * tear_energy_j_per_m / (stiffness_n_per_m * cell_size_m));
}

double base_tear_strain(const SheetModel& model, const SheetParams& params) {
  if (model.spec.tear_rule == TearRule::kStrain) return params.tear_strain;
  if (model.spec.tear_rule == TearRule::kCohesive) return cohesive_law(model, params).zero_strain;
  return energy_rule_tear_strain(params.stiffness_n_per_m, params.tear_energy_j_per_m, model.cell_size_m);
}

double equivalent_tear_energy_j_per_m(double stiffness_n_per_m, double tear_strain, double cell_size_m) {
  return 0.5 * stiffness_n_per_m * tear_strain * tear_strain * cell_size_m;
}

}  // namespace repose
