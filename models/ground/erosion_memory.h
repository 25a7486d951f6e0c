#pragma once
// The cells that keep eroding: every cell that changed (displacement or
// erosion) is remembered for a number of steps, so slopes keep settling after
// the object has gone (the ground paper, 3.5). A list of the active cells
// plus a per-cell countdown for O(1) membership: nothing ever scans the grid,
// and an empty memory costs nothing.

#include <cstdint>
#include <vector>

namespace repose {

class ErosionMemory {
 public:
  ErosionMemory() = default;
  // memory_steps: how many steps after the one in which it changed a cell
  // keeps eroding (0: only that step). At most 65000.
  ErosionMemory(std::size_t cell_count, int memory_steps);

  // The cell changed in this step: (re)start its countdown.
  void touch(std::int64_t cell);
  bool contains(std::int64_t cell) const { return remaining_[static_cast<std::size_t>(cell)] != 0; }
  // Active cells, in the order they joined (deterministic).
  const std::vector<std::int64_t>& cells() const { return cells_; }
  bool empty() const { return cells_.empty(); }
  // Counts the step down and forgets the cells whose time ran out.
  void end_step();

 private:
  std::vector<std::uint16_t> remaining_;
  std::vector<std::int64_t> cells_;
  std::uint16_t start_ = 1;
};

}  // namespace repose
