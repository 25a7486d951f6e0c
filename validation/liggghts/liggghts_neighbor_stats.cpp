#include "validation/liggghts/liggghts_neighbor_stats.h"

#include <fstream>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

// The count after "PREFIX = " at the start of `line`, or -1.
long count_after(const std::string& line, const std::string& prefix) {
  if (line.rfind(prefix, 0) != 0) return -1;
  try {
    return std::stol(line.substr(prefix.size()));
  } catch (const std::exception&) {
    return -1;
  }
}

}  // namespace

NeighborStats read_neighbor_stats(const std::string& log_path) {
  std::ifstream in(log_path);
  if (!in) throw InputError(fmt::format("{}: cannot read the LIGGGHTS log", log_path));
  NeighborStats stats;
  for (std::string line; std::getline(in, line);) {
    if (const long n = count_after(line, "Neighbor list builds = "); n >= 0) stats.builds += n;
    if (const long n = count_after(line, "Dangerous builds = "); n >= 0) stats.dangerous_builds += n;
  }
  return stats;
}

}  // namespace repose
