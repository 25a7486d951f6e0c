#include "experiments/runner/run_scene.h"

#include "experiments/figures/render_height.h"
#include "experiments/cli/solvers.h"
#include "models/core/config/initial_height.h"
#include "models/core/io/npy_io.h"

namespace repose::cli {

void run_scene(const Scene& scene, const std::string& solver, OutputDirectory& out, Manifest& manifest,
               const ProgressFn& progress) {
  manifest.set_solver(solver);
  manifest.set_scene(scene);

  HeightField initial;
  manifest.time_stage("initial_height", [&] { initial = make_initial_height(scene); });
  manifest.time_stage("write_height_initial_npy", [&] { write_npy_2d(out.path("height_initial.npy"), initial.heights()); });
  manifest.add_file("height_initial.npy");
  manifest.time_stage("render_height_initial_png", [&] {
    render_height_png(out.path("height_initial.png"), initial, &scene, 0.0, CameraOverrides{});
  });
  manifest.add_file("height_initial.png");

  RunContext context{scene, initial, out, manifest, progress};
  manifest.time_stage("solver_" + solver, [&] { find_solver(solver).run(context); });

  manifest.add_file("manifest.json");
  manifest.write(out.path("manifest.json"));
}

}  // namespace repose::cli
