#pragma once
// `--solver tearing`: the paper-tearing sheet (models/tearing) as a repose
// Solver. Compiling draws the fibre images from the scene's seed and builds
// the sheet once; the parameters are stiffness_scale (E t, N/m) and
// tear_strain (1) under the strain rule or tear_energy (J/m) under the
// energy rule (tear_limit.h), and fibre_anisotropy (1). A run pulls the sheet by its grips for time.duration_s
// (or until the tear is stop_at_depth_m deep) and returns the fields
// fibre_composite (fibre density on the image's pixels), torn_time_s (per
// cell: when it tore, s; 0 for the notch, -1 intact) and displacement_z_m
// (per vertex, on a grid of cell pitch centred on the vertices), and the
// measures tear.length_m, tear.depth_m, tear.tortuosity, tear.roughness_m,
// tear.deviation_m, tear.cells, tear.stray_cells, tear.from_notch,
// grip.peak_force_n, grip.work_j, tear.work_per_length_j_per_m, steps,
// time_step_s, stable_time_step_s and simulated_time_s, and its timings:
// run_wall_s and run_cpu_s (the run without compiling and writing files,
// also in Run::wall_s and cpu_s; thread CPU time) and cpu_s_per_simulated_s
// and wall_s_per_simulated_s (for speed/accuracy ladders). The timings are
// the only measures that differ between two runs of the same scene.
// A scene with tensile: runs the tensile test of tensile_test.h instead and
// returns tensile.stiffness_n_per_m, tensile.strength_n_per_m,
// tensile.strain_at_peak, tensile.broke, steps, run_wall_s and run_cpu_s (and, with an
// output folder, tensile.csv: force per width against strain). With an output folder it writes the
// fibre layers and composite (16-bit PNG), the tear map and the layered tear
// edge (RGB PNG). The scene's ground is not used.

#include "models/core/solver/solver.h"

namespace repose {

class TearingSolver final : public Solver {
 public:
  std::string name() const override { return "tearing"; }
  std::string description() const override {
    return "paper tearing: a mass-spring sheet on fibre-density images (models/tearing): tear path, grip force";
  }
  std::vector<SectionType> sections() const override;
  bool can_run(const Scene& scene, std::string* why) const override;
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override;
};

}  // namespace repose
