#pragma once
// Received: the material one displacement put on each free cell (cell index
// -> m of height), so that routing moves only that and never bulldozes the
// ground already there (contact_region.h, excess_routing.h).
//
// A flat map (open addressing, linear probing, entries kept in insertion
// order), in place of std::unordered_map: routing looks a cell up several
// times per cell it visits, and the node-based map's lookups were most of
// the heap routing's time on the scoop. The amounts are the same doubles
// (the same additions in the same order); only how they are found changed.
// Iteration is in insertion order (deterministic); callers that need cell
// order sort. A reference from operator[] is valid until the next insertion.

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace repose {

class Received {
 public:
  using Entry = std::pair<std::int64_t, double>;

  // The amount of `cell` (>= 0), inserted as 0 when absent.
  double& operator[](std::int64_t cell) {
    if (2 * (entries_.size() + 1) > slots_.size()) grow();
    std::size_t s = slot_of(cell);
    while (slots_[s] >= 0) {
      Entry& e = entries_[static_cast<std::size_t>(slots_[s])];
      if (e.first == cell) return e.second;
      s = (s + 1) & (slots_.size() - 1);
    }
    slots_[s] = static_cast<std::int32_t>(entries_.size());
    entries_.emplace_back(cell, 0.0);
    return entries_.back().second;
  }
  // The amount of `cell`, or nullptr when it has none.
  const double* find(std::int64_t cell) const {
    if (slots_.empty()) return nullptr;
    for (std::size_t s = slot_of(cell); slots_[s] >= 0; s = (s + 1) & (slots_.size() - 1)) {
      const Entry& e = entries_[static_cast<std::size_t>(slots_[s])];
      if (e.first == cell) return &e.second;
    }
    return nullptr;
  }
  std::size_t size() const { return entries_.size(); }
  std::vector<Entry>::const_iterator begin() const { return entries_.begin(); }
  std::vector<Entry>::const_iterator end() const { return entries_.end(); }

 private:
  std::size_t slot_of(std::int64_t cell) const {
    // Fibonacci hashing: neighbouring cells land far apart
    return static_cast<std::size_t>((static_cast<std::uint64_t>(cell) * 0x9E3779B97F4A7C15ull) >> shift_);
  }
  void grow() {
    const std::size_t n = slots_.empty() ? 64 : 2 * slots_.size();
    shift_ = 64;
    for (std::size_t m = n; m > 1; m >>= 1) --shift_;
    slots_.assign(n, -1);
    for (std::size_t k = 0; k < entries_.size(); ++k) {
      std::size_t s = slot_of(entries_[k].first);
      while (slots_[s] >= 0) s = (s + 1) & (n - 1);
      slots_[s] = static_cast<std::int32_t>(k);
    }
  }
  std::vector<Entry> entries_;
  std::vector<std::int32_t> slots_;  // index into entries_, -1: empty; a power of two, at most half full
  int shift_ = 64;
};

}  // namespace repose
