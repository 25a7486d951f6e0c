#include "models/ground/excess_routing.h"

#include <algorithm>
#include <array>
#include <tuple>
#include <cmath>
#include <utility>

#include "models/core/base/error.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"
#include "models/ground/heap_in_one_pass.h"
#include "models/ground/heap_rings.h"
#include "models/ground/rank_queue.h"

namespace repose {

namespace {

int cell_i(std::int64_t c, int nx) { return static_cast<int>(c % nx); }
int cell_j(std::int64_t c, int nx) { return static_cast<int>(c / nx); }

std::vector<std::int64_t> cells_with_material(const Received& received) {
  std::vector<std::int64_t> cells;
  for (const auto& [c, amount] : received) {
    if (amount > 0.0) cells.push_back(c);
  }
  std::sort(cells.begin(), cells.end());  // by cell, not in the order they received
  return cells;
}

void sort_unique(std::vector<std::int64_t>* v) {
  std::sort(v->begin(), v->end());
  v->erase(std::unique(v->begin(), v->end()), v->end());
}

// Puts `amount` on cell (i, j), or records it as leaving the grid.
void deposit(const ExcessRouting& in, int i, int j, double amount, Received* received, GroundState* state) {
  const Grid& g = in.model.grid;
  if (!g.contains(i, j)) {
    state->ledger.left_grid_m3 += amount * g.cell_area_m2();
    return;
  }
  const std::int64_t c = in.model.cell(i, j);
  state->height.at(i, j) += amount;
  (*received)[c] += amount;
}

void take(const ExcessRouting& in, std::int64_t c, double amount, Received* received, GroundState* state) {
  state->height.heights().data()[c] -= amount;  // row-major: index c is cell (i, j)
  double& r = (*received)[c];
  r = std::max(0.0, r - amount);
}

// ---- 1. under an object: towards the nearest uncovered cell ----

// Levels over the footprint and one ring around it (the ring lies under no
// other object: objects with touching footprints share one region).
struct Levels {
  Footprint w;
  std::vector<int> level;  // -1: not reached
  std::size_t at(int i, int j) const { return static_cast<std::size_t>((j - w.j0) * w.ni + (i - w.i0)); }
  int of(int i, int j) const { return w.contains(i, j) ? level[at(i, j)] : -1; }
};

// Breadth-first from the queue's cells, through contact cells only when asked.
void grow(const ContactRegion& r, bool through_contact, std::vector<std::pair<int, int>>* queue, Levels* lv) {
  for (std::size_t q = 0; q < queue->size(); ++q) {
    const auto [i, j] = (*queue)[q];
    for (const auto& o : kNeighbours) {
      const int ni = i + o[0], nj = j + o[1];
      if (!lv->w.contains(ni, nj) || lv->level[lv->at(ni, nj)] != -1) continue;
      if (!through_contact && r.is_contact(ni, nj)) continue;
      lv->level[lv->at(ni, nj)] = lv->level[lv->at(i, j)] + 1;
      queue->emplace_back(ni, nj);
    }
  }
}

// Level 0: uncovered cells; 1: covered cells at the grid's edge (the open
// boundary is one step away). A cell above the ceiling that only contact
// cells separate from open ground (a hole that another object dug below
// this one's underside) would keep its excess: only then, the levels go on
// through the contact cells, which sit at the ceiling and so pass on
// whatever they are given.
Levels levels_to_open_ground(const ExcessRouting& in, const std::vector<std::int64_t>& over) {
  const Grid& g = in.model.grid;
  const Footprint& fp = in.region.fp;
  Levels lv;
  lv.w = Footprint{std::max(0, fp.i0 - 1), std::max(0, fp.j0 - 1),
                   std::min(g.nx, fp.i0 + fp.ni + 1) - std::max(0, fp.i0 - 1),
                   std::min(g.ny, fp.j0 + fp.nj + 1) - std::max(0, fp.j0 - 1)};
  lv.level.assign(static_cast<std::size_t>(lv.w.ni) * lv.w.nj, -1);
  std::vector<std::pair<int, int>> queue;
  for (const int seed_level : {0, 1}) {
    for (int j = lv.w.j0; j < lv.w.j0 + lv.w.nj; ++j) {
      for (int i = lv.w.i0; i < lv.w.i0 + lv.w.ni; ++i) {
        if (in.region.is_contact(i, j)) continue;
        const bool open = in.on_open_ground(i, j);
        const bool at_edge = i == 0 || j == 0 || i == g.nx - 1 || j == g.ny - 1;
        if ((seed_level == 0 && open) || (seed_level == 1 && !open && at_edge)) {
          lv.level[lv.at(i, j)] = seed_level;
          queue.emplace_back(i, j);
        }
      }
    }
  }
  grow(in.region, false, &queue, &lv);
  bool enclosed = false;
  for (const std::int64_t c : over) enclosed = enclosed || lv.of(cell_i(c, g.nx), cell_j(c, g.nx)) == -1;
  if (enclosed) grow(in.region, true, &queue, &lv);
  return lv;
}

// The neighbours of a level-k cell one level nearer open ground; not
// backwards while dragging unless that is the only way out (staying under
// the object would be worse than moving back). Off the grid counts as level 0.
int nearer_neighbours(const ExcessRouting& in, const Levels& lv, int i, int j, int k, int targets[4][2]) {
  int n = 0;
  for (const bool allow_backward : {false, true}) {
    for (const auto& o : kNeighbours) {
      if (!allow_backward && in.dir.backward(o[0], o[1])) continue;
      const int ni = i + o[0], nj = j + o[1];
      const bool nearer = in.model.grid.contains(ni, nj) ? lv.of(ni, nj) == k - 1 : k == 1;
      if (nearer) targets[n][0] = ni, targets[n][1] = nj, ++n;
    }
    if (n > 0) break;
  }
  return n;
}

void move_under_objects(const ExcessRouting& in, Received* received, GroundState* state) {
  const Grid& g = in.model.grid;
  auto excess_at = [&](int i, int j) { return state->height.at(i, j) - in.limit_at(i, j); };
  std::vector<std::int64_t> over;
  for (const std::int64_t c : cells_with_material(*received)) {
    if (excess_at(cell_i(c, g.nx), cell_j(c, g.nx)) > 0.0) over.push_back(c);
  }
  if (over.empty()) return;
  const Levels lv = levels_to_open_ground(in, over);
  std::vector<std::vector<std::int64_t>> by_level(1);
  auto enqueue = [&](std::int64_t c) {
    const int k = lv.of(cell_i(c, g.nx), cell_j(c, g.nx));
    if (k <= 0) return;  // open cells: the heap rule (below); unreachable cells keep their excess
    if (k >= static_cast<int>(by_level.size())) by_level.resize(static_cast<std::size_t>(k) + 1);
    by_level[static_cast<std::size_t>(k)].push_back(c);
  };
  for (const std::int64_t c : over) enqueue(c);
  // from the farthest level down: a level only gives to the next, so each cell has all it will get
  for (int k = static_cast<int>(by_level.size()) - 1; k >= 1; --k) {
    std::vector<std::int64_t>& cells = by_level[static_cast<std::size_t>(k)];
    sort_unique(&cells);
    for (const std::int64_t c : cells) {
      const int i = cell_i(c, g.nx), j = cell_j(c, g.nx);
      const double e = excess_at(i, j);
      int targets[4][2];
      const int n = e > 0.0 ? nearer_neighbours(in, lv, i, j, k, targets) : 0;
      if (n == 0) continue;  // nothing above the ceiling; n == 0 cannot happen for k >= 1 (BFS)
      take(in, c, e, received, state);
      for (int t = 0; t < n; ++t) {
        deposit(in, targets[t][0], targets[t][1], e / n, received, state);
        if (g.contains(targets[t][0], targets[t][1])) enqueue(in.model.cell(targets[t][0], targets[t][1]));
      }
    }
  }
}

// ---- 2. on open ground: heaps no steeper than theta, no higher than the crest ----

bool is_open(const ExcessRouting& in, int i, int j) { return in.on_open_ground(i, j); }

struct Shed {
  std::int64_t from;
  double amount;
  int n;
  int to[4][2];  // may lie off the grid
};

// What cell c of ring k passes on (amount 0: nothing).
Shed shed_of(const ExcessRouting& in, const Rings& rings, std::int64_t c, int i, int j, int k,
             const Received& received, const GroundState& state) {
  const Grid& g = in.model.grid;
  const double h = state.height.at(i, j);
  const double* got = received.find(c);
  const double mine = got == nullptr ? 0.0 : *got;
  Shed s{c, 0.0, 0, {}};
  if (!(mine > 0.0)) return s;
  double lowest = std::numeric_limits<double>::infinity();
  // tiers: ahead along a drag; not backwards; any way out (excess_routing.h)
  for (std::size_t tier = 0; tier < 3; ++tier) {
    for (int q = 0; q < in.tier_dir_count[tier]; ++q) {
      const std::size_t m = static_cast<std::size_t>(in.tier_dirs[tier][static_cast<std::size_t>(q)]);
      const int ni = i + kNeighbours[m][0], nj = j + kNeighbours[m][1];
      const bool inside = g.contains(ni, nj);
      if (inside && !onward(rings, i, j, k, ni, nj)) continue;
      lowest = std::min(lowest, inside ? state.height.at(ni, nj) : h - mine);  // beyond the edge: as the edge was
      s.to[s.n][0] = ni, s.to[s.n][1] = nj, ++s.n;
    }
    if (s.n > 0) break;
  }
  if (s.n == 0) return s;  // hemmed in: keeps what it got
  const double cap = std::min(in.crest_m, lowest + in.repose_step_m[static_cast<std::size_t>(in.model.material_at(c))]);
  s.amount = std::min(mine, h - cap);
  return s;
}

// Moves the material of `holding` (cells that just received) outwards until
// it rests: ring by ring, within a ring from the centre outwards, cells
// equally far from it all at once (Jacobi: they never give to each other,
// and their caps are taken from the heights before any of them moves).
// Only cells that received are visited: a cell's cap never falls (its
// onward neighbours only rise), so one that rested still rests.
void shed_outwards(const ExcessRouting& in, const std::vector<std::int64_t>& holding, Rings* rings,
                   Received* received, GroundState* state) {
  const Grid& g = in.model.grid;
  RankQueue queue;
  auto enqueue = [&](int r) {
    REPOSE_DEMAND(r >= 0);  // open cells are in rings 1 and on, ranked as their ring grows
    queue.push(r);
  };
  for (const std::int64_t c : holding) enqueue(rings->rank(c));
  std::vector<Shed> sheds;
  while (!queue.empty()) {
    const int k = rings->ring_of_rank(queue.top());
    const std::int64_t away = rings->away_of_rank(queue.top());
    rings->at(k + 1);  // its onward neighbours are known
    sheds.clear();
    for (int r = queue.top(); r >= 0; r = queue.top()) {
      if (rings->ring_of_rank(r) != k || rings->away_of_rank(r) != away) break;
      const std::int64_t c = rings->cell_of_rank(r);
      queue.pop();
      const Shed s = shed_of(in, *rings, c, rings->i_of_rank(r), rings->j_of_rank(r), k, *received, *state);
      if (s.amount > 0.0) sheds.push_back(s);
    }
    for (const Shed& s : sheds) {
      take(in, s.from, s.amount, received, state);
      for (int t = 0; t < s.n; ++t) {
        const int ti = s.to[t][0], tj = s.to[t][1];
        deposit(in, ti, tj, s.amount / s.n, received, state);
        if (g.contains(ti, tj)) enqueue(rings->rank(ti, tj));
      }
    }
  }
}

// The material on uncovered cells is laid down in portions of at most one
// repose step (cell_size * tan(theta)) at its source, each swept outwards:
// as poured material does, the heap grows upwards near the object only as
// its foot widens, so it ends as a slope at theta rather than a thin layer
// spread far (at most kMaxPortions portions; theta = 90 deg needs one).
void heap_on_open_ground(const ExcessRouting& in, Received* received, GroundState* state) {
  constexpr int kMaxPortions = 16;
  const Grid& g = in.model.grid;
  Rings rings(in);
  std::vector<std::pair<std::int64_t, double>> sources;  // cell, displaced material on it
  std::vector<std::int64_t> holding;
  double portions = 1.0;
  for (const std::int64_t c : cells_with_material(*received)) {
    const int i = cell_i(c, g.nx), j = cell_j(c, g.nx);
    if (!is_open(in, i, j)) continue;
    for (int k = 1; rings.of(c) == -1 && !rings.at(k).empty(); ++k) {
    }
    if (rings.of(c) == -1) continue;  // hemmed in: keeps what it got
    const double amount = (*received)[c];
    sources.emplace_back(c, amount);
    holding.push_back(c);
    const double step_m = in.repose_step_m[static_cast<std::size_t>(in.model.material_at(c))];
    portions = std::max(portions, std::min<double>(kMaxPortions, std::ceil(amount / step_m)));
    state->height.at(i, j) -= amount;
    (*received)[c] = 0.0;
  }
  if (in.model.options.heap_laying == GroundModelSpec::HeapLaying::kOnePass) {
    lay_heap_in_one_pass(in, sources, &rings, received, state);
    return;
  }
  for (int p = 0; p < static_cast<int>(portions); ++p) {
    for (const auto& [c, amount] : sources) {
      state->height.at(cell_i(c, g.nx), cell_j(c, g.nx)) += amount / portions;
      (*received)[c] += amount / portions;
    }
    shed_outwards(in, holding, &rings, received, state);
  }
}

// Pockets: uncovered cells of the window that uncovered cells do not join
// to the window's outer ring or the grid's edge.
void find_pockets(ExcessRouting* in) {
  const Grid& g = in->model.grid;
  const Footprint& fp = in->region.fp;
  Footprint& w = in->window;
  w = Footprint{std::max(0, fp.i0 - 1), std::max(0, fp.j0 - 1),
                std::min(g.nx, fp.i0 + fp.ni + 1) - std::max(0, fp.i0 - 1),
                std::min(g.ny, fp.j0 + fp.nj + 1) - std::max(0, fp.j0 - 1)};
  auto at = [&](int i, int j) { return static_cast<std::size_t>((j - w.j0) * w.ni + (i - w.i0)); };
  auto uncovered = [&](int i, int j) { return std::isinf(in->ceiling.at(i, j)); };
  std::vector<char> joined(static_cast<std::size_t>(w.ni) * w.nj, 0);
  std::vector<std::pair<int, int>> queue;
  for (int j = w.j0; j < w.j0 + w.nj; ++j) {
    for (int i = w.i0; i < w.i0 + w.ni; ++i) {
      const bool outer = i == w.i0 || j == w.j0 || i == w.i0 + w.ni - 1 || j == w.j0 + w.nj - 1;
      const bool at_edge = i == 0 || j == 0 || i == g.nx - 1 || j == g.ny - 1;
      if ((outer || at_edge) && uncovered(i, j)) joined[at(i, j)] = 1, queue.emplace_back(i, j);
    }
  }
  for (std::size_t q = 0; q < queue.size(); ++q) {
    for (const auto& o : kNeighbours) {
      const int ni = queue[q].first + o[0], nj = queue[q].second + o[1];
      if (!w.contains(ni, nj) || joined[at(ni, nj)] || !uncovered(ni, nj)) continue;
      joined[at(ni, nj)] = 1;
      queue.emplace_back(ni, nj);
    }
  }
  in->pocket.assign(joined.size(), 0);
  for (int j = w.j0; j < w.j0 + w.nj; ++j) {
    for (int i = w.i0; i < w.i0 + w.ni; ++i) in->pocket[at(i, j)] = uncovered(i, j) && !joined[at(i, j)];
  }
}

}  // namespace

double ExcessRouting::limit_at(int i, int j) const {
  const double c = ceiling.at(i, j);
  if (std::isfinite(c)) return std::max(c, 0.0);  // an underside below the base meets bedrock: the cell stays at 0
  if (!window.contains(i, j)) return c;
  return pocket[static_cast<std::size_t>((j - window.j0) * window.ni + (i - window.i0))] ? crest_m : c;
}

void route_excess(ExcessRouting in, Received* received, GroundState* state) {
  find_pockets(&in);
  for (const Material& m : in.params.materials) in.repose_step_m.push_back(in.model.grid.cell_size_m * std::tan(m.repose_angle_rad));
  for (std::size_t m = 0; m < kNeighbours.size(); ++m) {
    const int oi = kNeighbours[m][0], oj = kNeighbours[m][1];
    in.tier_allows[0][m] = !(in.dir.active && !in.dir.forward(oi, oj)) && !in.dir.backward(oi, oj);
    in.tier_allows[1][m] = !in.dir.backward(oi, oj);
    in.tier_allows[2][m] = true;
  }
  for (std::size_t t = 0; t < in.tier_allows.size(); ++t) {
    for (std::size_t m = 0; m < kNeighbours.size(); ++m) {
      if (in.tier_allows[t][m]) in.tier_dirs[t][static_cast<std::size_t>(in.tier_dir_count[t]++)] = static_cast<int>(m);
    }
  }
  move_under_objects(in, received, state);
  heap_on_open_ground(in, received, state);
}

}  // namespace repose
