#pragma once
// Settled rigid-body beds, cached by the sha256 of everything that
// determines them: the engine's name, version and options, the grain and
// contact parameters of the dem section, the grid, the seed and the layout
// version. An entry is written in a temporary sibling directory and renamed
// into place only after the bed settled with no grain lost, so a failed or
// killed run never leaves an entry.
//
// Entry layout: CACHE/rigid_beds/KEY/{grains.npy (#G by 4: x y z r, m), key.txt, manifest.json}.
// A run always starts from the grains as stored (at rest), whether it just
// settled them or read them back, so a cached and a fresh run give the same bits.

#include <string>

#include "validation/particles/grain_set.h"
#include "validation/rigid/rigid_engine.h"
#include "validation/rigid/rigid_setup.h"
#include "validation/rigid/rigid_simulation.h"

namespace repose {

struct RigidBed {
  GrainSet grains;           // settled, at rest
  std::string key;           // sha256 hex
  std::string directory;     // the cache entry
  bool from_cache = false;
  RigidPhaseSummary settle;  // of the settling run (zeros when from the cache)
};

// The kinetic energy (J) below which the grains count as settled
// (RigidOptions::settle_rms_speed_m_s).
double settle_threshold_j(const RigidOptions& options, const DemSpec& dem, const GrainSet& grains);

// The text whose sha256 is the key (one key=value per line).
std::string rigid_bed_key_text(const RigidEngine& engine, const RigidInputs& in);

// Returns the cached bed or settles one and caches it. Throws
// std::runtime_error when the bed does not settle within
// rigid.max_settle_time_s or loses a grain (nothing is cached then).
RigidBed settled_rigid_bed(const RigidEngine& engine, const RigidInputs& in, const std::string& cache_dir);

}  // namespace repose
