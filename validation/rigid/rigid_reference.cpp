#include "validation/rigid/rigid_reference.h"

#include <filesystem>
#include <fstream>
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
  json.end_object();
  out << "\n";
  if (!out) throw std::runtime_error(fmt::format("{}: write failed", path));
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
  r.run = run_motion(*world, in.objects, in.time.duration_s);
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
  return r;
}

void write_rigid_reference(const RigidReferenceResult& r, const std::string& run_dir) {
  const fs::path dir(run_dir);
  write_npy_2d((dir / "height_initial.npy").string(), r.height_initial.heights());
  write_npy_2d((dir / "height_final.npy").string(), r.height_final.heights());
  write_npy_2d((dir / "material_per_area_final.npy").string(), r.material_per_area_final.heights());
  write_grains_npy((dir / "grains_initial.npy").string(), r.grains_initial);
  write_grains_npy((dir / "grains_final.npy").string(), r.grains_final);
  write_manifest((dir / fmt::format("{}_manifest.json", r.engine)).string(), r);
}

}  // namespace repose
