#include "validation/bullet/bullet_globals.h"

#include <btBulletDynamicsCommon.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

btScalar no_spinning(const btCollisionObject*, const btCollisionObject*) { return 0.0; }

}  // namespace

void set_bullet_globals(const BulletOptions& options, double radius_m, const BulletPairRules& rules) {
  REPOSE_DEMAND(rules.friction != nullptr && rules.restitution != nullptr && rules.rolling != nullptr);
  gContactBreakingThreshold = options.contact_breaking_fraction * radius_m;
  gDbvtMargin = options.broadphase_margin_fraction * radius_m;
  gCalculateCombinedFrictionCallback = rules.friction;
  gCalculateCombinedRestitutionCallback = rules.restitution;
  gCalculateCombinedRollingFrictionCallback = rules.rolling;
  gCalculateCombinedSpinningFrictionCallback = no_spinning;
}

}  // namespace repose
