#pragma once
// RankQueue: the cells waiting to shed in the heap routing
// (excess_routing.cpp), by rank (their place in the order of visits),
// smallest first. One bit per rank and a cursor that only moves forwards
// while popping: a cell only ever gives to cells visited after it, so every
// rank pushed while popping lies beyond the cursor. In place of a binary
// heap of ranks: no comparisons, no reordering, and a rank pushed twice
// waits once.

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace repose {

class RankQueue {
 public:
  // r >= 0. A rank smaller than the last popped one may be pushed too (the
  // cursor moves back), as long as nothing is waiting below it.
  void push(int r) {
    const std::size_t w = static_cast<std::size_t>(r) >> 6;
    if (w >= bits_.size()) bits_.resize(w + 1, 0);
    bits_[w] |= std::uint64_t{1} << (r & 63);
    cursor_ = std::min(cursor_, w);
  }
  bool empty() { return top() < 0; }
  // The smallest waiting rank, -1 when none waits.
  int top() {
    for (; cursor_ < bits_.size(); ++cursor_) {
      if (bits_[cursor_] != 0) return static_cast<int>(64 * cursor_) + std::countr_zero(bits_[cursor_]);
    }
    return -1;
  }
  // Removes top(); only after top() found a rank.
  void pop() { bits_[cursor_] &= bits_[cursor_] - 1; }

 private:
  std::vector<std::uint64_t> bits_;
  std::size_t cursor_ = 0;
};

}  // namespace repose
