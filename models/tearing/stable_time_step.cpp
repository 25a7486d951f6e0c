#include "models/tearing/stable_time_step.h"

#include <cmath>

#include "models/core/base/error.h"
#include "models/tearing/sheet_forces.h"

namespace repose {

double stable_time_step_s(const SheetModel& model, const SheetParams& params) {
  params.validate();
  const SpringConstants k = spring_constants(model, params);
  const Eigen::VectorXd& m = model.mass_kg;
  Eigen::VectorXd bound = Eigen::VectorXd::Zero(model.vertex_count());
  for (int c = 0; c < model.cell_count(); ++c) {
    for (const CellSpring& s : cell_springs(model, c)) {
      const double ks = spring_constant_n_per_m(k, s, model.cell_stiffness[c]);
      const double cross = ks / std::sqrt(m[s.a] * m[s.b]);
      bound[s.a] += ks / m[s.a] + cross;
      bound[s.b] += ks / m[s.b] + cross;
    }
  }
  constexpr double kCoefficient[3] = {1.0, -2.0, 1.0};
  for (const BendingTerm& t : model.bending) {
    const int v[3] = {t.a, t.b, t.c};
    const double kb = k.bending_n_per_m * t.weight;
    for (int p = 0; p < 3; ++p) {
      for (int q = 0; q < 3; ++q) {
        bound[v[p]] += kb * std::abs(kCoefficient[p] * kCoefficient[q]) / std::sqrt(m[v[p]] * m[v[q]]);
      }
    }
  }
  if (k.twist_n_per_m > 0.0) {  // the twist terms (sheet_model.h): |c_p c_q| = 1
    for (int c = 0; c < model.cell_count(); ++c) {
      const std::array<int, 4> v = model.corners(c);
      const double kt = k.twist_n_per_m * model.cell_stiffness[c];
      for (const int p : v) {
        for (const int q : v) bound[p] += kt / std::sqrt(m[p] * m[q]);
      }
    }
  }
  const double omega_max = std::sqrt(bound.maxCoeff());
  REPOSE_DEMAND(std::isfinite(omega_max));
  if (!(omega_max > 0.0)) return INFINITY;
  // the dashpots (beta K): damping ratio z = beta w / 2 on the mode w;
  // symplectic Euler with the damping force at v_n is stable for
  // (w dt)^2 + 4 z (w dt) <= 4 (the Jury conditions on its 2 x 2 step)
  const double z = 0.5 * model.spec.stiffness_damping_s * omega_max;
  return 2.0 / omega_max * (std::sqrt(1.0 + z * z) - z);
}

}  // namespace repose
