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
// Masses are given to Bullet in units of ten times the heaviest element's
// mass (forces read back are converted to N): Bullet 3.24's solver caps a
// contact's rolling-friction torque impulse at min(lever x normal impulse,
// lever), the second term in N m s whatever the masses, so with tonne
// elements (normal impulses of 10-100 N s per step) rolling resistance was
// cut 10-100 fold and the flow ran 89 m where ODE and LIGGGHTS ran ~50 m.
// In these units a normal impulse stays below 1 unless an element's
// velocity changes by 10 m/s in one step; the motion is unchanged otherwise
// (every force scales with mass; gravity is an acceleration).
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
