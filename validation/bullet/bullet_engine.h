#pragma once
// Bullet as a rigid-body reference engine (validation/rigid/rigid_engine.h):
// run_rigid_reference(bullet_engine(options), rigid_inputs(scene)) runs a scene.

#include "validation/bullet/bullet_options.h"
#include "validation/rigid/rigid_engine.h"

namespace repose {

// Throws InputError when the options break their rules.
RigidEngine bullet_engine(const BulletOptions& options);

}  // namespace repose
