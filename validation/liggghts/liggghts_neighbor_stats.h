#pragma once
// The neighbour-list statistics a LIGGGHTS log prints after each run block:
// "Neighbor list builds = N" and "Dangerous builds = N" (a build that found
// a pair already inside contact range: with a skin too thin or checks too
// rare, contacts were missed). Summed over the log's run blocks, so a
// tuning of the neighbour settings (liggghts_options.h) shows what it costs.

#include <string>

namespace repose {

struct NeighborStats {
  long builds = 0;
  long dangerous_builds = 0;
};

// Throws InputError naming the log when it cannot be read.
NeighborStats read_neighbor_stats(const std::string& log_path);

}  // namespace repose
