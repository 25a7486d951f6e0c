#include "validation/liggghts/liggghts_reference.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/run/repository_path.h"
#include "models/core/io/mesh_io.h"
#include "models/core/io/npy_io.h"
#include "models/core/base/sha256.h"
#include "validation/liggghts/liggghts_dump.h"
#include "validation/liggghts/liggghts_free_body.h"
#include "validation/liggghts/liggghts_thermo.h"
#include "validation/particles/particle_observables.h"

namespace repose {

namespace fs = std::filesystem;

namespace {

constexpr const char* kRunScriptFile = "run.in";
constexpr double kRestingWindowFraction = 0.2;  // a free body's resting force: the mean over this last part of the run

void write_forces_csv(const fs::path& path, const ThermoTable& thermo, const RunScript& script, double step_s) {
  std::ofstream out(path);
  out << "time_s";
  std::vector<int> cols;
  for (const LiggghtsMeshFile& m : script.meshes) {
    for (int a = 1; a <= 3; ++a) {
      out << fmt::format(",{}_f{}_n", m.fix_id, "xyz"[a - 1]);
      const int c = thermo.column(fmt::format("{}[{}]", m.fix_id, a));
      REPOSE_DEMAND(c >= 0);
      cols.push_back(c);
    }
  }
  out << "\n";
  for (const auto& row : thermo.rows) {
    out << fmt::format("{}", row[0] * step_s);
    for (int c : cols) out << fmt::format(",{}", row[c]);
    out << "\n";
  }
  if (!out) throw InputError(fmt::format("{}: write failed", path.string()));
}

double mean_grain_diameter_m(const DemSpec& dem) { return 2.0 * dem.grain_radius_m; }

// Runout over the dumps and, for a cylinder, the final pile's flank angles.
void measure_column(LiggghtsReferenceResult& r, const Scene& scene, const std::vector<std::string>& dumps,
                    const LiggghtsReferenceOptions& options, const fs::path& dir) {
  std::vector<GrainSet> frames;
  std::vector<double> times;
  for (const std::string& path : dumps) {
    DumpFrame f = read_last_dump_frame(path);
    times.push_back(static_cast<double>(f.timestep) * dem_of(scene)->time_step_s);
    frames.push_back(std::move(f.grains));
  }
  const ColumnGeometry geometry = column_geometry(scene);
  r.column = measure_column_collapse(geometry, read_last_dump_frame(r.bed.dump_path).grains, frames, times,
                                     mean_grain_diameter_m(*dem_of(scene)), options.column);
  write_runout_csv((dir / "runout.csv").string(), *r.column);
  if (is_axisymmetric(geometry.shape)) {
    r.pile = pile_flank_angles(r.height_final, geometry.axis_xy_m, options.flank);
    write_flank_angles_csv((dir / "pile_flank_angles.csv").string(), *r.pile);
  }
}

// The impact on the wall (the first object, mesh 0) of a chute's flow, from
// the dumps' grains and velocities and the thermo lines' force on it.
void measure_chute(LiggghtsReferenceResult& r, const Scene& scene, const std::vector<std::string>& dumps,
                   const ThermoTable& thermo, const RunScript& script, const fs::path& dir) {
  const double step_s = dem_of(scene)->time_step_s;
  std::vector<GrainSet> frames;
  std::vector<double> times;
  for (const std::string& path : dumps) {
    DumpFrame f = read_last_dump_frame(path);
    times.push_back(static_cast<double>(f.timestep) * step_s);
    frames.push_back(std::move(f.grains));
  }
  const int column = thermo.column(fmt::format("{}[1]", script.meshes.front().fix_id));
  REPOSE_DEMAND(column >= 0);
  std::vector<double> force_time, force_x;
  for (const auto& row : thermo.rows) {
    force_time.push_back(row[0] * step_s);
    force_x.push_back(row[static_cast<std::size_t>(column)]);
  }
  r.chute = measure_chute_impact(chute_geometry(scene), frames, times, force_time, force_x);
  write_chute_impact_csv((dir / "chute_impact.csv").string(), *r.chute);
}

// The free spheres' tracks (printed by LIGGGHTS), their rest, their CSV files.
void measure_free_bodies(LiggghtsReferenceResult& r, const Scene& scene, const fs::path& dir) {
  const DemSpec& dem = *dem_of(scene);
  r.free_bodies = read_liggghts_free_bodies(scene, dem, dir.string());
  std::size_t b = 0;
  for (const ObjectSpec& o : scene.objects) {
    if (!o.dynamic) continue;
    const FreeBodyTrack& t = r.free_bodies[b++];
    r.free_body_rests.push_back(
        free_body_rest(o, t, r.height_initial, dem.gravity_m_s2, kRestingWindowFraction * scene.time.duration_s));
    write_free_body_csv((dir / ("free_body_" + t.name + ".csv")).string(), t);
  }
}

// The mass each keyframed object holds at every dump (none without such an object).
void measure_held_mass(LiggghtsReferenceResult& r, const Scene& scene, const std::vector<std::string>& dumps,
                       const fs::path& dir) {
  if (std::none_of(scene.objects.begin(), scene.objects.end(), [](const ObjectSpec& o) { return !o.dynamic; })) return;
  const DemSpec& dem = *dem_of(scene);
  std::vector<GrainFrame> frames;
  for (const std::string& path : dumps) {
    DumpFrame f = read_last_dump_frame(path);
    frames.push_back({static_cast<double>(f.timestep) * dem.time_step_s, std::move(f.grains)});
  }
  r.held_mass = held_mass_series(scene.objects, frames, dem.density_kg_m3);
  write_held_mass_csv((dir / "held_mass.csv").string(), r.held_mass);
}

void write_manifest(const fs::path& path, const LiggghtsReferenceResult& r, const Scene& scene) {
  const DemSpec& dem = *dem_of(scene);
  nlohmann::json json = liggghts_results_json(r);
  json["solver"] = "liggghts";
  json["scene"] = scene.name;
  json["scene_path"] = repository_relative(scene.source_path);
  json["seed"] = scene.seed;
  json["time_step_s"] = dem.time_step_s;
  json["simulated_time_s"] = static_cast<double>(r.steps) * dem.time_step_s;
  json["wall_time_s"] = r.run.wall_time_s;
  json["cpu_time_s"] = r.run.cpu_time_s;
  json["youngs_modulus_pa"] = dem.youngs_modulus_pa;
  json["youngs_modulus_note"] = "softened, as DEM practice does, to allow a practical time step";
  json["rayleigh_time_s"] = rayleigh_time_s(dem);
  json["bed"] = {{"cache_key", r.bed.key},           {"directory", repository_relative(r.bed.directory)},
                 {"from_cache", r.bed.from_cache},   {"grain_count", r.bed.grain_count},
                 {"steps", r.bed.steps},             {"wall_time_s", r.bed.wall_time_s},
                 {"cpu_time_s", r.bed.cpu_time_s}};
  std::ofstream out(path);
  out << json.dump(2) << "\n";
  if (!out) throw InputError(fmt::format("{}: write failed", path.string()));
}

}  // namespace

nlohmann::json liggghts_results_json(const LiggghtsReferenceResult& r) {
  nlohmann::json json;
  json["liggghts_version"] = r.run.version;
  json["script_sha256"] = r.script_sha256;
  json["bed_cache_key"] = r.bed.key;
  json["bed_from_cache"] = r.bed.from_cache;
  json["grain_count"] = r.grain_count;
  json["steps"] = r.steps;
  json["particle_steps_per_s"] = r.particle_steps_per_s;
  json["neighbor"] = {{"builds", r.neighbor.builds}, {"dangerous_builds", r.neighbor.dangerous_builds}};
  json["run_wall_s"] = r.run.wall_time_s;
  json["run_cpu_s"] = r.run.cpu_time_s;
  json["bed_wall_s"] = r.bed.wall_time_s;
  json["bed_cpu_s"] = r.bed.cpu_time_s;
  json["particle_steps_per_cpu_s"] =
      r.run.cpu_time_s > 0 ? static_cast<double>(r.grain_count) * static_cast<double>(r.steps) / r.run.cpu_time_s : 0.0;
  json.update(column_results_json(r.column, r.pile));
  json.update(chute_results_json(r.chute));
  for (const auto& [name, kg] : r.mass_held_kg) json["mass_held_kg"][name] = kg;
  if (!r.free_bodies.empty()) json["free_bodies"] = free_bodies_json(r.free_bodies, r.free_body_rests);
  return json;
}

LiggghtsReferenceResult run_liggghts_reference(const Scene& scene, const std::string& run_dir,
                                               const LiggghtsReferenceOptions& options) {
  const RunScript script = run_script(scene, options.script);  // checks the scene before any run
  const fs::path dir(run_dir);
  if (!fs::is_directory(dir)) throw InputError(fmt::format("{}: the run directory does not exist", run_dir));

  LiggghtsReferenceResult r;
  r.bed = settled_bed(scene, options.bed);

  fs::copy_file(r.bed.restart_path, dir / kBedRestartFile, fs::copy_options::overwrite_existing);
  // the bed's own manifest (its cost, also when it came from the cache)
  fs::copy_file(fs::path(r.bed.directory) / "manifest.json", dir / "bed_manifest.json",
                fs::copy_options::overwrite_existing);
  for (const LiggghtsMeshFile& m : script.meshes) write_stl((dir / m.file_name).string(), m.mesh);
  fs::create_directories(dir / kDumpDirectory);
  std::ofstream(dir / kRunScriptFile) << script.text;
  r.script_sha256 = sha256_hex(script.text);

  LiggghtsRunOptions run = options.run;
  run.total_steps = script.total_steps;
  run.dump_directory = kDumpDirectory;
  r.run = run_liggghts(run_dir, kRunScriptFile, run);
  r.steps = script.total_steps;
  r.neighbor = read_neighbor_stats((dir / "log.liggghts").string());

  const Grid& grid = scene.ground.grid;
  const auto dumps = list_dump_files((dir / kDumpDirectory).string());
  if (dumps.empty()) {
    throw LiggghtsRunError(run_dir, (dir / "log.liggghts").string(), "the run wrote no dump");
  }
  const DumpFrame last = read_last_dump_frame(dumps.back());
  r.grain_count = static_cast<long>(last.grains.size());
  if (r.grain_count != r.bed.grain_count) {
    throw LiggghtsRunError(run_dir, (dir / "log.liggghts").string(),
                           fmt::format("{} grains at the end, {} in the bed", r.grain_count, r.bed.grain_count));
  }
  r.particle_steps_per_s =
      r.run.wall_time_s > 0 ? static_cast<double>(r.grain_count) * static_cast<double>(r.steps) / r.run.wall_time_s : 0.0;

  SurfaceHeightOptions surface = options.surface;
  surface.probe_radius_m = dem_of(scene)->surface_probe_radius_m;
  r.height_initial = surface_height(read_last_dump_frame(r.bed.dump_path).grains, grid, surface);
  r.height_final = surface_height(last.grains, grid, surface);
  write_npy_2d((dir / "height_initial.npy").string(), r.height_initial.heights());
  write_npy_2d((dir / "height_final.npy").string(), r.height_final.heights());
  write_field_csv((dir / "height_initial.csv").string(), r.height_initial, "height_m");
  write_field_csv((dir / "height_final.csv").string(), r.height_final, "height_m");
  r.material_per_area_final = material_per_area(last.grains, grid);
  write_npy_2d((dir / "material_per_area_final.npy").string(), r.material_per_area_final.heights());
  write_field_csv((dir / "material_per_area_final.csv").string(), r.material_per_area_final, "grain_volume_per_area_m");
  const ThermoTable thermo = read_thermo_table((dir / "log.liggghts").string());
  write_forces_csv(dir / "forces.csv", thermo, script, dem_of(scene)->time_step_s);
  if (dem_of(scene)->initial == DemSpec::Initial::kColumn) measure_column(r, scene, dumps, options, dir);
  if (measures_impact(*dem_of(scene))) measure_chute(r, scene, dumps, thermo, script, dir);
  measure_free_bodies(r, scene, dir);
  measure_held_mass(r, scene, dumps, dir);
  for (std::size_t k = 0, b = 0; k < scene.objects.size(); ++k) {
    const ObjectSpec& o = scene.objects[k];
    const Pose end = o.dynamic ? r.free_bodies[b++].samples.back().state.pose : o.pose_at(scene.time.duration_s);
    const TriangleMesh world = transformed(o.body, end);
    r.mass_held_kg.emplace_back(o.name.empty() ? fmt::format("object_{}", k) : o.name,
                                mass_held_by_object_kg(last.grains, world, dem_of(scene)->density_kg_m3));
  }
  write_manifest(dir / "liggghts_manifest.json", r, scene);
  return r;
}

}  // namespace repose
