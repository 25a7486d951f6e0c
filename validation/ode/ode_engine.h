#pragma once
// ODE as a rigid-body reference engine (validation/rigid/rigid_engine.h):
// run_rigid_reference(ode_engine(options), rigid_inputs(scene)) runs a scene.

#include "validation/ode/ode_options.h"
#include "validation/rigid/rigid_engine.h"

namespace repose {

// Throws InputError when the options break their rules.
RigidEngine ode_engine(const OdeOptions& options);

}  // namespace repose
