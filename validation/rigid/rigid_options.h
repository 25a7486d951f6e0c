#pragma once
// What the rigid-body references (Bullet, ODE) share of their options: the
// fixed internal step, the solver iterations, how the bed is laid out and
// when it counts as settled. Each engine's section (bullet:, ode:) holds
// these keys plus its own (bullet_options.h, ode_options.h).

#include "models/core/config/yaml_reader.h"

namespace repose {

struct RigidOptions {
  double time_step_s = 1.0 / 600.0;   // fixed internal step (the engine never substeps on its own)
  int solver_iterations = 10;         // contact solver iterations per step
  double packing_fraction = 0.6;      // settled packing that sizes the grain count (as the LIGGGHTS bed)
  double lattice_gap_fraction = 0.1;  // grains start on a loose lattice, this gap between neighbours (of the largest diameter)
  double max_settle_time_s = 3.0;     // give up settling after this (the bed fails, nothing is cached)
  double settle_check_interval_s = 0.02;  // kinetic energy checked this often while settling
  // Settled when the grains' kinetic energy is below that of the whole bed
  // moving at this speed (0.5 M v^2). Rigid-body solvers leave the grains
  // jittering in place: measured on 2,258 grains of 2 mm, Bullet reaches the
  // dem section's 1e-7 J after 2 s, ODE stays near 4e-7 J; 5 mm/s (2.4e-6 J
  // there) is reached in about 0.35 s by both. 0: the dem section's
  // settle_kinetic_energy_j instead.
  double settle_rms_speed_m_s = 0.005;
  // Impacts slower than this are perfectly inelastic (both engines have such
  // a threshold; it keeps resting contacts from chattering). LIGGGHTS has none.
  double restitution_velocity_threshold_m_s = 0.2;
};

// The field list (one list for reading, checking, the manifest and the cache key).
template <class V, class O>
void rigid_option_fields(V& v, O& o) {
  v.number("time_step_s", o.time_step_s, Range::left_open(0.0, 0.1));
  v.integer("solver_iterations", o.solver_iterations, IntRange{1, 1000});
  v.number("packing_fraction", o.packing_fraction, Range::open(0.0, 0.75));
  v.number("lattice_gap_fraction", o.lattice_gap_fraction, Range::closed(0.0, 1.0));
  v.number("max_settle_time_s", o.max_settle_time_s, Range::left_open(0.0, 1000.0));
  v.number("settle_check_interval_s", o.settle_check_interval_s, Range::left_open(0.0, 10.0));
  v.number("settle_rms_speed_m_s", o.settle_rms_speed_m_s, Range::non_negative());
  v.number("restitution_velocity_threshold_m_s", o.restitution_velocity_threshold_m_s, Range::non_negative());
}

// Throws FieldError (an InputError) "KEY: expected RULE, got VALUE" naming
// the first field that breaks its rule, or the rule between fields.
void validate(const RigidOptions& options);

}  // namespace repose
