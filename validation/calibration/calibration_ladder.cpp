#include "validation/calibration/calibration_ladder.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "models/core/base/cpu_time.h"
#include "models/core/base/error.h"
#include "models/core/io/npy_io.h"
#include "models/core/config/scene_loader.h"
#include "models/ground/ground_section.h"
#include "validation/calibration/reference_cost.h"
#include "validation/particles/dem_section.h"
#include "validation/observables/calibration_observables.h"
#include "validation/observables/surface_change.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

// A surface on the yardstick's grid: area-weighted from finer cells, bilinear from coarser ones.
HeightField onto(const HeightField& field, const Grid& target) {
  if (field.grid() == target) return field;
  return field.grid().cell_size_m < target.cell_size_m ? resample_conservative(field, target)
                                                        : resample_bilinear(field, target);
}

// The scene's reference: its start and final surfaces (means over its seeds).
struct Yardstick {
  std::string label;
  HeightField initial, final_height;
};

// RMSE of a rung's surface change (final - initial, each brought onto the
// yardstick's grid) against the yardstick's. Comparing changes rather than
// final surfaces lets a DEM run on another random bed be compared too.
double change_rmse_m(const HeightField& initial, const HeightField& final_height, const Yardstick& yard,
                     const std::optional<CalibrationRegion>& region) {
  const Grid& g = yard.initial.grid();
  HeightField shifted = yard.initial;
  shifted.heights() += onto(final_height, g).heights() - onto(initial, g).heights();
  return score_change(yard.initial, shifted, yard.final_height, region).rmse_m;
}

std::string millimetres(double m) { return fmt::format("{:.3g} mm", m * 1e3); }

struct ReferenceRun {
  LadderRung rung;
  std::string directory;
  HeightField initial_height, final_height;
  SeriesByName series;
};

// The scene's series observables on one rung (LadderRung::series): the
// rung's values (`series`; initial and final only for observe()) beside
// the seeds' mean, leaving out `own_seed` (a rung that is that seed's run).
std::vector<SeriesComparison> rung_series(const PreparedScene& s, const HeightField& initial,
                                          const HeightField& final_height, const SeriesByName& series,
                                          std::optional<std::size_t> own_seed) {
  std::vector<SeriesComparison> out;
  for (const ObservableSpec& o : s.entry.observables) {
    if (o.kind != ObservableSpec::Kind::kSeries || series.count(o.series) == 0) continue;
    SeriesComparison c;
    c.series = o.series;
    c.unit = series.at(o.series).unit;
    c.times_s = o.times_s;
    for (std::size_t seed = 0; seed < s.seed_series.size(); ++seed) {
      if (seed != own_seed) c.seeds.push_back(seed_observation(o, s, seed));
    }
    if (c.seeds.empty()) continue;
    c.reference = mean_values(c.seeds);
    c.fitted = observe(o, initial, final_height, series);
    out.push_back(std::move(c));
  }
  return out;
}

std::string engine_label(const std::string& engine) {
  if (engine == "liggghts") return "LIGGGHTS";
  if (engine == "bullet") return "Bullet";
  if (engine == "ode") return "ODE";
  return engine;
}

ReferenceRun load_reference_rung(const LadderReference& ref, const SectionTypes& sections) {
  const Scene scene = load_scene(ref.scene_path, sections);
  if (dem_of(scene) == nullptr) {
    throw InputError(ref.scene_path + ": a ladder reference scene needs a dem section (its grain size)");
  }
  const Grid& grid = scene.ground.grid;
  ReferenceRun run;
  run.directory = ref.directory;
  const std::string what = "a ladder run of " + ref.scene_path;
  run.initial_height = read_height_field((fs::path(ref.directory) / "height_initial.npy").string(), grid, what);
  run.final_height = read_height_field((fs::path(ref.directory) / "height_final.npy").string(), grid, what);
  run.series = read_reference_series(ref.directory);
  run.rung.kind = read_run_engine(ref.directory);
  run.rung.resolution_m = 2.0 * dem_of(scene)->grain_radius_m;
  run.rung.label = engine_label(run.rung.kind) + " d = " + millimetres(run.rung.resolution_m);
  const auto cost = read_run_cost(ref.directory);
  if (!cost) throw InputError(ref.directory + ": a ladder reference folder without its cost (liggghts_manifest.json or manifest.json)");
  run.rung.wall_time_s = cost->wall_s;
  run.rung.cpu_time_s = cost->cpu_s;
  return run;
}

// A particle engine's rung: its ground error and series. A run that is one
// of the reference's own seeds is compared with the mean of the other seeds
// (comparing it with a mean that holds it would flatter it): its error is
// then the reference's noise.
void score_reference_rung(ReferenceRun& run, const PreparedScene& s, const Yardstick& yard) {
  const auto& seeds = s.entry.reference.directories;
  const auto own = std::find_if(seeds.begin(), seeds.end(),
                                [&](const std::string& d) { return fs::equivalent(d, run.directory); });
  if (own == seeds.end() || seeds.size() < 2) {
    run.rung.rmse_m = change_rmse_m(run.initial_height, run.final_height, yard, s.entry.rmse_region);
    run.rung.series = rung_series(s, run.initial_height, run.final_height, run.series, std::nullopt);
    return;
  }
  const std::size_t own_seed = static_cast<std::size_t>(own - seeds.begin());
  std::vector<HeightField> initial, final_height;
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    if (k == own_seed) continue;
    initial.push_back(s.seed_initial[k]);
    final_height.push_back(s.seed_final[k]);
  }
  run.rung.label += " (one seed, against the others' mean)";
  const Yardstick others{"", mean_field(initial), mean_field(final_height)};
  run.rung.rmse_m = change_rmse_m(run.initial_height, run.final_height, others, s.entry.rmse_region);
  run.rung.series = rung_series(s, run.initial_height, run.final_height, run.series, own_seed);
}

// The scene on a grid of cell size h over the same extent.
Grid regridded(const Grid& grid, double h, const std::string& source) {
  if (const auto g = grid.with_cell_size(h)) return *g;
  throw InputError(fmt::format("{}: ladder.heuristic_cell_sizes_m: {} m does not divide the scene's extent {} x {} m",
                               source, h, grid.extent_x_m(), grid.extent_y_m()));
}

struct RunTimes {
  double wall_s = std::numeric_limits<double>::infinity();
  double cpu_s = std::numeric_limits<double>::infinity();
};

// The fastest of `repeats` runs of the calibrated solver on `scene` (its
// parameters by name from the prepared scene's values), by wall and by
// thread CPU time (the heuristics run on the calling thread; on a shared
// machine the CPU time is the steadier), and the result.
RunTimes timed_run(const CalibrationProblem& problem, const PreparedScene& prepared, const Scene& scene,
                   const std::vector<double>& values, int repeats, Run* result) {
  const auto solver = problem.solver().compile(scene);
  std::vector<double> solver_values = solver->default_values();
  const std::vector<double> prepared_values = problem.solver_values(prepared, values);
  for (std::size_t k = 0; k < prepared_values.size(); ++k) {
    solver_values[solver->parameter_index(prepared.solver->parameters()[k].name)] = prepared_values[k];
  }
  RunTimes best;
  for (int r = 0; r < repeats; ++r) {
    const Stopwatch watch;
    Run run = solver->run(solver_values, RunOptions{});
    best.wall_s = std::min(best.wall_s, watch.wall_s());
    best.cpu_s = std::min(best.cpu_s, watch.cpu_s());
    *result = std::move(run);
  }
  return best;
}

Scene with_initial(Scene scene, const HeightField& initial) {
  scene.ground.initial.kind = InitialHeight::Kind::kGiven;
  scene.ground.initial.given = std::make_shared<const HeightField>(initial);
  return scene;
}

// A rung of the calibrated solver on `scene`, its surface against the yardstick.
LadderRung solver_rung(const CalibrationProblem& problem, const PreparedScene& s, const Scene& scene,
                       const std::vector<double>& values, const Yardstick& yard, LadderRung rung) {
  const LadderSpec& spec = *problem.spec().ladder;
  Run run;
  const RunTimes times = timed_run(problem, s, scene, values, spec.timing_repeats, &run);
  rung.wall_time_s = times.wall_s;
  rung.cpu_time_s = times.cpu_s;
  const HeightField& initial = scene.ground.initial.given ? *scene.ground.initial.given : yard.initial;
  const HeightField& final_height = run.field("height_final");
  rung.rmse_m = change_rmse_m(initial, final_height, yard, s.entry.rmse_region);
  rung.series = rung_series(s, initial, final_height, run.series, std::nullopt);
  return rung;
}

// A rung before it is run: what it is.
LadderRung unmeasured_rung(std::string label, std::string kind, double resolution_m) {
  LadderRung rung;
  rung.label = std::move(label);
  rung.kind = std::move(kind);
  rung.resolution_m = resolution_m;
  return rung;
}

// The cell sizes of the ladder, the scene's own included, coarsest first.
std::vector<double> ladder_cell_sizes(const LadderSpec& spec, double own) {
  std::vector<double> sizes = spec.heuristic_cell_sizes_m;
  if (std::none_of(sizes.begin(), sizes.end(), [&](double h) { return std::abs(h - own) <= 1e-9 * own; })) sizes.push_back(own);
  std::sort(sizes.begin(), sizes.end(), std::greater<>());
  return sizes;
}

// Every object on the coarse grid of the ground model's multi-resolution stage.
Scene multires_scene(Scene scene, int coarse_factor) {
  for (ObjectSpec& o : scene.objects) o.simple = true;
  GroundModelSpec options = ground_model_section(scene).options;
  options.coarse_factor = coarse_factor;
  return with_ground_options(std::move(scene), options);
}

}  // namespace

Ladder measure_ladder(const CalibrationProblem& problem, const std::vector<double>& values, const ProgressFn& progress) {
  REPOSE_DEMAND(problem.spec().ladder.has_value());
  const LadderSpec& spec = *problem.spec().ladder;
  const PreparedScene& s = problem.scene_named(spec.scene);
  Ladder ladder;
  ladder.scene = s.entry.name;
  std::vector<ReferenceRun> runs;
  for (const LadderReference& ref : spec.references) runs.push_back(load_reference_rung(ref, problem.registry().sections()));
  // LIGGGHTS first, then by engine; finest grains first
  std::stable_sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) {
    const bool la = a.rung.kind == "liggghts", lb = b.rung.kind == "liggghts";
    if (la != lb) return la;
    if (a.rung.kind != b.rung.kind) return a.rung.kind < b.rung.kind;
    return a.rung.resolution_m < b.rung.resolution_m;
  });
  const std::size_t seeds = std::max<std::size_t>(1, s.seed_final.size());
  const Yardstick yard{fmt::format("the scene's reference (mean of {} seed{})", seeds, seeds > 1 ? "s" : ""), s.initial,
                       s.reference_final};
  ladder.yardstick = yard.label;
  if (const auto noise = noise_floor(s.seed_initial, s.seed_final, s.entry.rmse_region)) ladder.noise_floor_m = noise->rmse_m;

  const std::string solver = problem.solver().name();
  const double own_h = s.scene.ground.grid.cell_size_m;
  const std::vector<double> sizes = ladder_cell_sizes(spec, own_h);
  std::optional<LadderRung> own;
  const std::size_t total = sizes.size() + (spec.multires ? 1 : 0);
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const double h = sizes[k];
    report(progress, static_cast<double>(k) / total, "ladder: " + solver + " at " + millimetres(h));
    Scene scene = s.scene;
    scene.ground.grid = regridded(s.scene.ground.grid, h, problem.spec().source_path);
    scene = with_initial(std::move(scene), onto(s.initial, scene.ground.grid));
    ladder.rungs.push_back(solver_rung(problem, s, scene, values, yard, unmeasured_rung(solver + " " + millimetres(h), solver, h)));
    if (std::abs(h - own_h) <= 1e-9 * own_h) own = ladder.rungs.back();
  }
  if (spec.multires) {
    report(progress, static_cast<double>(sizes.size()) / total, "ladder: multi-resolution " + solver);
    const std::string label =
        fmt::format("{} multires {} / {}", solver, millimetres(own_h), millimetres(own_h * spec.multires_coarse_factor));
    ladder.rungs.push_back(solver_rung(problem, s, multires_scene(s.scene, spec.multires_coarse_factor), values, yard,
                                       unmeasured_rung(label, solver + "-multires", own_h)));
  }
  for (ReferenceRun& run : runs) {
    score_reference_rung(run, s, yard);
    ladder.rungs.push_back(run.rung);
  }
  if (own) ladder.own_rung = own->label;
  if (!runs.empty() && runs.front().rung.kind == "liggghts") {
    // LIGGGHTS' finest grains: the reference's own resolution
    const LadderRung& liggghts = runs.front().rung;
    for (LadderRung& r : ladder.rungs) {
      if (liggghts.cpu_time_s && r.cpu_time_s && *r.cpu_time_s > 0.0) r.liggghts_cpu_over_this = *liggghts.cpu_time_s / *r.cpu_time_s;
    }
    if (own && own->wall_time_s > 0.0 && *own->cpu_time_s > 0.0) {
      ladder.liggghts_over_ground_time = liggghts.wall_time_s / own->wall_time_s;
      if (liggghts.cpu_time_s) ladder.liggghts_over_ground_cpu_time = *liggghts.cpu_time_s / *own->cpu_time_s;
    }
  }
  report(progress, 1.0, "ladder measured");
  return ladder;
}

}  // namespace repose
