#include "validation/calibration/calibration_ladder.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "models/core/base/error.h"
#include "models/core/io/npy_io.h"
#include "models/core/config/scene_loader.h"
#include "models/ground/simulate_ground.h"
#include "validation/observables/calibration_observables.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

struct Yardstick {
  std::string label;
  HeightField final_height;
};

// A surface on the yardstick's grid: area-weighted from finer cells, bilinear from coarser ones.
HeightField onto(const HeightField& field, const Grid& target) {
  if (field.grid() == target) return field;
  return field.grid().cell_size_m < target.cell_size_m ? resample_conservative(field, target)
                                                        : resample_bilinear(field, target);
}

double manifest_number(const std::string& directory, const char* key) {
  const std::string path = (fs::path(directory) / "liggghts_manifest.json").string();
  try {
    return YAML::LoadFile(path)[key].as<double>();
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("{}: no number {} ({})", path, key, e.what()));
  }
}

std::string millimetres(double m) { return fmt::format("{:.3g} mm", m * 1e3); }

struct LiggghtsRun {
  LadderRung rung;
  HeightField final_height;
};

LiggghtsRun load_liggghts_rung(const LadderReference& ref) {
  const Scene scene = load_scene(ref.scene_path);
  if (!scene.dem) throw InputError(ref.scene_path + ": a ladder LIGGGHTS scene needs a dem section (its grain size)");
  const std::string path = (fs::path(ref.directory) / "height_final.npy").string();
  const ArrayXXdR a = read_npy_2d(path);
  const Grid& grid = scene.ground.grid;
  if (a.rows() != grid.ny || a.cols() != grid.nx) {
    throw InputError(fmt::format("{}: {} x {} heights, its scene's grid ({}) is {} x {}", path, a.rows(), a.cols(),
                                 ref.scene_path, grid.ny, grid.nx));
  }
  LiggghtsRun run;
  run.final_height = HeightField(grid, a);
  run.rung.kind = "liggghts";
  run.rung.resolution_m = 2.0 * scene.dem->grain_radius_m;
  run.rung.label = "LIGGGHTS d = " + millimetres(run.rung.resolution_m);
  run.rung.wall_time_s = manifest_number(ref.directory, "wall_time_s");
  run.rung.cpu_time_s = manifest_number(ref.directory, "cpu_time_s");
  return run;
}

// The scene on a grid of cell size h over the same extent.
Grid regridded(const Grid& grid, double h, const std::string& source) {
  const double nx = grid.extent_x_m() / h, ny = grid.extent_y_m() / h;
  Grid g = grid;
  g.nx = static_cast<int>(std::llround(nx));
  g.ny = static_cast<int>(std::llround(ny));
  g.cell_size_m = h;
  if (g.nx < 1 || g.ny < 1 || std::abs(nx - g.nx) > 1e-6 || std::abs(ny - g.ny) > 1e-6) {
    throw InputError(fmt::format("{}: ladder.heuristic_cell_sizes_m: {} m does not divide the scene's extent {} x {} m",
                                 source, h, grid.extent_x_m(), grid.extent_y_m()));
  }
  return g;
}

// The fastest of `repeats` runs, and the result.
double timed_run(const GroundModel& model, const GroundParams& params, const HeightField& initial, int repeats,
                 HeightField* result) {
  double best = std::numeric_limits<double>::infinity();
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    GroundRun run = simulate_ground(model, params, initial);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    *result = std::move(run.final_height);
  }
  return best;
}

}  // namespace

Ladder measure_ladder(const CalibrationProblem& problem, const std::vector<double>& values, const ProgressFn& progress) {
  REPOSE_DEMAND(problem.spec().ladder.has_value());
  const LadderSpec& spec = *problem.spec().ladder;
  const PreparedScene& s = problem.scene_named(spec.scene);
  const auto& region = s.entry.rmse_region;
  Ladder ladder;
  ladder.scene = s.entry.name;

  std::vector<LiggghtsRun> runs;
  for (const LadderReference& ref : spec.liggghts) runs.push_back(load_liggghts_rung(ref));
  std::sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.rung.resolution_m < b.rung.resolution_m; });
  Yardstick yard{"the scene's reference", s.reference_final};
  if (!runs.empty()) {
    runs.front().rung.yardstick = true;
    yard = {runs.front().rung.label, runs.front().final_height};
  }
  ladder.yardstick = yard.label;
  const Grid& yard_grid = yard.final_height.grid();

  // the ground model at each cell size, the scene's own included
  std::vector<double> sizes = spec.heuristic_cell_sizes_m;
  const double own = s.scene.ground.grid.cell_size_m;
  if (std::none_of(sizes.begin(), sizes.end(), [&](double h) { return std::abs(h - own) <= 1e-9 * own; })) sizes.push_back(own);
  std::sort(sizes.begin(), sizes.end(), std::greater<>());
  const GroundParams params = problem.params_for(s, values);
  std::optional<double> own_time;
  std::size_t done = 0;
  const std::size_t total = sizes.size() + (spec.multires ? 1 : 0);
  for (const double h : sizes) {
    report(progress, static_cast<double>(done++) / total, "ladder: ground model at " + millimetres(h));
    Scene scene = s.scene;
    scene.ground.grid = regridded(s.scene.ground.grid, h, problem.spec().source_path);
    const GroundModel model = build_ground_model(scene);
    const HeightField initial = onto(s.initial, scene.ground.grid);
    HeightField result;
    LadderRung rung;
    rung.kind = "ground";
    rung.resolution_m = h;
    rung.label = "ground " + millimetres(h);
    rung.wall_time_s = timed_run(model, params, initial, spec.timing_repeats, &result);
    rung.rmse_m = surface_rmse_m(onto(result, yard_grid), yard.final_height, region);
    if (std::abs(h - own) <= 1e-9 * own) own_time = rung.wall_time_s;
    ladder.rungs.push_back(rung);
  }
  if (spec.multires) {
    report(progress, static_cast<double>(done++) / total, "ladder: multi-resolution ground model");
    Scene scene = s.scene;
    for (ObjectSpec& o : scene.objects) o.simple = true;
    scene.ground_model.coarse_factor = spec.multires_coarse_factor;
    const GroundModel model = build_ground_model(scene);
    HeightField result;
    LadderRung rung;
    rung.kind = "ground-multires";
    rung.resolution_m = own;
    rung.label = fmt::format("ground multires {} / {}", millimetres(own), millimetres(own * spec.multires_coarse_factor));
    rung.wall_time_s = timed_run(model, params, s.initial, spec.timing_repeats, &result);
    rung.rmse_m = surface_rmse_m(onto(result, yard_grid), yard.final_height, region);
    ladder.rungs.push_back(rung);
  }
  for (LiggghtsRun& run : runs) {
    run.rung.rmse_m = surface_rmse_m(onto(run.final_height, yard_grid), yard.final_height, region);
    ladder.rungs.push_back(run.rung);
  }
  if (!runs.empty() && own_time && *own_time > 0.0) {
    ladder.liggghts_over_ground_time = runs.front().rung.wall_time_s / *own_time;
    if (runs.front().rung.cpu_time_s) ladder.liggghts_over_ground_cpu_time = *runs.front().rung.cpu_time_s / *own_time;
  }
  report(progress, 1.0, "ladder measured");
  return ladder;
}

}  // namespace repose
