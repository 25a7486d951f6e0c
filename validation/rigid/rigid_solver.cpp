#include "validation/rigid/rigid_solver.h"

#include <filesystem>
#include <numbers>

#include "models/terrain/terrain_section.h"
#include "validation/rigid/debris_solver.h"
#include "validation/rigid/grain_file.h"
#include "validation/rigid/rigid_reference.h"
#include "validation/rigid/rigid_setup.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

std::vector<ParameterInfo> contact_parameters(const DemSpec& dem) {
  return {
      {"friction", "1", 1.0, 0.0, 2.0, dem.friction, "sliding friction coefficient, every pair"},
      {"restitution", "1", 1.0, 0.01, 1.0, dem.restitution, "coefficient of restitution, every pair"},
      {"rolling_friction", "1", 1.0, 0.0, 1.0, dem.rolling_friction,
       "rolling resistance mu_r: torque mu_r r_eff N (the floor keeps its own on a rough floor)"},
  };
}

// Every number of a JSON object as a measure (dotted names).
void set_json_measures(const nlohmann::json& json, const std::string& prefix, Run& run) {
  for (const auto& [key, value] : json.items()) {
    const std::string name = prefix.empty() ? key : prefix + "." + key;
    if (value.is_object()) set_json_measures(value, name, run);
    if (value.is_number()) run.set(name, value.get<double>(), "");
  }
}

void set_measures(const RigidReferenceResult& r, const RigidEngine& engine, Run& run) {
  run.set("grain_count", static_cast<double>(r.grain_count), "count");
  run.set("steps", static_cast<double>(r.run.steps), "count");
  run.set("particle_steps_per_cpu_s", r.particle_steps_per_cpu_s, "1/s");
  run.set("run_wall_s", r.run.wall_time_s, "s");
  run.set("run_cpu_s", r.run.cpu_time_s, "s");
  run.set("bed_steps", static_cast<double>(r.bed.settle.steps), "count");
  run.set("bed_wall_s", r.bed.settle.wall_time_s, "s");
  run.set("bed_cpu_s", r.bed.settle.cpu_time_s, "s");
  run.set("bed_kinetic_energy_j", r.bed.settle.kinetic_energy_j, "J");
  run.set("time_step_s", engine.rigid.time_step_s, "s");
  run.set("solver_iterations", engine.rigid.solver_iterations, "count");
  for (const auto& [name, kg] : r.mass_held_kg) run.set("mass_held_kg." + name, kg, "kg");
  for (std::size_t k = 0; k < r.free_bodies.size(); ++k) {
    const std::string key = "free_bodies." + r.free_bodies[k].name;
    const FreeBodyRest& rest = r.free_body_rests[k];
    run.set(key + ".resting_depth_m", rest.resting_depth_m, "m");
    run.set(key + ".final_z_m", rest.position_m.z(), "m");
    run.set(key + ".final_speed_m_s", rest.final_speed_m_s, "m/s");
    run.set(key + ".resting_force_z_n", rest.resting_force_n.z(), "N");
    run.set(key + ".weight_n", rest.weight_n, "N");
    run.set(key + ".max_force_n", rest.max_force_n, "N");
  }
  if (r.column) {
    run.set("column.height_initial_m", r.column->height_initial_m, "m");
    run.set("column.aspect_ratio", r.column->aspect_ratio, "1");
    run.set("column.front_initial_m", r.column->front_initial_m, "m");
    run.set("column.front_final_m", r.column->front_final_m, "m");
    run.set("column.height_final_m", r.column->height_final_m, "m");
    run.set("column.runout_normalised", r.column->runout_normalised, "1");
  }
  if (r.pile) {
    run.set("pile.flank_angle_mean_deg", r.pile->mean_rad * 180.0 / std::numbers::pi, "deg");
    run.set("pile.flank_angle_std_deg", r.pile->std_rad * 180.0 / std::numbers::pi, "deg");
  }
  set_json_measures(chute_results_json(r.chute), "", run);
  run.details["engine_version"] = r.engine_version;
  run.details["bed_cache_key"] = r.bed.key;
}

class CompiledRigid final : public CompiledSolver {
 public:
  CompiledRigid(RigidInputs in, RigidEngine engine)
      : in_(std::move(in)), engine_(std::move(engine)), parameters_(contact_parameters(in_.dem)) {}
  const std::vector<ParameterInfo>& parameters() const override { return parameters_; }

  Run run(const std::vector<double>& values_si, const RunOptions& options) const override {
    check_values(parameters_, values_si, engine_.name);
    RigidInputs in = in_;
    in.dem.friction = values_si[0];
    in.dem.restitution = values_si[1];
    in.dem.rolling_friction = values_si[2];
    const RigidReferenceResult r = run_rigid_reference(engine_, in);
    Run run;
    run.solver = engine_.name;
    run.wall_s = r.run.wall_time_s;
    run.cpu_s = r.run.cpu_time_s;
    run.fields["height_initial"] = r.height_initial;
    run.fields["height_final"] = r.height_final;
    run.fields["material_per_area_final"] = r.material_per_area_final;
    run.stages = {r.bed.from_cache ? "bed:cached" : "bed:settled", engine_.name + "-run"};
    set_measures(r, engine_, run);
    if (!options.output_dir.empty()) {
      write_rigid_reference(r, options.output_dir);
      run.files = {"height_initial.npy", "height_final.npy", "material_per_area_final.npy", "grains_initial.npy",
                   "grains_final.npy", engine_.name + "_manifest.json"};
      for (const FreeBodyTrack& t : r.free_bodies) run.files.push_back("free_body_" + t.name + ".csv");
      if (r.column) run.files.push_back("runout.csv");
      if (r.pile) run.files.push_back("pile_flank_angles.csv");
      if (!r.object_forces.time_s.empty()) run.files.push_back("forces.csv");
      if (r.chute) run.files.push_back("chute_impact.csv");
    }
    return run;
  }

 private:
  RigidInputs in_;
  RigidEngine engine_;
  std::vector<ParameterInfo> parameters_;
};

}  // namespace

std::unique_ptr<CompiledSolver> compile_rigid(const Scene& scene, RigidEngine engine) {
  if (dem_of(scene) == nullptr && scene.section<TerrainSection>() != nullptr) return compile_debris(scene, std::move(engine));
  RigidInputs in = rigid_inputs(scene, engine.name);
  return std::make_unique<CompiledRigid>(std::move(in), std::move(engine));
}

}  // namespace repose
