#include "validation/liggghts_debris/liggghts_debris_run.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/liggghts/liggghts_dump.h"
#include "validation/liggghts_debris/liggghts_debris_script.h"

namespace repose {

namespace fs = std::filesystem;

void read_debris_forces(const std::string& path, double time_step_s, const std::vector<int>& part_building,
                        DebrisRunResult& r) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot read the building forces", path));
  const std::size_t parts = part_building.size();
  r.force_time_s.clear();
  for (BuildingOutcome& b : r.buildings) b.force_n.clear();
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream row(line);
    double step = 0.0;
    std::vector<double> v(3 * parts);
    row >> step;
    for (double& x : v) row >> x;
    if (!row || !std::isfinite(step)) {
      throw InputError(fmt::format("{}:{}: expected a step and {} finite forces", path, number, 3 * parts));
    }
    r.force_time_s.push_back(step * time_step_s);
    std::vector<Eigen::Vector3d> sum(r.buildings.size(), Eigen::Vector3d::Zero());
    for (std::size_t p = 0; p < parts; ++p) {
      sum.at(static_cast<std::size_t>(part_building[p])) += Eigen::Vector3d(v[3 * p], v[3 * p + 1], v[3 * p + 2]);
    }
    for (std::size_t b = 0; b < sum.size(); ++b) r.buildings[b].force_n.push_back(sum[b].norm());
  }
}

namespace {

std::vector<BuildingOutcome> fixed_buildings(const DebrisSetup& setup) {
  std::vector<BuildingOutcome> out;
  for (const std::string& name : setup.building_names) out.emplace_back().name = name;
  for (const DebrisPart& p : setup.spec.parts) out.at(static_cast<std::size_t>(p.building)).parts += 1;
  for (int b : setup.joint_building) out.at(static_cast<std::size_t>(b)).joints += 1;
  return out;
}

// One dump as a frame: every element there, in id order.
DebrisFrame dump_frame(const std::string& path, const DebrisSetup& setup, double dt, double quantile) {
  DumpFrame d = read_last_dump_frame(path);
  const auto n = static_cast<Eigen::Index>(setup.spec.elements.size());
  if (d.grains.size() != n || d.grains.velocity_m_s.rows() != n) {
    throw InputError(fmt::format("{}: {} atoms with velocities, expected the {} elements", path, d.grains.size(), n));
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    if (d.id[static_cast<std::size_t>(i)] != i + 1) throw InputError(fmt::format("{}: atoms not sorted by id", path));
  }
  std::vector<Pose> parts;
  for (const DebrisPart& p : setup.spec.parts) parts.push_back({p.centre_m, Eigen::Quaterniond::Identity()});
  return debris_frame(static_cast<double>(d.timestep) * dt, std::move(d.grains), std::move(parts), 0, setup, quantile);
}

}  // namespace

LiggghtsDebrisResult run_liggghts_debris(const DebrisSetup& setup, double duration_s,
                                         const LiggghtsDebrisOptions& options, const std::string& run_dir,
                                         LiggghtsRunOptions run_options) {
  const LiggghtsDebrisScript script = liggghts_debris_script(setup, duration_s, options);
  fs::create_directories(run_dir);
  write_liggghts_debris_inputs(script, run_dir);
  run_options.total_steps = script.total_steps;
  run_options.dump_directory = kDebrisDumpDirectory;
  const LiggghtsRunSummary summary = run_liggghts(run_dir, kDebrisScriptFile, run_options);

  LiggghtsDebrisResult out;
  out.version = summary.version;
  DebrisRunResult& r = out.run;
  for (const std::string& path : list_dump_files((fs::path(run_dir) / kDebrisDumpDirectory).string())) {
    r.frames.push_back(dump_frame(path, setup, options.time_step_s, options.front_quantile));
  }
  if (r.frames.empty()) throw InputError(fmt::format("{}: the run wrote no dumps", run_dir));
  r.buildings = fixed_buildings(setup);
  if (!setup.spec.parts.empty()) {
    std::vector<int> part_building;
    for (const DebrisPart& p : setup.spec.parts) part_building.push_back(p.building);
    read_debris_forces((fs::path(run_dir) / kDebrisForceFile).string(), options.time_step_s, part_building, r);
  }
  r.steps = script.total_steps;
  r.simulated_s = static_cast<double>(script.total_steps) * options.time_step_s;
  r.cpu_time_s = summary.cpu_time_s;
  r.wall_time_s = summary.wall_time_s;
  finish_debris_result(setup, SurfaceHeightOptions{}, r);
  return out;
}

}  // namespace repose
