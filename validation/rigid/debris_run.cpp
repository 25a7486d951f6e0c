#include "validation/rigid/debris_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "models/core/base/error.h"
#include "models/core/io/height_field_io.h"
#include "models/core/io/mesh_io.h"
#include "models/core/io/npy_io.h"
#include "models/terrain/terrain_surface.h"
#include "validation/rigid/rigid_simulation.h"

namespace repose {

void DebrisRunOptions::validate() const {
  if (!(frame_interval_s >= 0.0 && std::isfinite(frame_interval_s))) {
    throw InputError(fmt::format("debris: frame_interval_s = {} must be >= 0", frame_interval_s));
  }
  if (!(moved_threshold_m > 0.0 && std::isfinite(moved_threshold_m))) {
    throw InputError(fmt::format("debris: moved_threshold_m = {} must be > 0", moved_threshold_m));
  }
  if (!(front_quantile > 0.0 && front_quantile <= 1.0)) {
    throw InputError(fmt::format("debris: front_quantile = {} must lie in (0, 1]", front_quantile));
  }
  if (!(force_interval_s > 0.0 && std::isfinite(force_interval_s))) {
    throw InputError(fmt::format("debris: force_interval_s = {} must be > 0", force_interval_s));
  }
}

double debris_front_m(const GrainSet& elements, const Eigen::Vector2d& centre_m, const Eigen::Vector2d& direction,
                      double quantile) {
  if (elements.size() == 0) return 0.0;
  std::vector<double> along(static_cast<std::size_t>(elements.size()));
  for (Eigen::Index i = 0; i < elements.size(); ++i) {
    const Eigen::Vector2d p(elements.position_m(i, 0), elements.position_m(i, 1));
    along[static_cast<std::size_t>(i)] = (p - centre_m).dot(direction);
  }
  const auto k = static_cast<std::size_t>(std::ceil(quantile * static_cast<double>(along.size()))) - 1;
  std::nth_element(along.begin(), along.begin() + static_cast<std::ptrdiff_t>(k), along.end());
  return along[k];
}

DebrisFrame debris_frame(double t, GrainSet elements, std::vector<Pose> parts, int joints_broken,
                         const DebrisSetup& setup, double quantile) {
  DebrisFrame f;
  f.time_s = t;
  f.elements = std::move(elements);
  f.parts = std::move(parts);
  f.joints_broken = joints_broken;
  f.front_m = debris_front_m(f.elements, setup.source_centre_m, setup.flow_direction, quantile);
  f.mean_speed_m_s = f.elements.size() > 0 ? f.elements.velocity_m_s.rowwise().norm().mean() : 0.0;
  for (Eigen::Index i = 0; i < f.elements.size(); ++i) {
    if (!f.elements.position_m.row(i).allFinite()) {
      throw std::runtime_error(fmt::format("debris: element {} left the world (non-finite) at t = {} s", i, t));
    }
  }
  return f;
}

namespace {

DebrisFrame make_frame(const DebrisWorld& world, const DebrisSetup& setup, double t, double quantile) {
  int broken = 0;
  for (bool b : world.joints_broken()) broken += b ? 1 : 0;
  return debris_frame(t, world.elements(), world.part_poses(), broken, setup, quantile);
}

void set_front_speeds(std::vector<DebrisFrame>& frames) {
  const std::size_t n = frames.size();
  for (std::size_t k = 0; k < n && n > 1; ++k) {
    const std::size_t a = k == 0 ? 0 : k - 1, b = k + 1 == n ? k : k + 1;
    frames[k].front_speed_m_s = (frames[b].front_m - frames[a].front_m) / (frames[b].time_s - frames[a].time_s);
  }
}

std::vector<BuildingOutcome> building_outcomes(const DebrisSetup& setup, const DebrisWorld& world,
                                               const std::vector<double>& static_force_n, double moved_m) {
  std::vector<BuildingOutcome> out;
  for (const std::string& name : setup.building_names) out.emplace_back().name = name;
  const std::vector<Pose> poses = world.part_poses();
  for (std::size_t p = 0; p < setup.spec.parts.size(); ++p) {
    BuildingOutcome& b = out.at(static_cast<std::size_t>(setup.spec.parts[p].building));
    const double d = (poses[p].position_m - setup.spec.parts[p].centre_m).norm();
    b.parts += 1;
    b.parts_moved += d > moved_m ? 1 : 0;
    b.max_displacement_m = std::max(b.max_displacement_m, d);
  }
  const std::vector<bool> broken = world.joints_broken();
  for (std::size_t j = 0; j < broken.size(); ++j) {
    BuildingOutcome& b = out.at(static_cast<std::size_t>(setup.joint_building[j]));
    b.joints += 1;
    b.joints_broken += broken[j] ? 1 : 0;
    b.static_joint_force_n = std::max(b.static_joint_force_n, static_force_n[j]);
  }
  return out;
}

// The elements' force on each building, binned (debris_run.h).
class BuildingForces {
 public:
  BuildingForces(const DebrisSetup& setup, double dt) : setup_(setup), dt_(dt), impulse_(setup.building_names.size()) {
    for (auto& i : impulse_) i.setZero();
    force_n_.resize(setup.building_names.size());
  }
  void add_step(const std::vector<Eigen::Vector3d>& part_force_n) {
    for (std::size_t p = 0; p < part_force_n.size(); ++p) {
      impulse_.at(static_cast<std::size_t>(setup_.spec.parts.at(p).building)) += part_force_n[p] * dt_;
    }
    ++steps_in_bin_;
  }
  void close_bin(double t) {
    if (steps_in_bin_ == 0) return;
    time_s_.push_back(t);
    for (std::size_t b = 0; b < impulse_.size(); ++b) {
      force_n_[b].push_back(impulse_[b].norm() / (steps_in_bin_ * dt_));
      impulse_[b].setZero();
    }
    steps_in_bin_ = 0;
  }
  void store(DebrisRunResult& r) const {
    r.force_time_s = time_s_;
    for (std::size_t b = 0; b < r.buildings.size(); ++b) r.buildings[b].force_n = force_n_[b];
  }

 private:
  const DebrisSetup& setup_;
  double dt_;
  std::vector<Eigen::Vector3d> impulse_;  // per building, of the open bin
  long steps_in_bin_ = 0;
  std::vector<double> time_s_;
  std::vector<std::vector<double>> force_n_;
};

// On a grid `refine` times finer than the ground's (cells at most half the
// smallest element's radius, at most 8 times finer), then averaged back.
HeightField deposit_depth(const GrainSet& elements, const DebrisSetup& setup, const SurfaceHeightOptions& options) {
  const Grid& coarse = setup.scenery.terrain.height_field.grid();
  const double r_min = elements.size() > 0 ? elements.radius_m.minCoeff() : coarse.cell_size_m;
  const int refine = std::clamp(static_cast<int>(std::ceil(coarse.cell_size_m / (0.5 * r_min))), 1, 8);
  const Grid fine{coarse.nx * refine, coarse.ny * refine, coarse.cell_size_m / refine, coarse.origin_x_m, coarse.origin_y_m};
  const HeightField ground = sample_height_field(TerrainSurface(setup.spec.terrain), fine, setup.spec.plain_height_m);
  HeightField top = surface_height(elements, fine, options);
  top.heights() = (top.heights() - ground.heights()).max(0.0);
  return resample_conservative(top, coarse);
}

}  // namespace

DebrisRunResult run_debris(DebrisWorld& world, const DebrisSetup& setup, double duration_s,
                           const DebrisRunOptions& options) {
  options.validate();
  const double dt = world.time_step_s();
  const long steps = static_cast<long>(std::ceil(duration_s / dt - 1e-9));
  const double interval = options.frame_interval_s > 0.0 ? options.frame_interval_s : duration_s / 20.0;
  const long every = std::max(1L, std::lround(interval / dt));
  const long force_every = std::max(1L, std::lround(options.force_interval_s / dt));
  BuildingForces forces(setup, dt);
  DebrisRunResult r;
  const auto wall0 = std::chrono::steady_clock::now();
  const double cpu0 = process_cpu_time_s();
  r.frames.push_back(make_frame(world, setup, 0.0, options.front_quantile));
  std::vector<double> static_force_n;
  for (long s = 1; s <= steps; ++s) {
    world.step();
    if (s == 1) static_force_n = world.joint_forces_n();
    forces.add_step(world.part_element_forces_n());
    if (s % force_every == 0 || s == steps) forces.close_bin(s * dt);
    if (s % every == 0 || s == steps) r.frames.push_back(make_frame(world, setup, s * dt, options.front_quantile));
  }
  r.cpu_time_s = process_cpu_time_s() - cpu0;
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  r.steps = steps;
  r.simulated_s = steps * dt;
  static_force_n.resize(setup.spec.joints.size(), 0.0);
  r.buildings = building_outcomes(setup, world, static_force_n, options.moved_threshold_m);
  forces.store(r);
  finish_debris_result(setup, options.surface, r);
  return r;
}

void finish_debris_result(const DebrisSetup& setup, const SurfaceHeightOptions& surface, DebrisRunResult& r) {
  REPOSE_DEMAND(!r.frames.empty());
  set_front_speeds(r.frames);
  r.runout_m = r.frames.back().front_m - r.frames.front().front_m;
  r.peak_front_speed_m_s = 0.0;
  for (const DebrisFrame& f : r.frames) r.peak_front_speed_m_s = std::max(r.peak_front_speed_m_s, f.front_speed_m_s);
  r.deposit = deposit_depth(r.frames.back().elements, setup, surface);
  for (BuildingOutcome& o : r.buildings) {
    REPOSE_DEMAND(o.force_n.size() == r.force_time_s.size());
    o.peak_force_n = o.impulse_n_s = 0.0;
    for (std::size_t k = 0; k < r.force_time_s.size(); ++k) {
      o.peak_force_n = std::max(o.peak_force_n, o.force_n[k]);
      o.impulse_n_s += o.force_n[k] * (r.force_time_s[k] - (k == 0 ? 0.0 : r.force_time_s[k - 1]));
    }
  }
}

namespace {

ArrayXXdR elements_array(const GrainSet& g) {
  ArrayXXdR a(g.size(), 4);
  a.leftCols(3) = g.position_m.array();
  a.col(3) = g.radius_m.array();
  return a;
}

ArrayXXdR parts_array(const std::vector<Pose>& parts) {
  ArrayXXdR a(static_cast<Eigen::Index>(parts.size()), 7);
  for (std::size_t p = 0; p < parts.size(); ++p) {
    const Pose& q = parts[p];
    a.row(static_cast<Eigen::Index>(p)) << q.position_m.x(), q.position_m.y(), q.position_m.z(), q.orientation.w(),
        q.orientation.x(), q.orientation.y(), q.orientation.z();
  }
  return a;
}

void write_building_forces_csv(const std::string& path, const DebrisRunResult& r) {
  std::ofstream out(path);
  out << "time_s";
  for (const BuildingOutcome& b : r.buildings) out << "," << b.name;
  out << "\n";
  for (std::size_t k = 0; k < r.force_time_s.size(); ++k) {
    out << fmt::format("{:.6g}", r.force_time_s[k]);
    for (const BuildingOutcome& b : r.buildings) out << fmt::format(",{:.9g}", b.force_n[k]);
    out << "\n";
  }
}

void write_parts_json(const std::string& path, const DebrisSetup& setup) {
  nlohmann::json parts = nlohmann::json::array();
  for (const DebrisPart& p : setup.spec.parts) {
    nlohmann::json hull = nlohmann::json::array();
    for (Eigen::Index v = 0; v < p.hull_m.rows(); ++v) hull.push_back({p.hull_m(v, 0), p.hull_m(v, 1), p.hull_m(v, 2)});
    parts.push_back({{"building", p.building}, {"mass_kg", p.mass_kg}, {"hull_m", hull}});
  }
  std::ofstream(path) << nlohmann::json{{"buildings", setup.building_names}, {"parts", parts}}.dump(1) << "\n";
}

}  // namespace

std::vector<std::string> write_debris_run(const DebrisRunResult& r, const DebrisSetup& setup, const std::string& dir) {
  namespace fs = std::filesystem;
  std::vector<std::string> files = {"terrain.obj", "front.csv", "buildings.csv", "building_forces.csv", "deposit.npy",
                                    "parts.json"};
  write_obj((fs::path(dir) / "terrain.obj").string(), setup.spec.terrain);
  std::ofstream front(fs::path(dir) / "front.csv");
  front << "time_s,front_m,front_speed_m_s,mean_speed_m_s,joints_broken\n";
  for (const DebrisFrame& f : r.frames) {
    front << fmt::format("{:.6g},{:.9g},{:.9g},{:.9g},{}\n", f.time_s, f.front_m, f.front_speed_m_s, f.mean_speed_m_s,
                         f.joints_broken);
  }
  std::ofstream buildings(fs::path(dir) / "buildings.csv");
  buildings << "building,parts,parts_moved,max_displacement_m,joints,joints_broken,static_joint_force_n,peak_force_n,"
               "impulse_n_s\n";
  for (const BuildingOutcome& b : r.buildings) {
    buildings << fmt::format("\"{}\",{},{},{:.9g},{},{},{:.9g},{:.9g},{:.9g}\n", b.name, b.parts, b.parts_moved,
                             b.max_displacement_m, b.joints, b.joints_broken, b.static_joint_force_n, b.peak_force_n,
                             b.impulse_n_s);
  }
  write_building_forces_csv((fs::path(dir) / "building_forces.csv").string(), r);
  write_height_field_npy((fs::path(dir) / "deposit.npy").string(), r.deposit);
  write_parts_json((fs::path(dir) / "parts.json").string(), setup);
  fs::create_directories(fs::path(dir) / "frames");
  for (std::size_t k = 0; k < r.frames.size(); ++k) {
    const std::string e = fmt::format("frames/elements_{:03d}.npy", k), p = fmt::format("frames/parts_{:03d}.npy", k);
    write_npy_2d((fs::path(dir) / e).string(), elements_array(r.frames[k].elements));
    write_npy_2d((fs::path(dir) / p).string(), parts_array(r.frames[k].parts));
    files.push_back(e);
    files.push_back(p);
  }
  return files;
}

}  // namespace repose
