#pragma once
// The cells that keep eroding: every cell that changed (displacement or
// erosion) is remembered, so slopes keep settling after the object has gone
// (the ground paper, 3.5). A list of the active cells plus a per-cell
// countdown for O(1) membership: nothing ever scans the grid, and an empty
// memory costs nothing.
//
// Departure from the paper, which remembers a cell for a fixed time: a
// cell is remembered for at least `memory_steps` steps after it last
// changed and after that until it is settled (erosion.h, is_settled). With
// a fixed time alone, cells were forgotten while their slopes were still
// steeper than the angle of repose (37 deg for a 30 deg sand 1.2 s after a
// sphere was lifted out, issue 16), so the surface never reached it unless
// En or the memory were large. Now a surface left alone reaches tan(theta)
// (to erosion's tolerance) whatever En and the memory length: these only
// set how fast, and for how long settled cells are still examined.

#include <cstdint>
#include <functional>
#include <vector>

namespace repose {

class ErosionMemory {
 public:
  ErosionMemory() = default;
  // memory_steps: how many steps after the one in which it changed a cell
  // is surely examined (0: only that step). At most 65000.
  ErosionMemory(std::size_t cell_count, int memory_steps);

  // The cell changed in this step: (re)start its countdown. Inline: erosion
  // touches both cells of every move.
  void touch(std::int64_t cell) {
    std::uint16_t& r = remaining_[static_cast<std::size_t>(cell)];
    if (r == 0) cells_.push_back(cell);
    r = start_;
  }
  bool contains(std::int64_t cell) const { return remaining_[static_cast<std::size_t>(cell)] != 0; }
  // Active cells, in the order they joined (deterministic).
  const std::vector<std::int64_t>& cells() const { return cells_; }
  bool empty() const { return cells_.empty(); }
  // Counts the step down; a cell whose time ran out is forgotten only if
  // `settled(cell)` (none given: every cell counts as settled, the paper's
  // rule); an unsettled one stays, to be asked again at the next step.
  void end_step(const std::function<bool(std::int64_t)>& settled = {});

 private:
  std::vector<std::uint16_t> remaining_;
  std::vector<std::int64_t> cells_;
  std::uint16_t start_ = 1;
};

}  // namespace repose
