#include "experiments/runner/run_scene.h"

#include "experiments/figures/render_height.h"
#include "models/core/io/npy_io.h"

namespace repose::cli {

namespace {

// Each field as NAME.npy; height fields also as NAME.png (the scene's camera).
void write_fields(const Run& run, const Scene& scene, OutputDirectory& out, Manifest& manifest) {
  for (const auto& [name, field] : run.fields) {
    manifest.time_stage("write_" + name + "_npy", [&] { write_npy_2d(out.path(name + ".npy"), field.heights()); });
    manifest.add_file(name + ".npy");
    if (!name.starts_with("height_")) continue;
    const double time_s = name == "height_initial" ? 0.0 : scene.time.duration_s;
    manifest.time_stage("render_" + name + "_png", [&] {
      render_height_png(out.path(name + ".png"), field, &scene, time_s, CameraOverrides{});
    });
    manifest.add_file(name + ".png");
  }
}

}  // namespace

Run run_scene(const Scene& scene, const Solver& solver, OutputDirectory& out, Manifest& manifest,
              const ProgressFn& progress) {
  manifest.set_solver(solver.name());
  manifest.set_scene(scene);
  std::unique_ptr<CompiledSolver> compiled;
  manifest.time_stage("compile_" + solver.name(), [&] { compiled = solver.compile(scene); });
  Run run;
  manifest.time_stage("solver_" + solver.name(), [&] {
    run = compiled->run(compiled->default_values(), RunOptions{progress, out.temporary().string()});
  });
  write_fields(run, scene, out, manifest);
  for (const std::string& file : run.files) manifest.add_file(file);
  manifest.set_run(run);
  manifest.add_file("manifest.json");
  manifest.write(out.path("manifest.json"));
  return run;
}

}  // namespace repose::cli
