#include "validation/calibration/calibration_problem.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "models/core/base/error.h"
#include "models/core/config/initial_height.h"
#include "models/core/io/npy_io.h"
#include "models/core/config/scene_loader.h"
#include "models/ground/simulate_ground.h"
#include "validation/observables/calibration_observables.h"
#include "validation/liggghts/liggghts_reference.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

HeightField read_field(const std::string& path, const Grid& grid, const std::string& what) {
  const ArrayXXdR a = read_npy_2d(path);
  if (a.rows() != grid.ny || a.cols() != grid.nx) {
    throw InputError(fmt::format("{}: {} holds {} rows x {} columns, the scene's grid is {} x {} (ny x nx)", path,
                                 what, a.rows(), a.cols(), grid.ny, grid.nx));
  }
  if (!a.allFinite()) throw InputError(fmt::format("{}: {} holds a non-finite height", path, what));
  return HeightField(grid, a);
}

// A number of a run's liggghts_manifest.json (JSON is read as YAML).
std::optional<double> manifest_number(const std::string& directory, const std::string& key) {
  const fs::path path = fs::path(directory) / "liggghts_manifest.json";
  if (!fs::exists(path)) return std::nullopt;
  try {
    const YAML::Node node = YAML::LoadFile(path.string());
    if (node[key] && node[key].IsScalar()) return node[key].as<double>();
  } catch (const YAML::Exception& e) {
    throw InputError(fmt::format("{}: cannot be read as JSON: {}", path.string(), e.what()));
  }
  return std::nullopt;
}

void set_field(Material& m, ParameterSpec::Field field, double value) {
  switch (field) {
    case ParameterSpec::Field::kAlpha: m.alpha = value; break;
    case ParameterSpec::Field::kReposeAngle: m.repose_angle_rad = value; break;
    case ParameterSpec::Field::kSigma: m.sigma = value; break;
  }
}

void load_reference(PreparedScene& s, const ProgressFn& progress) {
  const Grid& grid = s.scene.ground.grid;
  const ReferenceSpec& ref = s.entry.reference;
  if (ref.kind == ReferenceSpec::Kind::kHeuristic) {
    s.initial = make_initial_height(s.scene);
    GroundParams params = default_params(s.model);
    for (Material& m : params.materials) {
      if (!ref.material.empty() && m.name != ref.material) continue;
      if (ref.alpha) m.alpha = *ref.alpha;
      if (ref.repose_angle_rad) m.repose_angle_rad = *ref.repose_angle_rad;
      if (ref.sigma) m.sigma = *ref.sigma;
    }
    s.reference_final = simulate_ground(s.model, params, s.initial).final_height;
    return;
  }
  if (ref.kind == ReferenceSpec::Kind::kLiggghts && !fs::exists(fs::path(ref.directory) / "height_final.npy")) {
    report(progress, 0.0, fmt::format("LIGGGHTS reference of {} into {} (minutes)", s.entry.name, ref.directory));
    fs::create_directories(ref.directory);
    LiggghtsReferenceOptions options;
    run_liggghts_reference(s.scene, ref.directory, options);
  }
  s.initial = read_field((fs::path(ref.directory) / "height_initial.npy").string(), grid, "the reference's initial surface");
  s.reference_final = read_field((fs::path(ref.directory) / "height_final.npy").string(), grid, "the reference's final surface");
  s.reference_wall_time_s = manifest_number(ref.directory, "wall_time_s");
  s.reference_cpu_time_s = manifest_number(ref.directory, "cpu_time_s");
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

CalibrationProblem::CalibrationProblem(CalibrationSpec spec, const ProgressFn& progress) : spec_(std::move(spec)) {
  for (std::size_t k = 0; k < spec_.scenes.size(); ++k) {
    PreparedScene s;
    s.entry = spec_.scenes[k];
    s.scene = load_scene(s.entry.scene_path);
    if (s.entry.name.empty()) s.entry.name = s.scene.name;
    report(progress, static_cast<double>(k) / spec_.scenes.size(), "reference of " + s.entry.name);
    s.model = build_ground_model(s.scene);
    if (s.scene.dem) s.grain_diameter_m = 2.0 * s.scene.dem->grain_radius_m;
    load_reference(s, progress);
    for (const ObservableSpec& o : s.entry.observables) {
      s.reference_values.push_back(observe(o, s.initial, s.reference_final));
      s.residual_count += s.reference_values.back().size();
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
  for (std::size_t p = 0; p < spec_.parameters.size(); ++p) {
    const ParameterSpec& param = spec_.parameters[p];
    if (!param.fixed) free_.push_back(p);
    const bool used = std::any_of(scenes_.begin(), scenes_.end(), [&](const PreparedScene& s) {
      return s.fit() && std::any_of(s.model.materials.begin(), s.model.materials.end(),
                                    [&](const Material& m) { return m.name == param.material; });
    });
    if (!used) {
      throw InputError(fmt::format("{}: parameters: {} names material '{}', which no fit scene has", spec_.source_path,
                                   param.label(), param.material));
    }
  }
  if (spec_.ladder) {
    if (spec_.ladder->scene.empty()) {
      spec_.ladder->scene = std::find_if(scenes_.begin(), scenes_.end(), [](const auto& s) { return s.fit(); })->entry.name;
    }
    scene_named(spec_.ladder->scene);
  }
  report(progress, 1.0, "references loaded");
}

const PreparedScene& CalibrationProblem::scene_named(const std::string& name) const {
  for (const PreparedScene& s : scenes_) {
    if (s.entry.name == name) return s;
  }
  throw InputError(fmt::format("{}: ladder.scene: no scene named '{}'", spec_.source_path, name));
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

GroundParams CalibrationProblem::params_for(const PreparedScene& scene, const std::vector<double>& values) const {
  REPOSE_DEMAND(values.size() == spec_.parameters.size());
  GroundParams params = default_params(scene.model);
  for (std::size_t p = 0; p < values.size(); ++p) {
    for (Material& m : params.materials) {
      if (m.name == spec_.parameters[p].material) set_field(m, spec_.parameters[p].field, values[p]);
    }
  }
  return params;
}

HeightField CalibrationProblem::run(const PreparedScene& scene, const std::vector<double>& values) const {
  return simulate_ground(scene.model, params_for(scene, values), scene.initial).final_height;
}

std::vector<double> CalibrationProblem::residuals(const PreparedScene& scene, const HeightField& final_height) const {
  std::vector<double> r;
  r.reserve(scene.residual_count);
  for (std::size_t o = 0; o < scene.entry.observables.size(); ++o) {
    const ObservableSpec& spec = scene.entry.observables[o];
    const std::vector<double> values = observe(spec, scene.initial, final_height);
    const std::vector<double>& reference = scene.reference_values[o];
    REPOSE_DEMAND(values.size() == reference.size());
    const double scale = spec.weight / std::sqrt(static_cast<double>(values.size()));
    for (std::size_t k = 0; k < values.size(); ++k) r.push_back(scale * (values[k] - reference[k]));
  }
  return r;
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
  parallel_for(free_points.size() * fit.size(), spec_.solver.threads, [&](std::size_t task) {
    const std::size_t point = task / fit.size(), scene = task % fit.size();
    parts[point][scene] = residuals(*fit[scene], run(*fit[scene], values[point]));
  });
  runs_ += static_cast<long long>(free_points.size() * fit.size());
  std::vector<std::vector<double>> out(free_points.size());
  for (std::size_t p = 0; p < free_points.size(); ++p) {
    for (const auto& part : parts[p]) out[p].insert(out[p].end(), part.begin(), part.end());
  }
  return out;
}

}  // namespace repose
