#include "models/tearing/cohesive_law.h"

#include <algorithm>
#include <cmath>

#include "models/tearing/tear_limit.h"

namespace repose {

double CohesiveLaw::damage_factor(double max_strain) const {
  if (max_strain <= peak_strain) return 1.0;
  if (max_strain >= zero_strain) return 0.0;
  return (peak_strain / max_strain) * (zero_strain - max_strain) / (zero_strain - peak_strain);
}

double CohesiveLaw::secant_factor(double strain, double max_strain) const {
  return strain <= 0.0 ? 1.0 : damage_factor(max_strain);
}

double CohesiveLaw::force_n(double k_n_per_m, double rest_length_m, double strain, double max_strain) const {
  const double reached = std::max(strain, max_strain);
  return secant_factor(strain, reached) * k_n_per_m * rest_length_m * strain;
}

double CohesiveLaw::dissipated_j(double k_n_per_m, double rest_length_m, double max_strain) const {
  if (max_strain <= peak_strain || zero_strain <= peak_strain) return 0.0;
  const double m = std::min(max_strain, zero_strain);
  return area_j(k_n_per_m, rest_length_m) * (m - peak_strain) / (zero_strain - peak_strain);
}

double CohesiveLaw::area_j(double k_n_per_m, double rest_length_m) const {
  return 0.5 * k_n_per_m * rest_length_m * rest_length_m * peak_strain * zero_strain;
}

double CohesiveLaw::soften(double k_n_per_m, double rest_length_m, double strain, double* max_strain) const {
  if (strain <= peak_strain || strain <= *max_strain || zero_strain <= peak_strain) return 0.0;
  const double before = dissipated_j(k_n_per_m, rest_length_m, *max_strain);
  *max_strain = std::min(strain, zero_strain);
  return dissipated_j(k_n_per_m, rest_length_m, *max_strain) - before;
}

CohesiveLaw cohesive_law(const SheetModel& model, const SheetParams& params) {
  const double et = params.stiffness_n_per_m, gamma = params.tear_energy_j_per_m, h = model.cell_size_m;
  const double energy_rule = energy_rule_tear_strain(et, gamma, h);
  if (params.tear_strain >= energy_rule) return {energy_rule, energy_rule};  // the band too coarse: the snap
  const double peak = params.tear_strain;
  return {peak, std::max(peak, 2.0 * gamma / (et * peak * h))};
}

}  // namespace repose
