#pragma once
// Bullet 3.24 keeps its contact thresholds and its pair-combination rules in
// process-wide globals (gContactBreakingThreshold, gDbvtMargin,
// gCalculateCombined*Callback). Every world here (bullet_world.h,
// bullet_debris_world.h) sets them before each step through this one
// function, so worlds of different sizes or rules may live in one process.

#include <BulletCollision/CollisionDispatch/btManifoldResult.h>

#include "validation/bullet/bullet_options.h"

namespace repose {

// A world's pair rules: the friction, restitution and rolling-friction
// lever a contact between two bodies gets (spinning friction is always 0).
struct BulletPairRules {
  CalculateCombinedCallback friction = nullptr;
  CalculateCombinedCallback restitution = nullptr;
  CalculateCombinedCallback rolling = nullptr;
};

// The contact breaking threshold and broadphase margin as the options'
// fractions of radius_m (the world's largest grain or element), and the rules.
void set_bullet_globals(const BulletOptions& options, double radius_m, const BulletPairRules& rules);

}  // namespace repose
