#include "models/ground/erosion_memory.h"

#include "models/core/base/error.h"

namespace repose {

ErosionMemory::ErosionMemory(std::size_t cell_count, int memory_steps)
    : remaining_(cell_count, 0), start_(static_cast<std::uint16_t>(memory_steps + 1)) {
  REPOSE_DEMAND(memory_steps >= 0 && memory_steps <= 65000);
}

void ErosionMemory::end_step(const std::function<bool(std::int64_t)>& settled) {
  std::size_t kept = 0;
  for (const std::int64_t c : cells_) {
    std::uint16_t& r = remaining_[static_cast<std::size_t>(c)];
    if (r == 1 && settled && !settled(c)) {
      cells_[kept++] = c;  // time ran out but the slope has not settled: stays, r stays 1
      continue;
    }
    if (--r > 0) cells_[kept++] = c;
  }
  cells_.resize(kept);
}

}  // namespace repose
