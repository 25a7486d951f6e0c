#include "validation/liggghts/snowfall_reference.h"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "models/core/base/error.h"
#include "models/core/base/sha256.h"
#include "models/core/io/mesh_io.h"
#include "models/core/run/repository_path.h"
#include "models/snow/snow_model.h"
#include "models/snow/snow_section.h"
#include "validation/liggghts/grain_snow_depth.h"
#include "validation/liggghts/liggghts_dump.h"
#include "validation/liggghts/snowfall_script.h"
#include "validation/particles/particle_observables.h"

namespace repose {

namespace fs = std::filesystem;

namespace {

constexpr const char* kScriptFile = "snowfall.in";

void write_manifest(const fs::path& path, const Scene& scene, const Run& run, const std::string& version,
                    const std::string& sha) {
  nlohmann::json json;
  json["solver"] = "liggghts";
  json["mode"] = "snowfall";
  json["scene"] = scene.name;
  json["scene_path"] = repository_relative(scene.source_path);
  json["seed"] = scene.seed;
  json["liggghts_version"] = version;
  json["script_sha256"] = sha;
  json["grain_count"] = run.measure("grain_count").value;
  json["steps"] = run.measure("steps").value;
  json["time_step_s"] = dem_of(scene)->time_step_s;
  json["wall_time_s"] = run.wall_s;
  json["cpu_time_s"] = run.cpu_s;
  json["particle_steps_per_cpu_s"] = run.measure("particle_steps_per_cpu_s").value;
  std::ofstream out(path);
  out << json.dump(2) << "\n";
  if (!out) throw InputError(fmt::format("{}: write failed", path.string()));
}

void add_snow_fields(Run& run, const Scene& scene, const SnowModel& model, const GrainSet& grains) {
  const DemSpec& dem = *dem_of(scene);
  SurfaceHeightOptions surface;
  surface.probe_radius_m = dem.surface_probe_radius_m;
  const std::vector<ArrayXXdR> depth = grain_snow_depth(grains, model.maps, surface);
  const std::vector<int> map_of = snow_map_of_grains(grains, model.maps);
  const Grid& g = model.grid;
  run.fields["height_initial"] = HeightField(g, ArrayXXdR::Zero(g.ny, g.nx));
  for (std::size_t m = 0; m < model.maps.size(); ++m) {
    const std::string& name = model.maps[m].name;
    run.fields["snow_depth_final." + name] = HeightField(g, depth[m]);
    double volume = 0.0;
    for (Eigen::Index k = 0; k < grains.size(); ++k) {
      const double r = grains.radius_m(k);
      if (map_of[static_cast<std::size_t>(k)] == static_cast<int>(m)) volume += 4.0 / 3.0 * 3.141592653589793 * r * r * r;
    }
    run.set("snow.volume_m3." + name, volume, "m^3");
    run.set("snow.max_depth_m." + name, depth[m].maxCoeff(), "m");
    if (model.options.groups[m].ground) run.fields["height_final"] = HeightField(g, model.maps[m].base.z_m + depth[m]);
  }
  run.fields["material_per_area_final"] = material_per_area(grains, g);
}

}  // namespace

Run run_liggghts_snowfall(const Scene& scene, const std::string& run_dir, const LiggghtsRunOptions& options) {
  const SnowfallScript script = snowfall_script(scene);  // checks the scene before any run
  const SnowModel model = build_snow_model(scene, scene.section<SnowSection>()->spec.options);
  if (model.grid.nx != scene.ground.grid.nx || model.grid.ny != scene.ground.grid.ny) {
    throw InputError(fmt::format("{}: snow: cell_size_m: the snowfall reference needs the snow maps on the ground's "
                                 "grid (cell_size_m: 0)", scene.source_path));
  }
  const fs::path dir(run_dir);
  if (!fs::is_directory(dir)) throw InputError(fmt::format("{}: the run directory does not exist", run_dir));
  for (const LiggghtsMeshFile& m : script.meshes) write_stl((dir / m.file_name).string(), m.mesh);
  std::ofstream(dir / kScriptFile) << script.text;

  LiggghtsRunOptions run_options = options;
  run_options.total_steps = script.plan.max_steps();
  const LiggghtsRunSummary summary = run_liggghts(run_dir, kScriptFile, run_options);
  const fs::path log = dir / "log.liggghts";
  const DumpFrame last = read_last_dump_frame((dir / kSnowfallDumpFile).string());
  const long grains = static_cast<long>(last.grains.size());
  if (grains != script.plan.grain_count) {
    throw LiggghtsRunError(run_dir, log.string(), fmt::format("{} grains at the end, {} rained (some failed to enter: "
                                                             "a larger insert_time_s gives them room)",
                                                             grains, script.plan.grain_count));
  }
  Run run;
  run.solver = "liggghts";
  run.wall_s = summary.wall_time_s;
  run.cpu_s = summary.cpu_time_s;
  run.stages = {"liggghts-snowfall"};
  const double steps = static_cast<double>(summary.last_step);
  run.set("grain_count", static_cast<double>(grains), "count");
  run.set("steps", steps, "count");
  run.set("run_wall_s", summary.wall_time_s, "s");
  run.set("run_cpu_s", summary.cpu_time_s, "s");
  run.set("particle_steps_per_cpu_s", summary.cpu_time_s > 0 ? static_cast<double>(grains) * steps / summary.cpu_time_s : 0.0, "");
  run.set("snow.open_depth_m", script.plan.open_depth_m, "m");
  run.details["liggghts_version"] = summary.version;
  run.details["script_sha256"] = sha256_hex(script.text);
  add_snow_fields(run, scene, model, last.grains);
  write_manifest(dir / "liggghts_manifest.json", scene, run, summary.version, sha256_hex(script.text));
  return run;
}

}  // namespace repose
