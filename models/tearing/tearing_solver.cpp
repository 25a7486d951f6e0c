#include "models/tearing/tearing_solver.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <random>

#include <fmt/format.h>

#include "models/core/base/cpu_time.h"
#include "models/core/base/error.h"
#include "models/core/config/scene.h"
#include "models/tearing/fibre_image.h"
#include "models/tearing/sheet_model.h"
#include "models/tearing/tear_edge_layers.h"
#include "models/tearing/tear_image.h"
#include "models/tearing/tear_path.h"
#include "models/tearing/tear_run.h"
#include "models/tearing/tearing_section.h"
#include "models/tearing/tensile_test.h"

namespace repose {

namespace {

// One scalar per cell (or vertex) as a HeightField on a grid of that pitch.
HeightField grid_field(int nx, int ny, double pitch_m, double origin_m, const std::vector<double>& values) {
  Grid grid;
  grid.nx = nx;
  grid.ny = ny;
  grid.cell_size_m = pitch_m;
  grid.origin_x_m = grid.origin_y_m = origin_m;
  HeightField field(grid);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) field.at(i, j) = values[static_cast<std::size_t>(j) * nx + i];
  }
  return field;
}

class CompiledTearing final : public CompiledSolver {
 public:
  explicit CompiledTearing(const Scene& scene) : section_(*scene.section<TearingSection>()), run_options_(section_.run) {
    run_options_.duration_s = scene.time.duration_s;  // the scene's time, however it was changed
    run_options_.validate();
    std::mt19937_64 rng(scene.seed);
    const SheetSpec& spec = section_.sheet;
    images_ = draw_fibre_images(spec.fibres, spec.width_m, spec.height_m, rng);
    model_ = build_sheet_model(spec, images_);
    const SheetParams& p = section_.params;
    parameters_ = {{"stiffness_scale", "N/m", 1.0, 1.0, 1.0e9, p.stiffness_n_per_m,
                    "in-plane stiffness E t of the sheet at mean fibre density"}};
    if (spec.tear_rule == TearRule::kStrain) {
      parameters_.push_back(
          {"tear_strain", "1", 1.0, 1.0e-6, 10.0, p.tear_strain, "a cell tears when a spring stretches past this strain"});
    } else {
      parameters_.push_back({"tear_energy", "J/m", 1.0, 1.0e-9, 1.0e6, p.tear_energy_j_per_m,
                             "energy per unit tear length; sets the tear strain with the cell size (tear_limit.h)"});
    }
    parameters_.push_back({"fibre_anisotropy", "1", 1.0, 0.0, 0.99, p.fibre_anisotropy,
                           "springs along the grain (1 + a), across it (1 - a) times stiffer (sheet_params.h)"});
  }

  const std::vector<ParameterInfo>& parameters() const override { return parameters_; }

  Run run(const std::vector<double>& values_si, const RunOptions& options) const override {
    check_values(parameters_, values_si, "tearing");
    const Stopwatch clock;
    SheetParams params = section_.params;
    params.stiffness_n_per_m = values_si[0];
    (model_.spec.tear_rule == TearRule::kStrain ? params.tear_strain : params.tear_energy_j_per_m) = values_si[1];
    params.fibre_anisotropy = values_si[2];
    params.validate();
    if (section_.tensile) return run_tensile(params, options, clock);
    const TearRunOptions& tear = run_options_;
    const TearRun pulled = run_tear(model_, params, tear, options.progress);
    Run run;
    run.solver = "tearing";
    run.stages = {tear.integrator == TearRunOptions::Integrator::kExplicit ? "explicit" : "implicit", "tearing"};
    add_measures(pulled, &run);
    add_fields(pulled.state, &run);
    set_timings(clock, &run);
    const double simulated_s = pulled.state.time_s;
    run.set("simulated_time_s", simulated_s, "s");
    if (simulated_s > 0.0) {
      run.set("cpu_s_per_simulated_s", run.cpu_s / simulated_s, "s/s");
      run.set("wall_s_per_simulated_s", run.wall_s / simulated_s, "s/s");
    }
    if (!options.output_dir.empty()) {
      write_files(pulled.state, options.output_dir, &run);
      write_grip_forces(pulled, options.output_dir, &run);
    }
    return run;
  }

 private:
  // grip_force.csv: the grips' forces over time (TearRun::grip_force_n).
  static void write_grip_forces(const TearRun& t, const std::string& dir, Run* run) {
    std::ofstream csv(dir + "/grip_force.csv");
    csv << "time_s,grip,force_x_n,force_y_n,force_z_n\n";
    for (std::size_t k = 0; k < t.force_time_s.size(); ++k) {
      for (Eigen::Index g = 0; g < t.grip_force_n[k].cols(); ++g) {
        const Eigen::Vector3d f = t.grip_force_n[k].col(g);
        csv << fmt::format("{},{},{},{},{}\n", t.force_time_s[k], g, f.x(), f.y(), f.z());
      }
    }
    if (!csv) throw InputError(fmt::format("tearing: could not write {}/grip_force.csv", dir));
    run->files.push_back("grip_force.csv");
  }

  Run run_tensile(const SheetParams& params, const RunOptions& options, const Stopwatch& clock) const {
    const TensileResult t = run_tensile_test(model_, params, *section_.tensile);
    Run run;
    run.solver = "tearing";
    run.stages = {"explicit", "tensile"};
    run.set("tensile.stiffness_n_per_m", t.stiffness_n_per_m, "N/m");
    run.set("tensile.strength_n_per_m", t.strength_n_per_m, "N/m");
    run.set("tensile.strain_at_peak", t.strain_at_peak, "1");
    run.set("tensile.broke", t.broke ? 1.0 : 0.0, "1");
    run.set("steps", static_cast<double>(t.steps), "count");
    set_timings(clock, &run);
    if (!options.output_dir.empty()) {
      std::ofstream csv(options.output_dir + "/tensile.csv");
      csv << "strain,force_per_width_n_per_m\n";
      for (std::size_t k = 0; k < t.strain.size(); k += std::max<std::size_t>(1, t.strain.size() / 2000)) {
        csv << fmt::format("{},{}\n", t.strain[k], t.force_per_width_n_per_m[k]);
      }
      run.files.push_back("tensile.csv");
    }
    return run;
  }

  // Run::wall_s and cpu_s, and the same as the measures run_wall_s and
  // run_cpu_s (as the rigid references report them) for experiments' tables.
  static void set_timings(const Stopwatch& clock, Run* run) {
    run->wall_s = clock.wall_s();
    run->cpu_s = clock.cpu_s();
    run->set("run_wall_s", run->wall_s, "s");
    run->set("run_cpu_s", run->cpu_s, "s");
  }

  static void add_measures(const TearRun& t, Run* run) {
    run->set("tear.length_m", t.tear_length_m, "m");
    run->set("tear.depth_m", t.path.depth_m, "m");
    run->set("tear.tortuosity", t.path.tortuosity, "1");
    run->set("tear.roughness_m", t.path.roughness_m, "m");
    run->set("tear.deviation_m", t.path.deviation_m, "m");
    run->set("tear.cells", t.path.tear_cells, "count");
    run->set("tear.stray_cells", t.path.stray_cells, "count");
    run->set("tear.from_notch", t.path.holds_notch ? 1.0 : 0.0, "1");
    run->set("tear.work_per_length_j_per_m", t.work_per_tear_length_j_per_m, "J/m");
    run->set("tear.fracture_energy_per_length_j_per_m", t.fracture_energy_per_tear_length_j_per_m, "J/m");
    run->set("tear.fracture_energy_per_path_length_j_per_m", t.fracture_energy_per_path_length_j_per_m, "J/m");
    run->set("grip.peak_force_n", t.peak_grip_force_n, "N");
    run->set("grip.work_j", t.grip_work_j, "J");
    // the energy ledger (tear_run.h), J, and per unit tear length, J/m
    const std::pair<const char*, double> ledger[] = {
        {"stored", t.ledger.stored_j},   {"kinetic", t.ledger.kinetic_j},   {"gravity", t.ledger.gravity_j},
        {"damping", t.ledger.damping_j}, {"fracture", t.ledger.fracture_j}, {"residual", t.ledger.residual_j},
        {"stored_structural", t.ledger.stored.structural_j}, {"stored_shear", t.ledger.stored.shear_j},
        {"stored_bending", t.ledger.stored.bending_j}, {"stored_twist", t.ledger.stored.twist_j},
        {"torn_twist", t.ledger.torn_twist_j}, {"torn_bending", t.ledger.torn_bending_j}};
    for (const auto& [name, joules] : ledger) {
      run->set(fmt::format("energy.{}_j", name), joules, "J");
      run->set(fmt::format("energy.{}_per_length_j_per_m", name), t.tear_length_m > 0.0 ? joules / t.tear_length_m : 0.0,
               "J/m");
    }
    if (!t.state.softening.empty()) {  // tear_rule cohesive: the softening springs' part of the fracture energy
      run->set("energy.softening_j", t.ledger.softening_j, "J");
      run->set("energy.softening_per_length_j_per_m", t.tear_length_m > 0.0 ? t.ledger.softening_j / t.tear_length_m : 0.0,
               "J/m");
    }
    run->set("steps", static_cast<double>(t.steps), "count");
    run->set("time_step_s", t.time_step_s, "s");
    run->set("stable_time_step_s", t.stable_time_step_s, "s");
  }

  void add_fields(const SheetState& state, Run* run) const {
    const double h = model_.cell_size_m;
    std::vector<double> torn(static_cast<std::size_t>(model_.cell_count()));
    for (int c = 0; c < model_.cell_count(); ++c) {
      const int step = state.torn_step[static_cast<std::size_t>(c)];
      torn[static_cast<std::size_t>(c)] = step < 0 ? -1.0 : step * (state.steps > 0 ? state.time_s / state.steps : 0.0);
    }
    run->fields["torn_time_s"] = grid_field(model_.cells_x, model_.cells_y, h, 0.0, torn);
    std::vector<double> z(static_cast<std::size_t>(model_.vertex_count()));
    for (int v = 0; v < model_.vertex_count(); ++v) z[static_cast<std::size_t>(v)] = state.positions(2, v);
    run->fields["displacement_z_m"] = grid_field(model_.cells_x + 1, model_.cells_y + 1, h, -0.5 * h, z);
    // the vertices' velocities, for where the kinetic energy sits
    // (experiments/tearing/bending_spectrum.py)
    for (int a = 0; a < 3; ++a) {
      for (int v = 0; v < model_.vertex_count(); ++v) z[static_cast<std::size_t>(v)] = state.velocities(a, v);
      run->fields[fmt::format("velocity_{}_m_per_s", "xyz"[a])] =
          grid_field(model_.cells_x + 1, model_.cells_y + 1, h, -0.5 * h, z);
    }
    Grid pixels;
    pixels.nx = images_.nx();
    pixels.ny = images_.ny();
    pixels.cell_size_m = images_.pixel_size_m;
    run->fields["fibre_composite"] = HeightField(pixels, images_.composite);
  }

  void write_files(const SheetState& state, const std::string& dir, Run* run) const {
    for (const std::string& path : write_fibre_pngs(images_, dir + "/fibres_")) {
      run->files.push_back(std::filesystem::path(path).filename().string());
    }
    write_png_rgb(dir + "/tear_map.png", draw_tear_image(model_, state, images_, 8));
    const TearEdgeOptions edge;
    write_png_rgb(dir + "/tear_edge.png",
                  draw_layered_tear_edge(images_, trace_layer_cuts(model_, state, images_, edge), edge));
    run->files.push_back("tear_map.png");
    run->files.push_back("tear_edge.png");
  }

  TearingSection section_;
  TearRunOptions run_options_;
  FibreImages images_;
  SheetModel model_;
  std::vector<ParameterInfo> parameters_;
};

}  // namespace

std::vector<SectionType> TearingSolver::sections() const { return {tearing_section_type()}; }

bool TearingSolver::can_run(const Scene& scene, std::string* why) const {
  if (scene.has_section(TearingSection::kKey)) return true;
  if (why != nullptr) *why = "the scene has no tearing: section";
  return false;
}

std::unique_ptr<CompiledSolver> TearingSolver::compile(const Scene& scene) const {
  if (!scene.has_section(TearingSection::kKey)) {
    throw InputError(fmt::format("{}: the tearing solver needs a tearing: section", scene.source_path));
  }
  return std::make_unique<CompiledTearing>(scene);
}

}  // namespace repose
