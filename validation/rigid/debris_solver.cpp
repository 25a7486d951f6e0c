#include "validation/rigid/debris_solver.h"

#include <algorithm>

#include "models/core/config/scene.h"
#include "models/terrain/terrain_section.h"
#include "models/terrain/terrain_surface.h"
#include "validation/rigid/debris_run.h"
#include "validation/rigid/debris_setup.h"

namespace repose {

namespace {

// The terrain on `grid` (cells off the mesh: the lowest key contour's height).
HeightField ground_on(const TerrainScenery& s, const Grid& grid) {
  double plain_m = s.terrain.summary.max_height_m;
  for (int r : s.terrain.nesting.roots) plain_m = std::min(plain_m, s.terrain.keys[static_cast<std::size_t>(r)].height_m);
  return sample_height_field(TerrainSurface(s.terrain.mesh), grid, plain_m);
}

GrainSet elements_of(const DebrisWorldSpec& spec) {
  GrainSet g;
  g.position_m.resize(static_cast<Eigen::Index>(spec.elements.size()), 3);
  g.radius_m.resize(static_cast<Eigen::Index>(spec.elements.size()));
  for (std::size_t i = 0; i < spec.elements.size(); ++i) {
    g.position_m.row(static_cast<Eigen::Index>(i)) = spec.elements[i].centre_m.transpose();
    g.radius_m(static_cast<Eigen::Index>(i)) = spec.elements[i].radius_m;
  }
  return g;
}

HeightField topped(const HeightField& ground, const GrainSet& elements) {
  HeightField h = surface_height(elements, ground.grid());
  h.heights() = h.heights().max(ground.heights());
  return h;
}

}  // namespace

void set_debris_measures(const DebrisRunResult& r, const DebrisSetup& setup, double dt, Run& run) {
  run.set("element_count", static_cast<double>(setup.spec.elements.size()), "count");
  run.set("part_count", static_cast<double>(setup.spec.parts.size()), "count");
  run.set("joint_count", static_cast<double>(setup.spec.joints.size()), "count");
  run.set("steps", static_cast<double>(r.steps), "count");
  run.set("time_step_s", dt, "s");
  run.set("run_cpu_s", r.cpu_time_s, "s");
  run.set("run_wall_s", r.wall_time_s, "s");
  run.set("cpu_s_per_simulated_s", r.cpu_s_per_simulated_s(), "1");
  run.set("runout_m", r.runout_m, "m");
  run.set("front_final_m", r.frames.back().front_m, "m");
  run.set("peak_front_speed_m_s", r.peak_front_speed_m_s, "m/s");
  run.set("deposit_volume_m3", r.deposit.volume_m3(), "m^3");
  int broken = 0, moved = 0;
  for (const BuildingOutcome& b : r.buildings) {
    const std::string key = "building." + b.name;
    run.set(key + ".parts", b.parts, "count");
    run.set(key + ".parts_moved", b.parts_moved, "count");
    run.set(key + ".max_displacement_m", b.max_displacement_m, "m");
    run.set(key + ".joints", b.joints, "count");
    run.set(key + ".joints_broken", b.joints_broken, "count");
    run.set(key + ".static_joint_force_n", b.static_joint_force_n, "N");
    run.set(key + ".peak_force_n", b.peak_force_n, "N");
    run.set(key + ".impulse_n_s", b.impulse_n_s, "N s");
    broken += b.joints_broken;
    moved += b.parts_moved;
  }
  run.set("joints_broken", broken, "count");
  run.set("parts_moved", moved, "count");
}

DebrisSetup solver_debris_setup(const TerrainScene& terrain, const Grid& grid, const DebrisMaterial& material,
                                double rolling_friction_scale, HeightField* initial) {
  DebrisSetup setup = debris_setup(terrain, material, rolling_friction_scale);
  setup.scenery.terrain.height_field = ground_on(setup.scenery, grid);
  if (initial != nullptr) *initial = topped(setup.scenery.terrain.height_field, elements_of(setup.spec));
  return setup;
}

Run debris_run_record(const DebrisRunResult& r, const DebrisSetup& setup, const HeightField& initial, double dt,
                      const std::string& solver) {
  Run run;
  run.solver = solver;
  run.wall_s = r.wall_time_s;
  run.cpu_s = r.cpu_time_s;
  run.fields["height_initial"] = initial;
  run.fields["height_final"] = topped(setup.scenery.terrain.height_field, r.frames.back().elements);
  run.fields["deposit"] = r.deposit;
  set_debris_measures(r, setup, dt, run);
  return run;
}

namespace {

class CompiledDebris final : public CompiledSolver {
 public:
  CompiledDebris(const Scene& scene, RigidEngine engine)
      : terrain_(terrain_section(scene).scene), grid_(scene.ground.grid), duration_s_(scene.time.duration_s),
        engine_(std::move(engine)) {
    const DebrisMaterial m;
    parameters_ = {
        {"rolling_friction_scale", "1", 1.0, 0.0, 10.0, 1.0, "multiplies every layer's rolling resistance mu_r"},
        {"building_friction", "1", 1.0, 0.0, 2.0, m.building_friction, "friction of building parts on parts and terrain"},
    };
    if (!terrain_.elements) throw InputError("terrain: elements: a debris run needs moving elements (terrain: elements)");
    terrain_.validate();
  }
  const std::vector<ParameterInfo>& parameters() const override { return parameters_; }

  Run run(const std::vector<double>& values_si, const RunOptions& options) const override {
    check_values(parameters_, values_si, engine_.name);
    DebrisMaterial material;
    material.building_friction = values_si[1];
    HeightField initial;
    const DebrisSetup setup = solver_debris_setup(terrain_, grid_, material, values_si[0], &initial);
    const auto world = engine_.make_debris_world(setup.spec);
    const DebrisRunResult r = run_debris(*world, setup, duration_s_);
    Run run = debris_run_record(r, setup, initial, world->time_step_s(), engine_.name);
    run.stages = {"terrain", engine_.name + "-debris"};
    run.details["engine_version"] = engine_.version;
    if (!options.output_dir.empty()) run.files = write_debris_run(r, setup, options.output_dir);
    return run;
  }

 private:
  TerrainScene terrain_;
  Grid grid_;
  double duration_s_;
  RigidEngine engine_;
  std::vector<ParameterInfo> parameters_;
};

}  // namespace

std::unique_ptr<CompiledSolver> compile_debris(const Scene& scene, RigidEngine engine) {
  return std::make_unique<CompiledDebris>(scene, std::move(engine));
}

}  // namespace repose
