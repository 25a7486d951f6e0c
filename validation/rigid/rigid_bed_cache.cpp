#include "validation/rigid/rigid_bed_cache.h"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "models/core/base/sha256.h"
#include "validation/rigid/grain_file.h"

namespace repose {

namespace fs = std::filesystem;

namespace {

constexpr const char* kGrainsFile = "grains.npy";
constexpr const char* kKeyFile = "key.txt";
constexpr const char* kManifestFile = "manifest.json";
constexpr const char* kLayoutVersion = "rigid bed layout 1";

bool complete_entry(const fs::path& dir) {
  std::error_code ec;
  return fs::is_regular_file(dir / kGrainsFile, ec) && fs::is_regular_file(dir / kManifestFile, ec);
}

fs::path fresh_temporary(const fs::path& beds, const std::string& key) {
  static std::atomic<int> counter{0};
  for (;;) {
    const fs::path p = beds / fmt::format(".tmp-{}-{}-{}", key.substr(0, 16), ::getpid(), counter++);
    if (fs::create_directory(p)) return p;
  }
}

void write_manifest(const fs::path& path, const RigidEngine& engine, const RigidBed& bed) {
  const RigidPhaseSummary& s = bed.settle;
  const double particle_steps = static_cast<double>(bed.grains.size()) * static_cast<double>(s.steps);
  const nlohmann::json json = {
      {"kind", "settled rigid bed"},
      {"engine", engine.name},
      {"engine_version", engine.version},
      {"cache_key", bed.key},
      {"grain_count", bed.grains.size()},
      {"steps", s.steps},
      {"simulated_s", s.simulated_s},
      {"kinetic_energy_j", s.kinetic_energy_j},
      {"wall_time_s", s.wall_time_s},
      {"cpu_time_s", s.cpu_time_s},
      {"particle_steps_per_cpu_s", s.cpu_time_s > 0 ? particle_steps / s.cpu_time_s : 0.0}};
  std::ofstream out(path);
  out << json.dump(2) << "\n";
  if (!out) throw std::runtime_error(fmt::format("{}: write failed", path.string()));
}

// Settles a fresh bed in tmp; throws when it does not settle or loses grains.
RigidBed settle_fresh(const RigidEngine& engine, const RigidInputs& in) {
  const RigidWorldSpec spec = settling_world(in, engine.rigid);
  const double threshold = settle_threshold_j(engine.rigid, in.dem, spec.grains);
  const auto world = engine.make_world(spec);
  RigidBed bed;
  bed.settle = settle(*world, threshold, engine.rigid.settle_check_interval_s, engine.rigid.max_settle_time_s);
  bed.grains = world->grains();
  demand_no_grain_lost(bed.grains, spec.bounds, engine.name, "settling");
  if (!bed.settle.settled) {
    throw std::runtime_error(fmt::format(
        "{}: the bed did not settle in {} s: kinetic energy {} J, threshold {} J (raise {}.max_settle_time_s or "
        "{}.settle_rms_speed_m_s)",
        engine.name, engine.rigid.max_settle_time_s, bed.settle.kinetic_energy_j, threshold, engine.name, engine.name));
  }
  return bed;
}

}  // namespace

double settle_threshold_j(const RigidOptions& options, const DemSpec& dem, const GrainSet& grains) {
  if (options.settle_rms_speed_m_s == 0.0) return dem.settle_kinetic_energy_j;
  const double mass_kg = dem.density_kg_m3 * 4.0 / 3.0 * M_PI * grains.radius_m.array().cube().sum();
  return 0.5 * mass_kg * options.settle_rms_speed_m_s * options.settle_rms_speed_m_s;
}

std::string rigid_bed_key_text(const RigidEngine& engine, const RigidInputs& in) {
  const DemSpec& d = in.dem;
  const Grid& g = in.grid;
  std::string text = fmt::format("{}\nengine={}\nversion={}\n", kLayoutVersion, engine.name, engine.version);
  text += engine.options_text;
  text += fmt::format(
      "grain_radius_m={}\nradius_spread={}\ndensity_kg_m3={}\nrestitution={}\nfriction={}\nrolling_friction={}\n"
      "floor={}\nfloor_rolling_friction={}\ngravity_m_s2={}\nsettle_kinetic_energy_j={}\nbed_depth_m={}\n",
      d.grain_radius_m, d.radius_spread, d.density_kg_m3, d.restitution, d.friction, d.rolling_friction,
      d.floor == DemSpec::Floor::kRough ? "rough" : "smooth", d.floor_rolling_friction, d.gravity_m_s2,
      d.settle_kinetic_energy_j, d.bed_depth_m);
  text += fmt::format("grid={} {} {} {} {}\nseed={}\n", g.nx, g.ny, g.cell_size_m, g.origin_x_m, g.origin_y_m, in.seed);
  if (in.column) {
    text += fmt::format("column={} {} {}\n", column_shape_name(in.column->shape),
                        d.column_width_m, d.column_height_m);
  }
  return text;
}

RigidBed settled_rigid_bed(const RigidEngine& engine, const RigidInputs& in, const std::string& cache_dir) {
  const std::string key_text = rigid_bed_key_text(engine, in);
  const std::string key = sha256_hex(key_text);
  const fs::path beds = fs::path(cache_dir) / "rigid_beds";
  const fs::path entry = beds / key;
  if (complete_entry(entry)) {
    RigidBed bed;
    bed.grains = read_grains_npy((entry / kGrainsFile).string());
    bed.key = key;
    bed.directory = entry.string();
    bed.from_cache = true;
    return bed;
  }
  RigidBed bed = settle_fresh(engine, in);
  bed.key = key;
  bed.directory = entry.string();
  fs::create_directories(beds);
  const fs::path tmp = fresh_temporary(beds, key);
  write_grains_npy((tmp / kGrainsFile).string(), bed.grains);
  std::ofstream(tmp / kKeyFile) << key_text;
  write_manifest(tmp / kManifestFile, engine, bed);
  std::error_code ec;
  fs::rename(tmp, entry, ec);
  if (ec) {
    // another process cached the same bed first: use theirs (the same bits)
    if (!complete_entry(entry)) {
      throw std::runtime_error(fmt::format("cannot move {} to {}: {}", tmp.string(), entry.string(), ec.message()));
    }
    fs::remove_all(tmp);
  }
  // start from the stored grains, as a cached run does
  bed.grains = read_grains_npy((entry / kGrainsFile).string());
  return bed;
}

}  // namespace repose
