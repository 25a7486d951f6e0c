#pragma once
// A RigidWorld (validation/rigid/rigid_world.h) in Bullet 3.24, double
// precision (pkg-config bullet-float64: BT_USE_DOUBLE_PRECISION): grains are
// btSphereShape bodies, the ground box static btBoxShapes, objects kinematic
// bodies (Bullet primitives, or btBvhTriangleMeshShape for meshes) moved
// through their motion states, so Bullet derives their velocity from the move.
// Free bodies (spec.bodies) are dynamic bodies of their mass: Bullet's
// primitives, a mesh as its convex hull (btConvexHullShape; Bullet moves a
// concave mesh only through GImpact), inertia Bullet's (a hull's is its
// bounding box's).
// Sequential impulse solver, btDbvtBroadphase, deactivation off (mm grains
// never sleep: one island), every step of the fixed size.
//
// Bullet's pair rules are replaced (gCalculateCombined*Callback) by the pair
// values rigid_world.h states: its default friction and restitution are the
// product of the two bodies' values, its rolling friction r0*mu1 + r1*mu0.
// Bullet's rolling friction limits the rolling impulse to (coefficient x
// normal impulse), so the coefficient given is the lever mu_r * r_eff (m).
// gContactBreakingThreshold and gDbvtMargin are process globals: each world
// sets them to its own values before it builds and before each step, so
// worlds of different grain sizes may alternate but not run on two threads.

#include <memory>

#include "validation/bullet/bullet_options.h"
#include "validation/rigid/rigid_world.h"

namespace repose {

// "Bullet 3.24 (double)": the version Bullet reports, and the precision.
std::string bullet_version();

// Throws InputError when the options break their rules.
std::unique_ptr<RigidWorld> make_bullet_world(const RigidWorldSpec& spec, const BulletOptions& options);

}  // namespace repose
