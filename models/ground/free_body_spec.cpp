#include "models/ground/free_body_spec.h"

#include <cmath>

namespace repose {

void validate(const FreeBodySpec& f) {
  if (!(f.ode_step_s > 0.0 && f.ode_step_s <= 0.1)) {
    throw FieldError("ode_step_s", "a time step in (0, 0.1] s", yaml_number(f.ode_step_s));
  }
  if (f.solver_iterations < 1 || f.solver_iterations > 1000) {
    throw FieldError("solver_iterations", "an integer in [1, 1000]", std::to_string(f.solver_iterations));
  }
  if (!(f.erp > 0.0 && f.erp <= 1.0)) throw FieldError("erp", "a number in (0, 1]", yaml_number(f.erp));
  if (!(f.cfm >= 0.0 && f.cfm <= 1.0)) throw FieldError("cfm", "a number in [0, 1]", yaml_number(f.cfm));
  if (!(f.friction >= 0.0 && f.friction <= 10.0)) {
    throw FieldError("friction", "a coefficient in [0, 10]", yaml_number(f.friction));
  }
  if (!(f.gravity_m_s2 >= 0.0 && f.gravity_m_s2 <= 100.0)) {
    throw FieldError("gravity_m_s2", "an acceleration in [0, 100] m/s^2", yaml_number(f.gravity_m_s2));
  }
  validate(f.bearing);
}

}  // namespace repose
