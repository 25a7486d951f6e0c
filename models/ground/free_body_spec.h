#pragma once
// How the ground model drives free bodies (objects with `dynamic:`) with ODE
// over its height field (free_body_drive.h): ODE's step and solver, the
// contact with the field, gravity, and the bearing rule that makes a body
// sink with its load (bekker_bearing.h).
//
//   ground_model:
//     free_bodies: {ode_step_s: 0.0016667, solver_iterations: 20, erp: 0.2, cfm: 1.0e-6, friction: 0.5,
//                   gravity_m_s2: 9.81}
//     bearing: {law: bekker}

#include "models/core/config/fields.h"
#include "models/ground/bekker_bearing.h"

namespace repose {

struct FreeBodySpec {
  // ODE's time step; a ground step holds round(step_s / ode_step_s) (at least one) ODE steps. (0, 0.1] s.
  double ode_step_s = 1.0 / 600.0;
  int solver_iterations = 20;  // QuickStep iterations, [1, 1000]
  double erp = 0.2;            // error reduction per ODE step, (0, 1]
  // constraint force mixing (m/N per step): 1e-6 keeps a body's penetration
  // of the field below a micrometre per kg, so its sinkage is the bearing rule's. [0, 1]
  double cfm = 1.0e-6;
  double friction = 0.5;       // Coulomb coefficient of body-field and body-body contacts, [0, 10]
  double gravity_m_s2 = 9.81;  // downward, [0, 100]
  BekkerBearing bearing;       // read from ground_model.bearing
};

// Throws FieldError naming the field (the bearing's fields by their own keys).
void validate(const FreeBodySpec& spec);

template <class V>
void free_body_fields(V& v, FreeBodySpec& f) {
  v.number("ode_step_s", f.ode_step_s, Range::left_open(0.0, 0.1));
  v.integer("solver_iterations", f.solver_iterations, IntRange{1, 1000});
  v.number("erp", f.erp, Range::left_open(0.0, 1.0));
  v.number("cfm", f.cfm, Range::closed(0.0, 1.0));
  v.number("friction", f.friction, Range::closed(0.0, 10.0));
  v.number("gravity_m_s2", f.gravity_m_s2, Range::closed(0.0, 100.0));
}

inline const auto kFreeBodyFields = [](auto& v, FreeBodySpec& x) { free_body_fields(v, x); };

}  // namespace repose
