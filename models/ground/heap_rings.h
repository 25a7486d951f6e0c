#pragma once
// The rings of the heap routing on open ground (excess_routing.h): rings of
// 4-neighbour distance from the objects through uncovered cells, each
// cell's place in the order of visits, and which neighbours material may
// pass to. Internal to the ground model (excess_routing.cpp,
// heap_in_one_pass.cpp); not a public interface.

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "models/ground/excess_routing.h"
#include "models/ground/ground_model.h"

namespace repose {

// Rings of 4-neighbour distance from the objects (ring 0: the covered cells
// of the footprint) through uncovered cells, found as far out as asked. The
// ring of each cell is kept in a dense window around the footprint, which
// doubles when a ring reaches its edge.
class Rings {
 public:
  explicit Rings(const ExcessRouting& in) : in_(in), window_(in.region.fp), covered_(covering_box(in)) {
    resize_window(16);
    const Footprint& fp = in.region.fp;
    rings_.emplace_back();
    for (int j = fp.j0; j < fp.j0 + fp.nj; ++j) {
      for (int i = fp.i0; i < fp.i0 + fp.ni; ++i) {
        if (!in.on_open_ground(i, j)) add(0, i, j);
      }
    }
  }
  // The cells of ring k from the footprint's centre outwards (by away(),
  // then index); empty past the last ring.
  const std::vector<std::array<int, 2>>& at(int k) {
    while (static_cast<int>(rings_.size()) <= k && !rings_.back().empty()) grow();
    return rings_[static_cast<std::size_t>(std::min(k, static_cast<int>(rings_.size()) - 1))];
  }
  // How far from the footprint's centre (4 x squared distance, in cells:
  // exact, so mirror images tie exactly). Within a ring, material moves
  // only away from the centre, so a cell in a concave corner of the region,
  // whose open neighbours share its ring, still has a way out.
  std::int64_t away(int i, int j) const {
    const Footprint& fp = in_.region.fp;
    const std::int64_t di = 2 * static_cast<std::int64_t>(i) - (2 * fp.i0 + fp.ni - 1);
    const std::int64_t dj = 2 * static_cast<std::int64_t>(j) - (2 * fp.j0 + fp.nj - 1);
    return di * di + dj * dj;
  }
  // -1 for a cell not reached yet (or never).
  int of(int i, int j) const { return window_.contains(i, j) ? ring_of_[slot(i, j)] : -1; }
  int of(std::int64_t c) const {
    const int nx = in_.model.grid.nx;
    return of(static_cast<int>(c % nx), static_cast<int>(c / nx));
  }
  // The place of a reached cell in the order of visits (ring, then away(),
  // then index): rings are numbered as they grow, each sorted, so a smaller
  // rank is visited first. Ring 0 (the covered cells) is never visited.
  int rank(std::int64_t c) const {
    const int nx = in_.model.grid.nx;
    return rank(static_cast<int>(c % nx), static_cast<int>(c / nx));
  }
  int rank(int i, int j) const { return rank_of_[slot(i, j)]; }
  // The cell of a rank (index and coordinates), its ring and its away().
  std::int64_t cell_of_rank(int r) const { return by_rank_[static_cast<std::size_t>(r)].cell; }
  int i_of_rank(int r) const { return by_rank_[static_cast<std::size_t>(r)].i; }
  int j_of_rank(int r) const { return by_rank_[static_cast<std::size_t>(r)].j; }
  int ring_of_rank(int r) const { return by_rank_[static_cast<std::size_t>(r)].ring; }
  std::int64_t away_of_rank(int r) const { return by_rank_[static_cast<std::size_t>(r)].away; }
  // How many cells have a rank so far (those of the rings grown).
  int ranked() const { return static_cast<int>(by_rank_.size()); }

 private:
  std::size_t slot(int i, int j) const {
    return static_cast<std::size_t>(j - window_.j0) * window_.ni + (i - window_.i0);
  }
  // The footprint and `margin` cells around it, clamped to the grid.
  void resize_window(int margin) {
    const Grid& g = in_.model.grid;
    const Footprint& fp = in_.region.fp;
    const Footprint old = window_;
    const std::vector<int> old_rings = std::move(ring_of_);
    const std::vector<int> old_ranks = std::move(rank_of_);
    const int i0 = std::max(0, fp.i0 - margin), j0 = std::max(0, fp.j0 - margin);
    window_ = Footprint{i0, j0, std::min(g.nx, fp.i0 + fp.ni + margin) - i0, std::min(g.ny, fp.j0 + fp.nj + margin) - j0};
    ring_of_.assign(static_cast<std::size_t>(window_.ni) * window_.nj, -1);
    rank_of_.assign(ring_of_.size(), -1);
    margin_ = margin;
    if (old_rings.empty()) return;
    for (int j = old.j0; j < old.j0 + old.nj; ++j) {
      for (int i = old.i0; i < old.i0 + old.ni; ++i) {
        const std::size_t o = static_cast<std::size_t>(j - old.j0) * old.ni + (i - old.i0);
        ring_of_[slot(i, j)] = old_rings[o];
        rank_of_[slot(i, j)] = old_ranks[o];
      }
    }
  }
  void add(int k, int i, int j) {
    if (!window_.contains(i, j)) resize_window(2 * margin_);
    int& r = ring_of_[slot(i, j)];
    if (r != -1) return;
    r = k;
    rings_[static_cast<std::size_t>(k)].push_back({i, j});
  }
  void grow() {
    const Grid& g = in_.model.grid;
    const int k = static_cast<int>(rings_.size());
    rings_.emplace_back();
    // add() only appends to rings_[k]: the previous ring stays where it is
    const std::vector<std::array<int, 2>>& last = rings_[static_cast<std::size_t>(k - 1)];
    for (const auto& [i, j] : last) {
      for (const auto& o : kNeighbours) {
        const int ni = i + o[0], nj = j + o[1];
        // a cell already in a ring needs no second look (on_open_ground is the costly part)
        if (!g.contains(ni, nj) || of(ni, nj) != -1) continue;
        if (!covered_.contains(ni, nj) || in_.on_open_ground(ni, nj)) add(k, ni, nj);
      }
    }
    // by away(), then index: the keys found once, not in every comparison
    std::vector<Ranked> keyed;
    keyed.reserve(rings_.back().size());
    for (const auto& [i, j] : rings_.back()) keyed.push_back({in_.model.cell(i, j), away(i, j), k, i, j});
    std::sort(keyed.begin(), keyed.end(), [](const Ranked& a, const Ranked& b) {
      return a.away != b.away ? a.away < b.away : a.cell < b.cell;
    });
    for (std::size_t m = 0; m < keyed.size(); ++m) {
      rings_.back()[m] = {keyed[m].i, keyed[m].j};
      rank_of_[slot(keyed[m].i, keyed[m].j)] = static_cast<int>(by_rank_.size());
      by_rank_.push_back(keyed[m]);
    }
  }
  // The box around every underside's footprint and the pockets' window:
  // beyond it no cell is covered and none is a pocket, so every cell is on
  // open ground (ExcessRouting::limit_at: +inf there) without asking.
  static Footprint covering_box(const ExcessRouting& in) {
    Footprint box = in.window;
    for (const Underside& u : in.ceiling.undersides) {
      if (!u.empty()) box = bounding_box(box, u.footprint);
    }
    return box;
  }
  const ExcessRouting& in_;
  Footprint window_;
  Footprint covered_;
  int margin_ = 0;
  std::vector<std::vector<std::array<int, 2>>> rings_;  // the cells (i, j) of each ring
  std::vector<int> ring_of_;  // over window_; -1: not reached
  std::vector<int> rank_of_;  // over window_; -1: not reached or ring 0
  struct Ranked {
    std::int64_t cell, away;
    int ring, i, j;
  };
  std::vector<Ranked> by_rank_;
};

// Whether material may pass from c (ring k) to n: outwards to ring k + 1,
// or within ring k away from the centre. Both orders are strict, so
// material never comes back.
inline bool onward(const Rings& rings, int i, int j, int k, int ni, int nj) {
  const int kn = rings.of(ni, nj);
  return kn == k + 1 || (kn == k && rings.away(ni, nj) > rings.away(i, j));
}

}  // namespace repose
