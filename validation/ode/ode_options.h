#pragma once
// The ode: section of a scene: ODE's fixed step and QuickStep solver, its
// global ERP and CFM, and the sizes made relative to the dem section's
// grain radius (DEPENDENCIES.md, "Pitfalls met running Bullet and ODE with
// mm-sized grains").
//
//   ode: {time_step_s: 0.0016667, solver_iterations: 20, erp: 0.2, cfm: 1.0e-3, ...}

#include <string>

#include "models/core/config/fields.h"
#include "models/core/config/yaml_reader.h"
#include "validation/rigid/rigid_options.h"

namespace repose {

struct OdeOptions {
  OdeOptions() { rigid.solver_iterations = 20; }
  RigidOptions rigid;                  // step, iterations (QuickStep), bed layout, settling (rigid_options.h)
  double erp = 0.2;                    // global error reduction per step
  double cfm = 1.0e-3;                 // global constraint force mixing (softness; measured stable on 2k-10k beds)
  double surface_layer_fraction = 0.01;  // penetration allowed before correction (dWorldSetContactSurfaceLayer)
  int max_contacts_per_pair = 4;       // contact points kept per colliding pair (spheres give one; meshes more)
};

template <class V, class O>
void ode_option_fields(V& v, O& o) {
  rigid_option_fields(v, o.rigid);
  v.number("erp", o.erp, Range::closed(0.0, 1.0));
  v.number("cfm", o.cfm, Range::left_open(0.0, 1.0));  // 0 trips an ODE assertion
  v.number("surface_layer_fraction", o.surface_layer_fraction, Range::closed(0.0, 0.5));
  v.integer("max_contacts_per_pair", o.max_contacts_per_pair, IntRange{1, 64});
}

// Throws FieldError (an InputError) "KEY: expected RULE, got VALUE".
void validate(const OdeOptions& options);

// Every option as key=value lines, numbers round-trip exact (cache keys).
std::string ode_options_text(const OdeOptions& options);

}  // namespace repose
