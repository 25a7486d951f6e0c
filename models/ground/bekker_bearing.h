#pragma once
// The ground's bearing rule for free bodies: Bekker's pressure-sinkage law
//
//   p = (k_c / b + k_phi) z^n
//
// (M. G. Bekker, Theory of Land Locomotion, 1956; J. Y. Wong, Theory of
// Ground Vehicles, 4th ed., 2008, eq. 2.52): a plate of smaller width b
// pressed with mean pressure p sinks z below the undisturbed surface. The
// ground heuristic alone has no bearing capacity (it removes only what a
// body's pose intersects, so a body resting on it sinks no deeper with
// more load); this law gives the depth a body's load presses it to
// (free_body_drive.h). Static and monotonic only: no unloading, no slip
// sinkage, no repetitive loading.
//
// In the scene (ground_model section; SI units, so the table's kN become N):
//
//   ground_model:
//     bearing: {law: bekker, exponent_n: 1.1, k_c_n_per_m_n_plus_1: 990, k_phi_n_per_m_n_plus_2: 1528430}
//     bearing: {law: off}     # free bodies rest on the field; no bearing sinkage
//
// Defaults: dry sand, Wong (2008), Table 2.3 (values from the Land
// Locomotion Laboratory): n = 1.1, k_c = 0.99 kN/m^(n+1), k_phi =
// 1528.43 kN/m^(n+2) (the set Chrono's SCM terrain demos use for loose sand).

#include "models/core/config/fields.h"

namespace repose {

struct BekkerBearing {
  enum class Law { kOff, kBekker };
  Law law = Law::kBekker;                    // off: bodies rest on the field, no bearing sinkage
  double exponent_n = 1.1;                   // sinkage exponent n, (0, 5]
  double k_c_n_per_m_n_plus_1 = 990.0;       // cohesive modulus k_c, N/m^(n+1), >= 0
  double k_phi_n_per_m_n_plus_2 = 1528430.0; // frictional modulus k_phi, N/m^(n+2), >= 0 (k_c and k_phi not both 0)
};

// Throws FieldError naming the field and the rule.
void validate(const BekkerBearing& bearing);

template <class V>
void bekker_bearing_fields(V& v, BekkerBearing& b) {
  using L = BekkerBearing::Law;
  v.choice("law", b.law, ChoiceTable<L>{{"bekker", L::kBekker}, {"off", L::kOff}});
  v.number("exponent_n", b.exponent_n, Range::left_open(0.0, 5.0));
  v.number("k_c_n_per_m_n_plus_1", b.k_c_n_per_m_n_plus_1, Range::non_negative());
  v.number("k_phi_n_per_m_n_plus_2", b.k_phi_n_per_m_n_plus_2, Range::non_negative());
}

inline const auto kBekkerBearingFields = [](auto& v, BekkerBearing& x) { bekker_bearing_fields(v, x); };

// The pressure (Pa) that holds a plate of smaller width width_m (> 0) at sinkage_m (>= 0).
double bekker_pressure_pa(const BekkerBearing& bearing, double sinkage_m, double width_m);

// The sinkage (m) of a plate of smaller width width_m (> 0) under pressure_pa (>= 0):
// z = (p / (k_c / b + k_phi))^(1/n). 0 when the law is off.
double bekker_sinkage_m(const BekkerBearing& bearing, double pressure_pa, double width_m);

}  // namespace repose
