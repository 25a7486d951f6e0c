#include "validation/calibration/calibration_problem.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <filesystem>
#include <map>
#include <mutex>
#include <thread>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/initial_height.h"
#include "models/core/io/npy_io.h"
#include "models/core/config/scene_loader.h"
#include "validation/calibration/calibration_parameters.h"
#include "validation/calibration/reference_cost.h"
#include "validation/observables/calibration_observables.h"
#include "validation/observables/surface_change.h"
#include "validation/particles/held_mass_series.h"
#include "validation/particles/dem_section.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

constexpr std::size_t kRunMemoryLimit = 64;  // runs remembered before the memory is emptied

}  // namespace

struct CalibrationProblem::RunMemory {
  std::mutex mutex;
  std::map<std::pair<std::string, std::vector<double>>, Run> runs;
};

HeightField read_height_field(const std::string& path, const Grid& grid, const std::string& what) {
  // the header's shape is checked before any data is read (npy_io.h)
  const NpyShape shape = read_npy_shape(path);
  if (shape.rows != static_cast<std::uint64_t>(grid.ny) || shape.cols != static_cast<std::uint64_t>(grid.nx)) {
    throw InputError(fmt::format("{}: {} holds {} rows x {} columns, the scene's grid is {} x {} (ny x nx)", path,
                                 what, shape.rows, shape.cols, grid.ny, grid.nx));
  }
  const ArrayXXdR a = read_npy_2d(path, grid.ny, grid.nx);
  if (!a.allFinite()) throw InputError(fmt::format("{}: {} holds a non-finite height", path, what));
  return HeightField(grid, a);
}

namespace {

// The scene starting from a given ground (the reference's initial surface).
Scene starting_from(Scene scene, const HeightField& initial) {
  scene.ground.initial.kind = InitialHeight::Kind::kGiven;
  scene.ground.initial.given = std::make_shared<const HeightField>(initial);
  return scene;
}

// The values of the solver's parameters, by full name (solver.parameter) in
// their units, over its defaults.
std::vector<double> named_values(const CompiledSolver& solver, const std::string& solver_name,
                                 const ReferenceSpec& ref) {
  std::vector<double> values = solver.default_values();
  for (const auto& [full, value] : ref.values) {
    const std::string prefix = solver_name + ".";
    if (!full.starts_with(prefix)) {
      throw InputError(fmt::format("{}: heuristic: {} is not a parameter of the calibrated solver {}", ref.location,
                                   full, solver_name));
    }
    try {
      const std::size_t k = solver.parameter_index(full.substr(prefix.size()));
      values[k] = value * solver.parameters()[k].si_per_unit;
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: heuristic: {}", ref.location, e.what()));
    }
  }
  return values;
}

// The reference's values of an observable: of the mean surfaces, or for a
// series, a measure or a heap's flank the mean over seeds of each seed's values.
std::vector<double> reference_values(const ObservableSpec& o, const PreparedScene& s) {
  if (!observed_per_seed(o)) return observe(o, s.initial, s.reference_final);
  REPOSE_DEMAND(s.seed_series.size() == s.seed_measures.size() && !s.seed_series.empty());
  std::vector<std::vector<double>> per_seed;
  for (std::size_t seed = 0; seed < s.seed_series.size(); ++seed) per_seed.push_back(seed_observation(o, s, seed));
  return mean_values(per_seed);
}

void load_reference(PreparedScene& s, const SolverRegistry& registry, const Solver& fitted,
                    const ProgressFn& progress) {
  const Grid& grid = s.scene.ground.grid;
  const ReferenceSpec& ref = s.entry.reference;
  if (ref.kind == ReferenceSpec::Kind::kHeuristic) {
    const auto solver = fitted.compile(s.scene);
    const Run run = solver->run(named_values(*solver, fitted.name(), ref), RunOptions{});
    s.initial = run.field("height_initial");
    s.reference_final = run.field(s.entry.field);
    s.seed_series.push_back(run.series);
    s.seed_measures.push_back(measure_values(run));
    return;
  }
  const std::string final_file = s.entry.field + ".npy";
  if (ref.kind == ReferenceSpec::Kind::kLiggghts && !fs::exists(fs::path(ref.directories.front()) / final_file)) {
    const std::string& dir = ref.directories.front();
    report(progress, 0.0, fmt::format("LIGGGHTS reference of {} into {} (minutes)", s.entry.name, dir));
    fs::create_directories(dir);
    const auto liggghts = registry.get("liggghts").compile(s.scene);
    liggghts->run(liggghts->default_values(), RunOptions{progress, dir});
  }
  double wall_s = 0.0, cpu_s = 0.0;
  bool costed = true;
  for (const std::string& dir : ref.directories) {
    s.seed_initial.push_back(read_height_field((fs::path(dir) / "height_initial.npy").string(), grid, "the reference's initial surface"));
    s.seed_final.push_back(read_height_field((fs::path(dir) / final_file).string(), grid, "the reference's final surface"));
    s.seed_series.push_back(read_reference_series(dir));
    s.seed_measures.push_back(read_run_measures(dir));
    const auto cost = read_run_cost(dir);
    costed = costed && cost.has_value();
    if (cost) {
      wall_s += cost->wall_s / static_cast<double>(ref.directories.size());
      cpu_s += cost->cpu_s / static_cast<double>(ref.directories.size());
    }
  }
  s.initial = mean_field(s.seed_initial);
  s.reference_final = mean_field(s.seed_final);
  if (costed) {
    s.reference_wall_time_s = wall_s;
    s.reference_cpu_time_s = cpu_s;
  }
}

// The grid of the scene entry's own cells (cell_size_m; default the scene
// file's): coarser ones only, that divide the scene's extent.
Grid entry_grid(const CalibrationScene& entry, const Grid& file_grid) {
  if (!entry.cell_size_m) return file_grid;
  const double h = *entry.cell_size_m;
  const auto grid = file_grid.with_cell_size(h);
  if (!grid || h < file_grid.cell_size_m * (1.0 - 1e-9)) {
    throw InputError(fmt::format("{}: cell_size_m: {} m is not a cell size the reference's surfaces can be averaged "
                                 "onto: give one at least the scene's {} m that divides its extent {} x {} m",
                                 entry.cell_size_location, h, file_grid.cell_size_m, file_grid.extent_x_m(),
                                 file_grid.extent_y_m()));
  }
  return *grid;
}

// The reference's surfaces, read on the scene file's grid, averaged onto the solver's.
void onto_solver_grid(PreparedScene& s, const Grid& grid) {
  if (grid == s.scene.ground.grid) return;
  auto onto = [&](HeightField& f) { f = resample_conservative(f, grid); };
  for (HeightField& f : s.seed_initial) onto(f);
  for (HeightField& f : s.seed_final) onto(f);
  onto(s.initial);
  onto(s.reference_final);
  s.scene.ground.grid = grid;
}

// Runs task(k) for k in [0, count) on up to `threads` threads; the first
// exception is rethrown here.
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t)>& task) {
  const std::size_t workers = std::min<std::size_t>(static_cast<std::size_t>(std::max(threads, 1)), count);
  if (workers <= 1) {
    for (std::size_t k = 0; k < count; ++k) task(k);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&] {
    for (std::size_t k = next++; k < count; k = next++) {
      try {
        task(k);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace

bool observed_per_seed(const ObservableSpec& o) {
  using K = ObservableSpec::Kind;
  return o.kind == K::kSeries || o.kind == K::kMeasure || o.kind == K::kHeapFlank;
}

SeriesByName read_reference_series(const std::string& dir) {
  SeriesByName out;
  const fs::path path = fs::path(dir) / "held_mass.csv";
  if (!fs::exists(path)) return out;
  for (auto& [object, track] : read_held_mass_csv(path.string())) {
    out["mass_held_kg." + object] = TimeSeries{"kg", std::move(track.time_s), std::move(track.mass_kg)};
  }
  return out;
}

std::vector<double> seed_observation(const ObservableSpec& o, const PreparedScene& s, std::size_t seed) {
  REPOSE_DEMAND(seed < s.seed_series.size() && seed < s.seed_measures.size());
  // a data reference keeps each seed's surfaces; a heuristic one only its mean
  const bool own = seed < s.seed_final.size() && seed < s.seed_initial.size();
  return observe(o, own ? s.seed_initial[seed] : s.initial, own ? s.seed_final[seed] : s.reference_final,
                 s.seed_series[seed], s.seed_measures[seed]);
}

std::vector<double> mean_values(const std::vector<std::vector<double>>& lists) {
  REPOSE_DEMAND(!lists.empty());
  std::vector<double> mean(lists.front().size(), 0.0);
  for (const std::vector<double>& v : lists) {
    REPOSE_DEMAND(v.size() == mean.size());
    for (std::size_t k = 0; k < v.size(); ++k) mean[k] += v[k] / static_cast<double>(lists.size());
  }
  return mean;
}

MeasureByName measure_values(const Run& run) {
  MeasureByName out;
  for (const auto& [name, measure] : run.measures) out[name] = measure.value;
  return out;
}

CalibrationProblem::CalibrationProblem(CalibrationSpec spec, const SolverRegistry& registry, const ProgressFn& progress)
    : spec_(std::move(spec)), registry_(&registry), solver_(registry.find(spec_.fitted_solver)),
      memory_(std::make_shared<RunMemory>()) {
  if (solver_ == nullptr) {
    throw InputError(fmt::format("{}: parameters: {} names an unknown solver '{}' (known: {})",
                                 spec_.parameters.front().location, spec_.parameters.front().label(),
                                 spec_.fitted_solver, fmt::join(registry.names(), ", ")));
  }
  for (std::size_t k = 0; k < spec_.scenes.size(); ++k) {
    PreparedScene s;
    s.entry = spec_.scenes[k];
    s.scene = load_scene(s.entry.scene_path, registry.sections());
    if (s.entry.seed) s.scene.seed = *s.entry.seed;
    if (s.entry.name.empty()) s.entry.name = s.scene.name;
    report(progress, static_cast<double>(k) / spec_.scenes.size(), "reference of " + s.entry.name);
    if (const DemSpec* dem = dem_of(s.scene)) s.grain_diameter_m = 2.0 * dem->grain_radius_m;
    s.reference_cell_size_m = s.scene.ground.grid.cell_size_m;
    const Grid solver_grid = entry_grid(s.entry, s.scene.ground.grid);  // refused before any reference is run
    try {
      load_reference(s, registry, *solver_, progress);
    } catch (const InputError& e) {
      // name the calibration file's line too: the reference it points at is the one to fix
      throw InputError(fmt::format("{}: reference: {}", s.entry.reference.location, e.what()));
    }
    onto_solver_grid(s, solver_grid);
    if (s.entry.beds == CalibrationScene::Beds::kEach) {
      for (const HeightField& bed : s.seed_initial) s.bed_solvers.push_back(solver_->compile(starting_from(s.scene, bed)));
    }
    s.scene = starting_from(std::move(s.scene), s.initial);
    s.solver = solver_->compile(s.scene);
    try {
      for (const ObservableSpec& o : s.entry.observables) {
        s.reference_values.push_back(reference_values(o, s));
        s.residual_count += s.reference_values.back().size();
      }
    } catch (const InputError& e) {
      throw InputError(fmt::format("{}: reference: {}", s.entry.reference.location, e.what()));
    }
    cells_in(s.entry.rmse_region, s.scene.ground.grid);  // a region without cells is refused now
    if (s.fit()) fit_residual_count_ += s.residual_count;
    for (const PreparedScene& other : scenes_) {
      if (other.entry.name == s.entry.name) {
        throw InputError(fmt::format("{}: two scenes named '{}': give one a name", spec_.source_path, s.entry.name));
      }
    }
    scenes_.push_back(std::move(s));
  }
  resolve_parameters();
  if (spec_.ladder) {
    if (spec_.ladder->scene.empty()) {
      spec_.ladder->scene = std::find_if(scenes_.begin(), scenes_.end(), [](const auto& s) { return s.fit(); })->entry.name;
    }
    scene_named(spec_.ladder->scene);
  }
  report(progress, 1.0, "references loaded");
}

void CalibrationProblem::resolve_parameters() {
  for (std::size_t p = 0; p < spec_.parameters.size(); ++p) {
    ParameterSpec& param = spec_.parameters[p];
    if (!param.fixed) free_.push_back(p);
    const ParameterInfo* info = nullptr;
    for (PreparedScene& s : scenes_) {
      const auto& list = s.solver->parameters();
      const auto it = std::find_if(list.begin(), list.end(), [&](const ParameterInfo& i) { return i.name == param.name; });
      s.parameter_index.push_back(it == list.end() ? -1 : static_cast<int>(it - list.begin()));
      if (it != list.end() && s.fit() && info == nullptr) info = &*it;
    }
    if (info == nullptr) {
      throw InputError(fmt::format("{}: parameters: {}: no fit scene has this parameter of solver {}",
                                   param.location, param.label(), param.solver));
    }
    resolve_parameter(param, *info);
  }
}

const PreparedScene& CalibrationProblem::scene_named(const std::string& name) const {
  for (const PreparedScene& s : scenes_) {
    if (s.entry.name == name) return s;
  }
  throw InputError(fmt::format("{}: ladder.scene: no scene named '{}'", spec_.source_path, name));
}

CalibrationProblem CalibrationProblem::holding_out(const std::string& name) const {
  CalibrationProblem held = *this;
  held.fit_residual_count_ = 0;
  bool found = false;
  for (PreparedScene& s : held.scenes_) {
    if (s.entry.name == name) {
      s.entry.role = CalibrationScene::Role::kHeldOut;
      found = true;
    }
    if (s.fit()) held.fit_residual_count_ += s.residual_count;
  }
  REPOSE_DEMAND(found && held.fit_residual_count_ > 0);
  held.runs_ = 0;
  return held;
}

std::optional<std::size_t> CalibrationProblem::free_index(std::size_t p) const {
  for (std::size_t k = 0; k < free_.size(); ++k) {
    if (free_[k] == p) return k;
  }
  return std::nullopt;
}

std::vector<double> CalibrationProblem::initial_values() const {
  std::vector<double> values;
  for (const ParameterSpec& p : spec_.parameters) values.push_back(p.initial);
  return values;
}

std::vector<double> CalibrationProblem::with_free(const std::vector<double>& free_values) const {
  REPOSE_DEMAND(free_values.size() == free_.size());
  std::vector<double> values = initial_values();
  for (std::size_t k = 0; k < free_.size(); ++k) values[free_[k]] = free_values[k];
  return values;
}

std::vector<double> CalibrationProblem::free_of(const std::vector<double>& values) const {
  std::vector<double> out;
  for (const std::size_t p : free_) out.push_back(values[p]);
  return out;
}

std::vector<double> CalibrationProblem::solver_values(const PreparedScene& scene, const std::vector<double>& values) const {
  REPOSE_DEMAND(values.size() == spec_.parameters.size());
  std::vector<double> solver_values = scene.solver->default_values();
  for (std::size_t p = 0; p < values.size(); ++p) {
    if (scene.parameter_index[p] >= 0) solver_values[static_cast<std::size_t>(scene.parameter_index[p])] = values[p];
  }
  return solver_values;
}

Run CalibrationProblem::run_on_bed(const PreparedScene& scene, const std::vector<double>& values, std::size_t bed) const {
  REPOSE_DEMAND(bed < scene.bed_count());
  // the scene file, its bed and its reference folders fix the scene the solver was compiled for
  std::string key = scene.entry.scene_path + "\nseed " + std::to_string(scene.scene.seed);
  for (const std::string& dir : scene.entry.reference.directories) key += "\n" + dir;
  if (!scene.bed_solvers.empty()) key += "\nbed " + std::to_string(bed);
  const std::vector<double> solver_in = solver_values(scene, values);
  const auto id = std::make_pair(key, solver_in);
  {
    std::lock_guard lock(memory_->mutex);
    const auto it = memory_->runs.find(id);
    if (it != memory_->runs.end()) return it->second;
  }
  const CompiledSolver& solver = scene.bed_solvers.empty() ? *scene.solver : *scene.bed_solvers[bed];
  Run run = solver.run(solver_in, RunOptions{});
  std::lock_guard lock(memory_->mutex);
  if (memory_->runs.size() >= kRunMemoryLimit) memory_->runs.clear();
  memory_->runs[id] = run;
  return run;
}

std::vector<Run> CalibrationProblem::runs(const PreparedScene& scene, const std::vector<double>& values) const {
  std::vector<Run> out;
  for (std::size_t bed = 0; bed < scene.bed_count(); ++bed) out.push_back(run_on_bed(scene, values, bed));
  return out;
}

HeightField CalibrationProblem::mean_final(const PreparedScene& scene, const std::vector<Run>& runs) const {
  REPOSE_DEMAND(runs.size() == scene.bed_count());
  std::vector<HeightField> fields;
  for (const Run& run : runs) fields.push_back(run.field(scene.entry.field));
  return fields.size() == 1 ? fields.front() : mean_field(fields);
}

std::vector<std::vector<std::vector<double>>> CalibrationProblem::observed_per_bed(const PreparedScene& scene,
                                                                                  const std::vector<Run>& runs) const {
  REPOSE_DEMAND(runs.size() == scene.bed_count());
  std::vector<std::vector<std::vector<double>>> out;
  for (const ObservableSpec& o : scene.entry.observables) {
    std::vector<std::vector<double>> per_bed;
    for (std::size_t bed = 0; bed < runs.size(); ++bed) {
      const Run& run = runs[bed];
      per_bed.push_back(observe(o, scene.bed_initial(bed), run.field(scene.entry.field), run.series, measure_values(run)));
    }
    out.push_back(std::move(per_bed));
  }
  return out;
}

std::vector<std::vector<double>> CalibrationProblem::mean_over_beds(
    const std::vector<std::vector<std::vector<double>>>& per_bed) {
  std::vector<std::vector<double>> out;
  for (const std::vector<std::vector<double>>& values : per_bed) out.push_back(mean_values(values));
  return out;
}

std::vector<std::vector<double>> CalibrationProblem::observed(const PreparedScene& scene, const std::vector<Run>& runs) const {
  return mean_over_beds(observed_per_bed(scene, runs));
}

std::vector<double> CalibrationProblem::weighted_residuals(const PreparedScene& scene,
                                                           const std::vector<std::vector<double>>& observed) const {
  REPOSE_DEMAND(observed.size() == scene.entry.observables.size());
  std::vector<double> r;
  r.reserve(scene.residual_count);
  for (std::size_t o = 0; o < observed.size(); ++o) {
    const std::vector<double>& values = observed[o];
    const std::vector<double>& reference = scene.reference_values[o];
    REPOSE_DEMAND(values.size() == reference.size());
    const double scale = scene.entry.observables[o].weight / std::sqrt(static_cast<double>(values.size()));
    for (std::size_t k = 0; k < values.size(); ++k) r.push_back(scale * (values[k] - reference[k]));
  }
  return r;
}

std::vector<double> CalibrationProblem::residuals(const PreparedScene& scene, const std::vector<Run>& runs) const {
  return weighted_residuals(scene, observed(scene, runs));
}

std::vector<double> CalibrationProblem::residuals(const PreparedScene& scene, const HeightField& final_height,
                                                  const SeriesByName& series, const MeasureByName& measures) const {
  std::vector<std::vector<double>> values;
  for (const ObservableSpec& o : scene.entry.observables) values.push_back(observe(o, scene.initial, final_height, series, measures));
  return weighted_residuals(scene, values);
}

std::vector<std::vector<double>> CalibrationProblem::fit_residuals(const std::vector<std::vector<double>>& free_points) const {
  std::vector<const PreparedScene*> fit;
  for (const PreparedScene& s : scenes_) {
    if (s.fit()) fit.push_back(&s);
  }
  // one task per (point, scene): each writes its own slot
  std::vector<std::vector<std::vector<double>>> parts(free_points.size(), std::vector<std::vector<double>>(fit.size()));
  std::vector<std::vector<double>> values;
  for (const auto& point : free_points) values.push_back(with_free(point));
  const int threads = solver_->thread_safe() ? spec_.solver.threads : 1;
  parallel_for(free_points.size() * fit.size(), threads, [&](std::size_t task) {
    const std::size_t point = task / fit.size(), scene = task % fit.size();
    parts[point][scene] = residuals(*fit[scene], runs(*fit[scene], values[point]));
  });
  runs_ += static_cast<long long>(free_points.size() * fit.size());
  std::vector<std::vector<double>> out(free_points.size());
  for (std::size_t p = 0; p < free_points.size(); ++p) {
    for (const auto& part : parts[p]) out[p].insert(out[p].end(), part.begin(), part.end());
  }
  return out;
}

}  // namespace repose
