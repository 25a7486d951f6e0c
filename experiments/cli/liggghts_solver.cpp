// `repose run --solver liggghts`: the scene as a LIGGGHTS DEM reference run
// (validation/liggghts/liggghts_reference.h). The settled bed's surface replaces the
// scene's own initial height, so that a heuristic compared with this run
// starts from the same ground. A column scene (dem.initial: column) adds
// its runout and, for a cylinder, the pile's flank angles to the results;
// every object adds the mass of grains it holds at the end (mass_held_kg).
#include "experiments/figures/render_height.h"
#include "experiments/cli/solvers.h"
#include "validation/liggghts/liggghts_reference.h"

namespace repose::cli {

void run_liggghts_solver(RunContext& context) {
  LiggghtsReferenceOptions options;
  options.bed.run.progress = context.progress;
  options.run.progress = context.progress;
  const LiggghtsReferenceResult r =
      run_liggghts_reference(context.scene, context.out.temporary().string(), options);

  for (const char* name : {"height_final.npy", "height_final.csv", "height_initial.csv", "material_per_area_final.npy",
                           "material_per_area_final.csv", "forces.csv", "liggghts_manifest.json",
                           "bed_manifest.json", "run.in", "log.liggghts"}) {
    context.manifest.add_file(name);
  }
  if (r.column) context.manifest.add_file("runout.csv");
  if (r.pile) context.manifest.add_file("pile_flank_angles.csv");
  render_height_png(context.out.path("height_initial.png"), r.height_initial, &context.scene, 0.0, CameraOverrides{});
  render_height_png(context.out.path("height_final.png"), r.height_final, &context.scene,
                    context.scene.time.duration_s, CameraOverrides{});
  context.manifest.add_file("height_final.png");

  context.manifest.set_stages_built({r.bed.from_cache ? "bed:cached" : "bed:settled", "liggghts-run"});
  context.manifest.set_results([r](JsonWriter& json) {
    json.key("liggghts_version").string(r.run.version);
    json.key("script_sha256").string(r.script_sha256);
    json.key("bed_cache_key").string(r.bed.key);
    json.key("bed_from_cache").boolean(r.bed.from_cache);
    json.key("grain_count").integer(r.grain_count);
    json.key("steps").integer(r.steps);
    json.key("particle_steps_per_s").number(r.particle_steps_per_s);
    json.key("run_wall_s").number(r.run.wall_time_s);
    json.key("run_cpu_s").number(r.run.cpu_time_s);
    json.key("bed_wall_s").number(r.bed.wall_time_s);
    json.key("bed_cpu_s").number(r.bed.cpu_time_s);
    json.key("particle_steps_per_cpu_s")
        .number(r.run.cpu_time_s > 0 ? static_cast<double>(r.grain_count) * static_cast<double>(r.steps) / r.run.cpu_time_s
                                     : 0.0);
    write_column_results(json, r);
    write_mass_held_results(json, r);  // mass_held_kg.<object name>
  });
}

}  // namespace repose::cli
