#include "models/ground/rear_to_front_order.h"

#include <algorithm>
#include <cstddef>

namespace repose {

std::vector<int> rear_to_front_order_by_sort(const DragDirection& dir, const ContactRegion& r) {
  // the keys are found once, not in every comparison
  struct Key {
    double along;
    int minus_dist, l;
    bool operator<(const Key& o) const {
      if (along != o.along) return along < o.along;
      if (minus_dist != o.minus_dist) return minus_dist < o.minus_dist;
      return l < o.l;
    }
  };
  std::vector<Key> keys;
  keys.reserve(r.cells.size());
  for (const int l : r.cells) keys.push_back({r.gi(l) * dir.dx + r.gj(l) * dir.dy, -r.dist[l], l});
  std::sort(keys.begin(), keys.end());
  std::vector<int> order;
  order.reserve(keys.size());
  for (const Key& key : keys) order.push_back(key.l);
  return order;
}

// Along an axis, i dx (j dy) is distinct per column (row) and monotone in
// it: first by distance to the border (farthest first) keeping the index
// order, then by column (row) along the drag, both stable.
std::vector<int> rear_to_front_order(const DragDirection& dir, const ContactRegion& r) {
  const bool along_i = dir.dx != 0.0 && dir.dy == 0.0, along_j = dir.dx == 0.0 && dir.dy != 0.0;
  if (!along_i && !along_j) return rear_to_front_order_by_sort(dir, r);
  int max_dist = 0;
  for (const int l : r.cells) max_dist = std::max(max_dist, r.dist[l]);
  auto dist_slot = [&](int l) { return static_cast<std::size_t>(max_dist - r.dist[l]); };  // farthest first
  std::vector<int> start(static_cast<std::size_t>(max_dist) + 2, 0);
  for (const int l : r.cells) ++start[dist_slot(l) + 1];
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<int> by_dist(r.cells.size());
  for (const int l : r.cells) by_dist[static_cast<std::size_t>(start[dist_slot(l)]++)] = l;
  const int lines = along_i ? r.fp.ni : r.fp.nj;
  const bool ascending = along_i ? dir.dx > 0.0 : dir.dy > 0.0;
  auto line_of = [&](int l) {
    const int k = along_i ? l % r.fp.ni : l / r.fp.ni;
    return static_cast<std::size_t>(ascending ? k : lines - 1 - k);
  };
  start.assign(static_cast<std::size_t>(lines) + 1, 0);
  for (const int l : by_dist) ++start[line_of(l) + 1];
  for (std::size_t k = 1; k < start.size(); ++k) start[k] += start[k - 1];
  std::vector<int> order(by_dist.size());
  for (const int l : by_dist) order[static_cast<std::size_t>(start[line_of(l)]++)] = l;
  return order;
}

}  // namespace repose
