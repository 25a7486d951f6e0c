#pragma once
// A terrain scene (the scene's terrain: section with elements, and
// optionally buildings) run as a debris flow in a rigid-body engine
// (Bullet, ODE): what `--solver bullet` and `--solver ode` do with a scene
// that has a terrain: section and no dem: section. The engine's section
// (bullet:, ode:) gives the step and solver; the scene's time.duration_s
// the length of the run.
//
// Fields: height_initial and height_final (the terrain sampled on the
// scene's grid, topped by the elements' surface), deposit (the elements'
// surface above the terrain at the end). Measures: element_count,
// part_count, joint_count, steps, time_step_s, run_cpu_s, run_wall_s,
// cpu_s_per_simulated_s, runout_m, front_final_m, peak_front_speed_m_s,
// deposit_volume_m3, joints_broken, parts_moved, and per building
// building.<name>.{parts, parts_moved, max_displacement_m, joints,
// joints_broken, static_joint_force_n, peak_force_n, impulse_n_s}. Files: debris_run.h's.
// Parameters: rolling_friction_scale (times every layer's mu_r), building_friction.

#include <memory>

#include <string>

#include "models/core/solver/solver.h"
#include "models/terrain/terrain_scene.h"
#include "validation/rigid/debris_run.h"
#include "validation/rigid/rigid_engine.h"

namespace repose {

// Throws InputError (one line naming the key) for a scene without a terrain
// section or elements, or whose terrain cannot be built.
std::unique_ptr<CompiledSolver> compile_debris(const Scene& scene, RigidEngine engine);

// What every debris solver (these and LIGGGHTS') shares:
// the setup with the terrain's heights sampled on the scene's grid, and (when
// `initial` is given) that terrain topped by the elements at the start;
DebrisSetup solver_debris_setup(const TerrainScene& terrain, const Grid& grid, const DebrisMaterial& material,
                                double rolling_friction_scale, HeightField* initial);
// a finished run as a repose Run: fields and measures above (dt: the engine's step);
Run debris_run_record(const DebrisRunResult& r, const DebrisSetup& setup, const HeightField& initial, double dt,
                      const std::string& solver);
// the measures alone.
void set_debris_measures(const DebrisRunResult& r, const DebrisSetup& setup, double dt, Run& run);

}  // namespace repose
