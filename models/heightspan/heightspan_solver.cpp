#include "models/heightspan/heightspan_solver.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numeric>

#include <fmt/format.h>

#include "models/core/base/cpu_time.h"
#include "models/core/base/error.h"
#include "models/core/config/initial_height.h"
#include "models/core/io/npy_io.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_section.h"
#include "models/ground/material_parameters.h"
#include "models/ground/simulate_ground.h"
#include "models/ground/substep_count.h"
#include "models/heightspan/frame_image.h"
#include "models/heightspan/heightspan_model.h"
#include "models/heightspan/heightspan_section.h"
#include "models/heightspan/heightspan_state.h"
#include "models/heightspan/simulate_heightspan.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

std::string object_name(const HeightSpanModel& model, int object) {
  return model.ground.objects[static_cast<std::size_t>(object)].name;
}

// The section's vertical extent: from the base to above everything that can be there.
FrameView frame_view(const HeightSpanModel& model, const HeightField& initial) {
  FrameView view;
  const double h = model.ground.grid.cell_size_m;
  double top = initial.max_height_m();
  for (const ObjectSpec& o : model.ground.objects) {
    const double radius = o.body.V.rowwise().norm().maxCoeff();
    for (const Keyframe& k : o.keyframes) top = std::max(top, k.pose.position_m.z() + radius);
  }
  view.z_max_m = top + 2 * h;
  const ObjectSpec& first = model.ground.objects[static_cast<std::size_t>(model.held.front().object)];
  view.section_y_m = first.pose_at(0.0).position_m.y();
  view.px_per_cell = std::clamp(600 / std::max(1, model.ground.grid.nx), 1, 4);
  return view;
}

void add_measures(const HeightSpanModel& model, const HeightSpanRun& r, Run* run) {
  run->set("steps", r.steps, "count");
  run->set("step_wall_s_median", median(r.step_wall_s), "s");
  const double total = std::accumulate(r.step_wall_s.begin(), r.step_wall_s.end(), 0.0);
  run->set("step_wall_s_mean", r.steps > 0 ? total / r.steps : 0.0, "s");
  run->set("contact_cells_total", static_cast<double>(r.contact_cells), "count");
  double held = 0.0;
  for (std::size_t k = 0; k < model.held.size(); ++k) {
    const std::string name = object_name(model, model.held[k].object);
    const double final_m3 = r.held_m3[k].empty() ? 0.0 : r.held_m3[k].back();
    const double max_m3 = r.held_m3[k].empty() ? 0.0 : *std::max_element(r.held_m3[k].begin(), r.held_m3[k].end());
    held += final_m3;
    run->set("volume_held_m3." + name, final_m3, "m^3");
    run->set("mass_held_kg." + name, final_m3 * model.options.bulk_density_kg_m3, "kg");
    run->set("mass_held_max_kg." + name, max_m3 * model.options.bulk_density_kg_m3, "kg");
  }
  for (std::size_t k = 0; k < model.held.size(); ++k) {
    TimeSeries& mass = run->series["mass_held_kg." + object_name(model, model.held[k].object)];
    mass.unit = "kg";
    mass.time_s = r.time_s;
    for (const double m3 : r.held_m3[k]) mass.value.push_back(m3 * model.options.bulk_density_kg_m3);
  }
  run->set("volume.initial_m3", r.initial_m3, "m^3");
  run->set("volume.ground_final_m3", r.final_height.volume_m3(), "m^3");
  run->set("volume.held_final_m3", held, "m^3");
  run->set("volume.in_flight_final_m3", r.in_flight_m3.empty() ? 0.0 : r.in_flight_m3.back(), "m^3");
  run->set("volume.compressed_m3", r.ledger.compressed_m3, "m^3");
  run->set("volume.left_grid_m3", r.ledger.left_grid_m3, "m^3");
  run->set("volume.imbalance_m3", r.imbalance_m3.empty() ? 0.0 : r.imbalance_m3.back(), "m^3");
  run->set("ledger.max_abs_imbalance_m3", r.max_abs_imbalance_m3, "m^3");
  run->set("ledger.max_relative_imbalance", r.initial_m3 > 0.0 ? r.max_abs_imbalance_m3 / r.initial_m3 : 0.0, "1");
  run->set("flows.taken_up_m3", r.taken_up_m3, "m^3");
  run->set("flows.wedge_kept_m3", r.wedge_kept_m3, "m^3");
  run->set("flows.wedge_laid_m3", r.wedge_laid_m3, "m^3");
  run->set("flows.side_cut_m3", r.side_cut_m3, "m^3");
  run->set("flows.over_lip_m3", r.over_lip_m3, "m^3");
  run->set("volume.wedge_final_m3", r.wedge_final_m3, "m^3");
  run->set("flows.span_to_ground_m3", r.span_to_ground_m3, "m^3");
  run->set("flows.ground_to_span_m3", r.ground_to_span_m3, "m^3");
  run->set("flows.span_to_particles_m3", r.span_to_particles_m3, "m^3");
  run->set("particles.released", static_cast<double>(r.particles_released), "count");
  run->set("particles.landed_on_spans", static_cast<double>(r.particles_on_spans), "count");
  run->set("particles.landed_on_ground", static_cast<double>(r.particles_on_ground), "count");
  run->set("particles.left_grid", static_cast<double>(r.particles_left_grid), "count");
}

void write_held_csv(const HeightSpanModel& model, const HeightSpanRun& r, const std::string& path) {
  std::ofstream out(path);
  out << "time_s";
  for (const HeldObject& h : model.held) {
    const std::string name = object_name(model, h.object);
    out << ',' << name << "_volume_m3," << name << "_mass_kg";
  }
  out << ",in_flight_m3,ledger_imbalance_m3\n";
  for (std::size_t s = 0; s < r.time_s.size(); ++s) {
    out << fmt::format("{}", r.time_s[s]);
    for (std::size_t k = 0; k < model.held.size(); ++k) {
      out << fmt::format(",{},{}", r.held_m3[k][s], r.held_m3[k][s] * model.options.bulk_density_kg_m3);
    }
    out << fmt::format(",{},{}\n", r.in_flight_m3[s], r.imbalance_m3[s]);
  }
  if (!out) throw InputError("heightspan: cannot write " + path);
}

class CompiledHeightSpan final : public CompiledSolver {
 public:
  static constexpr std::ptrdiff_t kOwnParameters = 10;

  explicit CompiledHeightSpan(const Scene& scene)
      : model_(build_heightspan_model(scene)), initial_(make_initial_height(scene)), parameters_(model_.ground) {
    if (model_.held.empty()) check_counts(model_.ground);  // the ground path: as the ground solver checks
    infos_ = parameters_.infos();
    infos_.push_back({"intake_layer_m", "m", 1.0, 1e-9, 1e6, model_.options.intake_layer_m,
                      "the thickest ground layer a span's top takes in per cell while moving sideways; the rest "
                      "is pushed ahead (heightspan.intake_layer_m; 1e6: no limit)"});
    infos_.push_back({"intake_fraction", "1", 1.0, 1e-9, 1.0, model_.options.intake_fraction,
                      "the share of the ground above a span's top it takes in per cell while moving sideways; the "
                      "rest is pushed ahead (heightspan.intake_fraction; ground_contact.h: Intake)"});
    infos_.push_back({"wedge_fraction", "1", 1.0, 0.0, 1.0, model_.options.wedge_fraction,
                      "the fraction of what a held object's drag compresses (or its lip pushes, by "
                      "heightspan.wedge_source) kept as a wedge ahead of it (heightspan.wedge_fraction; drag_wedge.h)"});
    infos_.push_back({"lip_wedge_fraction", "1", 1.0, 0.0, 1.0, model_.options.lip_wedge_fraction,
                      "with heightspan.wedge_source split, the fraction of what a held object's lip pushes ahead "
                      "kept in its wedge (heightspan.lip_wedge_fraction; drag_wedge.h)"});
    infos_.push_back({"press_fraction", "1", 1.0, 0.0, 1.0, model_.options.press_fraction,
                      "the fraction of what a held object's pressing would compress displaced around its contact "
                      "instead (heightspan.press_fraction; drag_wedge.h)"});
    infos_.push_back({"press_wedge_fraction", "1", 1.0, 0.0, 1.0, model_.options.press_wedge_fraction,
                      "the fraction of what a held object's pressing compresses kept in its wedge, driven ahead by "
                      "the drag that follows (heightspan.press_wedge_fraction; drag_wedge.h)"});
    infos_.push_back({"side_cut_m", "m", 1.0, 0.0, 0.1, model_.options.side_cut_m,
                      "the width beside a dragged held object's sides cut into its wedge where its lip meets new "
                      "ground (heightspan.side_cut_m; side_cut.h)"});
    infos_.push_back({"over_lip_fraction", "1", 1.0, 0.0, 1.0, model_.options.over_lip_fraction,
                      "the fraction of what a held object's drag keeps in its wedge from the compression that "
                      "rolls over its lip into it instead (heightspan.over_lip_fraction; drag_wedge.h)"});
    infos_.push_back({"release_speed_m_s", "m/s", 1.0, 0.0, 2.0, model_.options.release_speed_m_s,
                      "the horizontal speed material flowing off a held object's edge into the air has along its "
                      "way, beside the object's own motion (heightspan.release_speed_m_s; span_erosion.h)"});
    infos_.push_back({"shear_layer_m", "m", 1.0, 0.0, 0.05, model_.options.shear_layer_m,
                      "the layer of ground beneath a held object's bottom that it shears off with it: its underside "
                      "meets the ground this much lower (heightspan.shear_layer_m; ground_contact.h)"});
  }

  const std::vector<ParameterInfo>& parameters() const override { return infos_; }

  Run run(const std::vector<double>& values_si, const RunOptions& options) const override {
    check_values(infos_, values_si, "heightspan");
    const Stopwatch clock;
    const std::vector<double> material(values_si.begin(), values_si.end() - kOwnParameters);
    const GroundParams params = parameters_.params_for(model_.ground, material);
    HeightSpanModel model = model_;
    const double* own = values_si.data() + material.size();  // in infos_' order
    model.options.intake_layer_m = own[0];
    model.options.intake_fraction = own[1];
    model.options.wedge_fraction = own[2];
    model.options.lip_wedge_fraction = own[3];
    model.options.press_fraction = own[4];
    model.options.press_wedge_fraction = own[5];
    model.options.side_cut_m = own[6];
    model.options.over_lip_fraction = own[7];
    model.options.release_speed_m_s = own[8];
    model.options.shear_layer_m = own[9];
    validate(model.options);
    Run run;
    run.solver = "heightspan";
    run.fields["height_initial"] = initial_;
    if (model_.held.empty()) {
      run_ground_path(params, options, &run);
    } else {
      run_spans(model, params, options, &run);
    }
    nlohmann::json ground_path = nlohmann::json::array();
    for (const int o : model_.ground_path) ground_path.push_back(object_name(model_, o));
    run.details["built"]["ground_path_objects"] = ground_path;
    run.wall_s = clock.wall_s();
    run.cpu_s = clock.cpu_s();
    return run;
  }

 private:
  void run_ground_path(const GroundParams& params, const RunOptions& options, Run* run) const {
    const GroundRun g = simulate_ground(model_.ground, params, initial_, options.progress);
    run->fields["height_final"] = g.final_height;
    run->stages = g.stages;
    run->set("steps", g.steps, "count");
    run->set("step_wall_s_median", median(g.step_wall_s), "s");
    run->set("volume.initial_m3", g.ledger.initial_m3, "m^3");
    run->set("volume.imbalance_m3", g.ledger.imbalance_m3(g.final_volume_m3), "m^3");
    run->details["built"] = {{"span_maps", nlohmann::json::array()}, {"particles", false}, {"path", "ground model"}};
  }

  void run_spans(const HeightSpanModel& model, const GroundParams& params, const RunOptions& options, Run* run) const {
    FrameFn frame;
    const FrameView view = frame_view(model, initial_);
    if (!options.output_dir.empty()) {
      fs::create_directories(fs::path(options.output_dir) / "frames");
      frame = [&](int n, const HeightSpanState& state) {
        const std::string png = fmt::format("frames/frame_{:04d}.png", n), npy = fmt::format("frames/height_{:04d}.npy", n);
        write_png_rgb((fs::path(options.output_dir) / png).string(), render_frame(model, state, view));
        write_npy_2d((fs::path(options.output_dir) / npy).string(), state.ground.height.heights());
        run->files.push_back(png);
        run->files.push_back(npy);
      };
    }
    const HeightSpanRun r = simulate_heightspan(model, params, initial_, options.progress, frame);
    run->fields["height_final"] = r.final_height;
    run->stages = r.stages;
    add_measures(model, r, run);
    nlohmann::json maps = nlohmann::json::array();
    for (const HeldObject& h : model_.held) maps.push_back(object_name(model_, h.object));
    run->details["built"] = {{"span_maps", maps},
                             {"span_map_path", model_.options.span_maps == HeightSpanSpec::SpanMaps::kOsmesa
                                                   ? "osmesa depth peeling"
                                                   : "cpu depth peeling"},
                             {"particles", r.particles_built},
                             {"path", "height-span model"}};
    if (!options.output_dir.empty()) {
      write_held_csv(model_, r, (fs::path(options.output_dir) / "held_mass.csv").string());
      run->files.push_back("held_mass.csv");
    }
  }

  HeightSpanModel model_;
  HeightField initial_;
  MaterialParameters parameters_;
  // the materials' (parameters_), then the model's own kOwnParameters: intake_layer_m, intake_fraction,
  // wedge_fraction, lip_wedge_fraction, press_fraction, press_wedge_fraction, side_cut_m, over_lip_fraction,
  // release_speed_m_s, shear_layer_m
  std::vector<ParameterInfo> infos_;
};

}  // namespace

std::vector<SectionType> HeightSpanSolver::sections() const {
  return {ground_model_section_type(), heightspan_section_type()};
}

bool HeightSpanSolver::can_run(const Scene& scene, std::string* why) const {
  return Solver::can_run(scene, why) && keyframed_objects_only(scene, why);
}

std::unique_ptr<CompiledSolver> HeightSpanSolver::compile(const Scene& scene) const {
  return std::make_unique<CompiledHeightSpan>(scene);
}

}  // namespace repose
