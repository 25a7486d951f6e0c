#pragma once
// A rigid-body reference (Bullet, ODE) as a repose Solver: what BulletSolver
// and OdeSolver share. The scene's dem section gives the grains; the
// engine's own section (bullet:, ode:) its options. A run settles the bed
// (cached) and runs the scene (rigid_reference.h).
//
// Fields: height_initial (the settled bed's surface), height_final,
// material_per_area_final. Measures: grain_count, steps, particle_steps_per_cpu_s,
// run_wall_s, run_cpu_s, bed_steps, bed_wall_s, bed_cpu_s (0 when cached),
// bed_kinetic_energy_j, time_step_s, solver_iterations, mass_held_kg.<object>;
// column.* and pile.* for a column scene. Details: engine_version, bed_cache_key.
// Parameters a fit may change (they override the dem section's values, and
// a changed value settles a new bed): friction, restitution, rolling_friction.

#include <memory>
#include <string>

#include "models/core/solver/solver.h"
#include "validation/rigid/rigid_engine.h"

namespace repose {

// The compiled scene for an engine. Throws InputError for a scene without a
// dem section or whose column does not fit.
std::unique_ptr<CompiledSolver> compile_rigid(const Scene& scene, RigidEngine engine);

}  // namespace repose
