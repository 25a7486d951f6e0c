#include "validation/rigid/rigid_reference.h"

#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "models/core/io/json_writer.h"
#include "models/core/io/npy_io.h"
#include "validation/liggghts/liggghts_bed.h"
#include "validation/particles/particle_observables.h"
#include "validation/rigid/grain_file.h"
#include "validation/rigid/rigid_simulation.h"

namespace repose {

namespace fs = std::filesystem;

namespace {

void write_phase(JsonWriter& json, const char* name, const RigidPhaseSummary& s) {
  json.key(name).begin_object();
  json.key("steps").integer(s.steps);
  json.key("simulated_s").number(s.simulated_s);
  json.key("kinetic_energy_j").number(s.kinetic_energy_j);
  json.key("wall_time_s").number(s.wall_time_s);
  json.key("cpu_time_s").number(s.cpu_time_s);
  json.end_object();
}

void write_column(JsonWriter& json, const RigidReferenceResult& r) {
  constexpr double deg = 180.0 / std::numbers::pi;
  if (r.column) {
    const ColumnCollapse& c = *r.column;
    json.key("column").begin_object();
    json.key("shape").string(c.geometry.shape == DemSpec::ColumnShape::kSlot ? "slot" : "cylinder");
    json.key("width_m").number(c.geometry.width_m);
    json.key("height_initial_m").number(c.height_initial_m);
    json.key("aspect_ratio").number(c.aspect_ratio);
    json.key("front_initial_m").number(c.front_initial_m);
    json.key("front_final_m").number(c.front_final_m);
    json.key("front_final_spread_m").number(c.front_final_spread_m);
    json.key("height_final_m").number(c.height_final_m);
    json.key("runout_normalised").number(c.runout_normalised);
    json.end_object();
  }
  if (r.pile) {
    json.key("pile").begin_object();
    json.key("flank_angle_mean_deg").number(r.pile->mean_rad * deg);
    json.key("flank_angle_std_deg").number(r.pile->std_rad * deg);
    json.key("azimuth_count").integer(static_cast<long>(r.pile->angle_rad.size()));
    json.end_object();
  }
}

void write_manifest(const std::string& path, const RigidReferenceResult& r) {
  std::ofstream out(path);
  JsonWriter json(out);
  json.begin_object();
  json.key("engine").string(r.engine);
  json.key("engine_version").string(r.engine_version);
  json.key("bed_cache_key").string(r.bed.key);
  json.key("bed_from_cache").boolean(r.bed.from_cache);
  json.key("grain_count").integer(r.grain_count);
  json.key("particle_steps_per_cpu_s").number(r.particle_steps_per_cpu_s);
  write_phase(json, "bed", r.bed.settle);
  write_phase(json, "run", r.run);
  json.key("mass_held_kg").begin_object();
  for (const auto& [name, kg] : r.mass_held_kg) json.key(name).number(kg);
  json.end_object();
  write_column(json, r);
  json.end_object();
  out << "\n";
  if (!out) throw std::runtime_error(fmt::format("{}: write failed", path));
}

// Runout over the frames and, for a cylinder, the final pile's flank angles.
void measure_column(RigidReferenceResult& r, const RigidInputs& in, const std::vector<RigidFrame>& frames,
                    const RigidReferenceOptions& options) {
  std::vector<GrainSet> grains;
  std::vector<double> times;
  for (const RigidFrame& f : frames) {
    times.push_back(f.time_s);
    grains.push_back(f.grains);
  }
  r.column = measure_column_collapse(*in.column, r.grains_initial, grains, times, 2.0 * in.dem.grain_radius_m,
                                     options.column);
  if (in.column->shape == DemSpec::ColumnShape::kCylinder) {
    r.pile = pile_flank_angles(r.height_final, in.column->axis_xy_m, options.flank);
  }
}

}  // namespace

RigidReferenceResult run_rigid_reference(const RigidEngine& engine, const RigidInputs& in,
                                         const RigidReferenceOptions& options) {
  validate(engine.rigid, engine.name);
  RigidReferenceResult r;
  r.engine = engine.name;
  r.engine_version = engine.version;
  r.bed = settled_rigid_bed(engine, in, options.cache_dir.empty() ? default_cache_dir() : options.cache_dir);
  r.grains_initial = r.bed.grains;

  const RigidWorldSpec spec = run_world(in, r.bed.grains);
  const auto world = engine.make_world(spec);
  std::vector<RigidFrame> frames;
  r.run = run_motion(*world, in.objects, in.time.duration_s, in.dem.dump_interval_s, &frames);
  r.grains_final = world->grains();
  demand_no_grain_lost(r.grains_final, spec.bounds, engine.name, "the run");

  r.grain_count = static_cast<long>(r.grains_final.size());
  const double particle_steps = static_cast<double>(r.grain_count) * static_cast<double>(r.run.steps);
  r.particle_steps_per_cpu_s = r.run.cpu_time_s > 0.0 ? particle_steps / r.run.cpu_time_s : 0.0;
  r.height_initial = surface_height(r.grains_initial, in.grid, options.surface);
  r.height_final = surface_height(r.grains_final, in.grid, options.surface);
  r.material_per_area_final = material_per_area(r.grains_final, in.grid);
  for (const ObjectSpec& o : in.objects) {
    const TriangleMesh world_mesh = transformed(o.body, o.pose_at(in.time.duration_s));
    r.mass_held_kg.emplace_back(o.name, mass_held_by_object_kg(r.grains_final, world_mesh, in.dem.density_kg_m3));
  }
  if (in.column) measure_column(r, in, frames, options);
  return r;
}

void write_rigid_reference(const RigidReferenceResult& r, const std::string& run_dir) {
  const fs::path dir(run_dir);
  write_npy_2d((dir / "height_initial.npy").string(), r.height_initial.heights());
  write_npy_2d((dir / "height_final.npy").string(), r.height_final.heights());
  write_npy_2d((dir / "material_per_area_final.npy").string(), r.material_per_area_final.heights());
  write_grains_npy((dir / "grains_initial.npy").string(), r.grains_initial);
  write_grains_npy((dir / "grains_final.npy").string(), r.grains_final);
  if (r.column) write_runout_csv((dir / "runout.csv").string(), *r.column);
  if (r.pile) write_flank_angles_csv((dir / "pile_flank_angles.csv").string(), *r.pile);
  write_manifest((dir / fmt::format("{}_manifest.json", r.engine)).string(), r);
}

}  // namespace repose
