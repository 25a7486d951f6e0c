#include "models/ground/bekker_bearing.h"

#include <cmath>

namespace repose {

void validate(const BekkerBearing& b) {
  if (!(b.exponent_n > 0.0 && b.exponent_n <= 5.0)) {
    throw FieldError("exponent_n", "a number in (0, 5]", yaml_number(b.exponent_n));
  }
  if (!(b.k_c_n_per_m_n_plus_1 >= 0.0 && std::isfinite(b.k_c_n_per_m_n_plus_1))) {
    throw FieldError("k_c_n_per_m_n_plus_1", "a finite modulus >= 0 N/m^(n+1)", yaml_number(b.k_c_n_per_m_n_plus_1));
  }
  if (!(b.k_phi_n_per_m_n_plus_2 >= 0.0 && std::isfinite(b.k_phi_n_per_m_n_plus_2))) {
    throw FieldError("k_phi_n_per_m_n_plus_2", "a finite modulus >= 0 N/m^(n+2)",
                     yaml_number(b.k_phi_n_per_m_n_plus_2));
  }
  // with both zero the ground bears nothing: every loaded body would sink without end
  if (b.law == BekkerBearing::Law::kBekker && b.k_c_n_per_m_n_plus_1 == 0.0 && b.k_phi_n_per_m_n_plus_2 == 0.0) {
    throw FieldError("k_phi_n_per_m_n_plus_2", "k_c or k_phi > 0 (the ground must bear some load; law: off for none)",
                     "both 0");
  }
}

double bekker_pressure_pa(const BekkerBearing& b, double sinkage_m, double width_m) {
  REPOSE_DEMAND(width_m > 0.0 && sinkage_m >= 0.0);
  if (b.law == BekkerBearing::Law::kOff) return 0.0;
  return (b.k_c_n_per_m_n_plus_1 / width_m + b.k_phi_n_per_m_n_plus_2) * std::pow(sinkage_m, b.exponent_n);
}

double bekker_sinkage_m(const BekkerBearing& b, double pressure_pa, double width_m) {
  REPOSE_DEMAND(width_m > 0.0 && pressure_pa >= 0.0);
  if (b.law == BekkerBearing::Law::kOff) return 0.0;
  const double modulus = b.k_c_n_per_m_n_plus_1 / width_m + b.k_phi_n_per_m_n_plus_2;
  return std::pow(pressure_pa / modulus, 1.0 / b.exponent_n);
}

}  // namespace repose
