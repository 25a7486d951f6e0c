#include "validation/liggghts/liggghts_bed.h"

#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "models/core/base/error.h"
#include "models/core/base/sha256.h"
#include "validation/liggghts/liggghts_dump.h"

namespace repose {

namespace fs = std::filesystem;

namespace {

constexpr const char* kScriptFile = "bed.in";
constexpr const char* kManifestFile = "manifest.json";

bool complete_entry(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / kBedRestartFile, ec) && fs::is_regular_file(dir / kBedDumpFile, ec) &&
         fs::is_regular_file(dir / kManifestFile, ec);
}

fs::path fresh_temporary(const fs::path& beds, const std::string& key) {
  static std::atomic<int> counter{0};
  for (;;) {
    const fs::path p = beds / fmt::format(".tmp-{}-{}-{}", key.substr(0, 16), ::getpid(), counter++);
    if (fs::create_directory(p)) return p;
  }
}

// The settled grains must all be there and inside the box.
long check_settled(const fs::path& dir, const Scene& scene, const BedScriptOptions& o) {
  const std::string log = (dir / "log.liggghts").string();
  DumpFrame frame;
  try {
    frame = read_last_dump_frame((dir / kBedDumpFile).string());
  } catch (const InputError& e) {
    throw LiggghtsRunError(dir.string(), log, fmt::format("bad bed dump: {}", e.what()));
  }
  const long wanted = bed_grain_count(scene, o);
  if (frame.grains.size() != wanted) {
    throw LiggghtsRunError(dir.string(), log,
                           fmt::format("inserted {} grains of the {} asked (insertion region too dense?)",
                                       frame.grains.size(), wanted));
  }
  const DemDomain d = bed_domain(scene, o);
  for (Eigen::Index g = 0; g < frame.grains.size(); ++g) {
    const auto p = frame.grains.position_m.row(g);
    if (p.x() < d.x_min_m || p.x() > d.x_max_m || p.y() < d.y_min_m || p.y() > d.y_max_m || p.z() < d.z_min_m ||
        p.z() > d.z_max_m) {
      throw LiggghtsRunError(dir.string(), log,
                             fmt::format("grain {} at ({}, {}, {}) lies outside the box", frame.id[g], p.x(), p.y(), p.z()));
    }
  }
  return static_cast<long>(frame.grains.size());
}

void write_manifest(const fs::path& path, const SettledBed& bed, const Scene& scene) {
  const DemSpec& dem = *dem_of(scene);
  const double particle_steps = static_cast<double>(bed.grain_count) * static_cast<double>(bed.steps);
  const nlohmann::json json = {
      {"kind", "settled bed"},
      {"liggghts_version", bed.liggghts_version},
      {"script_sha256", sha256_hex_of_file((path.parent_path() / kScriptFile).string())},
      {"cache_key", bed.key},
      {"grain_count", bed.grain_count},
      {"steps", bed.steps},
      {"wall_time_s", bed.wall_time_s},
      {"cpu_time_s", bed.cpu_time_s},
      {"particle_steps_per_s", bed.wall_time_s > 0 ? particle_steps / bed.wall_time_s : 0.0},
      {"particle_steps_per_cpu_s", bed.cpu_time_s > 0 ? particle_steps / bed.cpu_time_s : 0.0},
      {"youngs_modulus_pa", dem.youngs_modulus_pa},
      {"youngs_modulus_note", "softened, as DEM practice does, to allow a practical time step"},
      {"time_step_s", dem.time_step_s},
      {"bed_depth_m", dem.bed_depth_m}};
  std::ofstream out(path);
  out << json.dump(2) << "\n";
  if (!out) throw std::runtime_error(fmt::format("{}: write failed", path.string()));
}

}  // namespace

std::string default_cache_dir() {
  if (const char* env = std::getenv("REPOSE_CACHE"); env && *env) return env;
#ifdef REPOSE_SOURCE_DIR
  return (fs::path(REPOSE_SOURCE_DIR) / "cache").string();
#else
  return "cache";
#endif
}

std::string bed_cache_key(const std::string& script_text, const std::string& liggghts_version) {
  return sha256_hex(script_text + "\n# " + liggghts_version + "\n");
}

SettledBed settled_bed(const Scene& scene, const BedOptions& options) {
  const std::string script = bed_script(scene, options.script);
  const std::string executable = resolve_liggghts_executable(options.run);
  SettledBed bed;
  bed.liggghts_version = liggghts_version(executable);
  bed.key = bed_cache_key(script, bed.liggghts_version);
  const fs::path beds = fs::path(options.cache_dir.empty() ? default_cache_dir() : options.cache_dir) / "beds";
  const fs::path entry = beds / bed.key;
  bed.directory = entry.string();
  bed.restart_path = (entry / kBedRestartFile).string();
  bed.dump_path = (entry / kBedDumpFile).string();

  if (complete_entry(entry)) {
    bed.from_cache = true;
    bed.grain_count = static_cast<long>(read_last_dump_frame(bed.dump_path).grains.size());
    return bed;
  }

  fs::create_directories(beds);
  const fs::path tmp = fresh_temporary(beds, bed.key);
  std::ofstream(tmp / kScriptFile) << script;
  LiggghtsRunOptions run = options.run;
  run.executable = executable;
  run.total_steps = bed_max_steps(scene, options.script);
  const LiggghtsRunSummary summary = run_liggghts(tmp.string(), kScriptFile, run);
  bed.grain_count = check_settled(tmp, scene, options.script);
  bed.wall_time_s = summary.wall_time_s;
  bed.cpu_time_s = summary.cpu_time_s;
  bed.steps = summary.last_step;
  write_manifest(tmp / kManifestFile, bed, scene);

  std::error_code ec;
  fs::rename(tmp, entry, ec);
  if (ec) {
    // another process cached the same bed first: use theirs
    if (!complete_entry(entry)) throw std::runtime_error(fmt::format("cannot move {} to {}: {}", tmp.string(), entry.string(), ec.message()));
    fs::remove_all(tmp);
  }
  return bed;
}

}  // namespace repose
