#pragma once
// A DebrisWorld (validation/rigid/debris_world.h) in Bullet 3.24, double
// precision: the terrain a static btBvhTriangleMeshShape, elements
// btSphereShape bodies, building parts btConvexHullShape bodies (inertia
// that of their hull's box), joints btFixedConstraint (to
// btTypedConstraint::getFixedBody() for the ground) added with collisions between
// the joined parts disabled; each step reads a joint's linear force from its
// btJointFeedback and disables it when above break_force_n (the rule ODE's
// world uses; Bullet's own setBreakingImpulseThreshold compares every
// constraint row, angular rows too, with one number).
// The options are the bullet: section's (bullet_options.h); sizes given as
// fractions of the grain radius are fractions of the largest element's
// radius here, except the parts' collision margin, which is also kept below
// a third of the smallest gap between parts so parts never start in contact.

#include <memory>

#include "validation/bullet/bullet_options.h"
#include "validation/rigid/debris_world.h"

namespace repose {

// Throws InputError when the options break their rules.
std::unique_ptr<DebrisWorld> make_bullet_debris_world(const DebrisWorldSpec& spec, const BulletOptions& options);

}  // namespace repose
