#pragma once
// Settled beds of grains, prepared once per scene material and bed size and
// cached: the key is the sha256 of the generated bed script (which holds
// every grain, contact and size parameter and the seeds) plus the LIGGGHTS
// version line. An entry is built in a temporary sibling directory and
// renamed into place only after the run succeeded and was checked, so a
// failed or killed run never leaves an entry (its temporary directory stays,
// named in the error, for diagnosis).
//
// Entry layout: CACHE/beds/KEY/{bed.in, bed.restart, bed.dump, log.liggghts, manifest.json}.

#include <string>

#include "models/core/config/scene.h"
#include "validation/liggghts/liggghts_runner.h"
#include "validation/liggghts/liggghts_script.h"

namespace repose {

struct BedOptions {
  BedScriptOptions script;
  std::string cache_dir;    // empty: default_cache_dir()
  LiggghtsRunOptions run;   // executable, wall-clock limit, progress (total_steps is set here)
};

struct SettledBed {
  std::string directory;     // the cache entry
  std::string restart_path;  // bed.restart: read by run scripts
  std::string dump_path;     // bed.dump: the settled grains (id type x y z radius)
  std::string key;           // sha256 hex
  std::string liggghts_version;
  long grain_count = 0;
  bool from_cache = false;
  double wall_time_s = 0.0;  // of the settling run (0 when from the cache)
  double cpu_time_s = 0.0;   // of the settling run (0 when from the cache)
  long steps = 0;            // steps of the settling run (0 when from the cache)
};

// $REPOSE_CACHE when set, else REPOSE_SOURCE_DIR/cache when the build defines
// it, else ./cache.
std::string default_cache_dir();

// The cache key of a bed script run by a LIGGGHTS version.
std::string bed_cache_key(const std::string& script_text, const std::string& liggghts_version);

// Returns the cached bed for the scene, or settles one (running LIGGGHTS)
// and caches it. Throws LiggghtsRunError when the run fails (including: not
// settled in time, fewer grains inserted than asked, grains outside the box)
// and InputError for a scene without a valid dem section.
SettledBed settled_bed(const Scene& scene, const BedOptions& options = {});

}  // namespace repose
