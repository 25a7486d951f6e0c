#pragma once
// The bullet: section of a scene: Bullet's fixed step and solver, and the
// sizes Bullet's defaults get wrong for mm grains (they are made for bodies
// of about a metre; see DEPENDENCIES.md, "Pitfalls met running Bullet and
// ODE with mm-sized grains"). Sizes are fractions of the dem section's
// grain radius, so one section fits every grain size.
//
//   bullet: {time_step_s: 0.0016667, solver_iterations: 20, erp: 0.2, friction_directions: 2, ...}

#include <string>

#include "models/core/config/fields.h"
#include "models/core/config/yaml_reader.h"
#include "validation/rigid/rigid_options.h"

namespace repose {

struct BulletOptions {
  // 20 iterations, not the shared 10: the sequential-impulse friction of a
  // pile under-converges at 10 (dem_pile's flank: 15.4 deg at 10, 18.7 at 20,
  // 21.2 at 40 with two friction directions; LIGGGHTS 18.5, ODE 19.7).
  BulletOptions() { rigid.solver_iterations = 20; }
  RigidOptions rigid;                       // step, iterations, bed layout and settling (rigid_options.h)
  double erp = 0.2;                         // contact error reduction per step (Bullet's m_erp2; m_erp is for joints)
  double linear_slop_fraction = 0.01;       // allowed penetration (m_linearSlop): cut residual kinetic energy ~10x
  double contact_breaking_fraction = 0.05;  // gContactBreakingThreshold (default 0.02 m: every pair of mm grains overlaps);
                                            // contacts are seen this far apart, and a contact seen apart loses its bounce
                                            // (0.2 r gave no rebound at all at 1/2400 s; 0.05 r bounces true)
  double broadphase_margin_fraction = 0.25; // gDbvtMargin, the dbvt broadphase's AABB padding (default 0.05 m)
  double shape_margin_fraction = 0.05;      // collision margin of boxes, cylinders, meshes (default 0.04 m)
  // Penetrations deeper than this are pushed out by split impulse (position
  // only, no velocity gained); shallower ones by erp. Bullet's default, 0.04 m,
  // never triggers at mm scale. Splitting every penetration (0) bounces
  // truer but leaves ~30x more residual kinetic energy in a settled bed, so
  // the default keeps Bullet's behaviour (20 radii: 0.04 m for 2 mm grains).
  double split_impulse_fraction = 20.0;
  // Sliding friction rows per contact: Bullet's default is 1, along the
  // current slip (or an arbitrary tangent at rest), so a resting contact
  // holds in one tangential direction only and grains slide off sideways;
  // 2 adds the perpendicular one (SOLVER_USE_2_FRICTION_DIRECTIONS), as a
  // Coulomb contact has. dem_pile's flank angle (1,496 grains, seed 21;
  // repose run experiments/scenes/dem_pile.yaml --solver bullet --set
  // bullet.friction_directions=1 ...): 10.7 deg with 1 direction and 10
  // iterations, 13.0 with 1 and 40, 15.4 with 2 and 10, 18.7 with 2 and 20
  // (seed 22: 8.8 with 1 and 10, 17.6 with 2 and 20); rolling friction only
  // shows with 2 (mu_r 0 / 0.1 / 0.3: 14.7 / 18.7 / 21.8 deg), where with 1
  // and 10 iterations mu_r 0 gave 12.4. ODE 19.7 and 20.6, LIGGGHTS 18.5.
  // Cost: 8.7e4 grain-steps per CPU second against 1.05e5.
  int friction_directions = 2;
};

template <class V, class O>
void bullet_option_fields(V& v, O& o) {
  rigid_option_fields(v, o.rigid);
  v.number("erp", o.erp, Range::closed(0.0, 1.0));
  v.number("linear_slop_fraction", o.linear_slop_fraction, Range::closed(0.0, 0.5));
  v.number("contact_breaking_fraction", o.contact_breaking_fraction, Range::left_open(0.0, 2.0));
  v.number("broadphase_margin_fraction", o.broadphase_margin_fraction, Range::closed(0.0, 2.0));
  v.number("shape_margin_fraction", o.shape_margin_fraction, Range::left_open(0.0, 0.5));
  v.number("split_impulse_fraction", o.split_impulse_fraction, Range::closed(0.0, 100.0));
  v.integer("friction_directions", o.friction_directions, IntRange{1, 2});
}

// Throws FieldError (an InputError) "KEY: expected RULE, got VALUE".
void validate(const BulletOptions& options);

// Every option as key=value lines, numbers round-trip exact (cache keys).
std::string bullet_options_text(const BulletOptions& options);

}  // namespace repose
