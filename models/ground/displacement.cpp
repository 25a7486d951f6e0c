#include "models/ground/displacement.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <vector>

#include "models/core/base/error.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"

namespace repose {

namespace {

constexpr std::array<std::array<int, 2>, 4> kNeighbours = {{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
constexpr double kDirectionEps = 1e-9;

// The in-plane direction of a drag, with negligible components snapped to 0.
struct DragDirection {
  bool active = false;
  double dx = 0.0, dy = 0.0;
  bool backward(int oi, int oj) const { return active && oi * dx + oj * dy < -kDirectionEps; }
};

DragDirection drag_direction(const Eigen::Vector3d& motion_m, double cell_size_m) {
  DragDirection d;
  if (!is_drag(motion_m, 1e-3 * cell_size_m)) return d;
  const double n = motion_m.head<2>().norm();
  d.active = true;
  d.dx = std::abs(motion_m.x() / n) < kDirectionEps ? 0.0 : motion_m.x() / n;
  d.dy = std::abs(motion_m.y() / n) < kDirectionEps ? 0.0 : motion_m.y() / n;
  return d;
}

// Local arrays over the footprint of one contact.
struct ContactRegion {
  Footprint fp;
  std::vector<int> dist;  // 0: free cell; >= 1: contact cell, distance to the border
  std::vector<double> carry;
  std::vector<int> cells;  // local indices of contact cells
  int local(int i, int j) const { return (j - fp.j0) * fp.ni + (i - fp.i0); }
  int gi(int l) const { return fp.i0 + l % fp.ni; }
  int gj(int l) const { return fp.j0 + l / fp.ni; }
  bool is_contact(int i, int j) const { return fp.contains(i, j) && dist[local(i, j)] != 0; }
};

// Removes dh' from colliding cells; returns the region with alpha*dh' carried.
ContactRegion remove_intersection(const GroundModel& model, const GroundParams& params, const Underside& contact,
                                  GroundState* state, DisplacementResult* result) {
  ContactRegion r;
  r.fp = contact.footprint;
  const int n = r.fp.ni * r.fp.nj;
  r.dist.assign(n, 0);
  r.carry.assign(n, 0.0);
  const double area = model.grid.cell_area_m2();
  for (int l = 0; l < n; ++l) {
    const int i = r.gi(l), j = r.gj(l);
    const double under = contact.z_m(j - r.fp.j0, i - r.fp.i0);
    double& h = state->height.at(i, j);
    if (!(under < h)) continue;
    const double dh = h - under;
    const double alpha = params.materials[model.material_at(model.cell(i, j))].alpha;
    h = under;
    r.carry[l] = alpha * dh;
    r.dist[l] = -1;
    r.cells.push_back(l);
    state->ledger.compressed_m3 += (1.0 - alpha) * dh * area;
    result->removed_m3 += dh * area;
    result->displaced_m3 += alpha * dh * area;
  }
  return r;
}

// Multi-source BFS: distance 1 for contact cells next to a free cell or the grid edge.
void distance_to_border(const Grid& grid, ContactRegion* r) {
  std::vector<int> queue;
  for (const int l : r->cells) {
    const int i = r->gi(l), j = r->gj(l);
    for (const auto& o : kNeighbours) {
      const int ni = i + o[0], nj = j + o[1];
      if (!grid.contains(ni, nj) || !r->fp.contains(ni, nj) || r->dist[r->local(ni, nj)] == 0) {
        r->dist[l] = 1;
        queue.push_back(l);
        break;
      }
    }
  }
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const int l = queue[q];
    const int i = r->gi(l), j = r->gj(l);
    for (const auto& o : kNeighbours) {
      const int ni = i + o[0], nj = j + o[1];
      if (!r->fp.contains(ni, nj)) continue;
      const int m = r->local(ni, nj);
      if (r->dist[m] != -1) continue;
      r->dist[m] = r->dist[l] + 1;
      queue.push_back(m);
    }
  }
}

// Where displaced material goes: a contact cell (carried on), a free cell
// (deposited), or off the grid (left).
struct Sink {
  const GroundModel& model;
  GroundState* state;
  ContactRegion* region;
  std::vector<std::int64_t>* deposits;
  void give(int i, int j, double amount) {
    if (!model.grid.contains(i, j)) {
      state->ledger.left_grid_m3 += amount * model.grid.cell_area_m2();
    } else if (region->is_contact(i, j)) {
      region->carry[region->local(i, j)] += amount;
    } else {
      state->height.at(i, j) += amount;
      deposits->push_back(model.cell(i, j));
    }
  }
};

void spread_from_inside_out(ContactRegion* r, Sink* sink) {
  std::vector<int> order = r->cells;
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return r->dist[a] > r->dist[b]; });
  for (const int l : order) {
    const double m = r->carry[l];
    if (m == 0.0) continue;
    const int i = r->gi(l), j = r->gj(l), d = r->dist[l];
    int targets[4][2];
    int k = 0;
    for (const auto& o : kNeighbours) {
      const int ni = i + o[0], nj = j + o[1];
      const int nd = r->is_contact(ni, nj) ? r->dist[r->local(ni, nj)] : 0;
      if (nd == d - 1) targets[k][0] = ni, targets[k][1] = nj, ++k;
    }
    REPOSE_DEMAND(k > 0);  // the distance transform gives every contact cell a nearer neighbour
    for (int t = 0; t < k; ++t) sink->give(targets[t][0], targets[t][1], m / k);
  }
}

void spread_rear_to_front(const DragDirection& dir, ContactRegion* r, Sink* sink) {
  std::vector<int> order = r->cells;
  auto along = [&](int l) { return r->gi(l) * dir.dx + r->gj(l) * dir.dy; };
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) {
    const double sa = along(a), sb = along(b);
    if (sa != sb) return sa < sb;
    return r->dist[a] > r->dist[b];  // sideways: from the inside towards the border
  });
  std::vector<int> rank(r->dist.size(), 0);
  for (std::size_t k = 0; k < order.size(); ++k) rank[order[k]] = static_cast<int>(k);
  for (const int l : order) {
    const double m = r->carry[l];
    if (m == 0.0) continue;
    const int i = r->gi(l), j = r->gj(l);
    int targets[4][2];
    int k = 0;
    for (const auto& o : kNeighbours) {
      if (dir.backward(o[0], o[1])) continue;
      const int ni = i + o[0], nj = j + o[1];
      if (r->is_contact(ni, nj) && rank[r->local(ni, nj)] < rank[l]) continue;
      targets[k][0] = ni, targets[k][1] = nj, ++k;
    }
    REPOSE_DEMAND(k > 0);  // the forward neighbour always qualifies
    for (int t = 0; t < k; ++t) sink->give(targets[t][0], targets[t][1], m / k);
  }
}

void sort_unique(std::vector<std::int64_t>* v) {
  std::sort(v->begin(), v->end());
  v->erase(std::unique(v->begin(), v->end()), v->end());
}

// Moves material above the ceiling further out: towards the nearest cell no
// object covers, level by level (level = 4-neighbour distance to such a cell
// through cells that are not in contact), from the farthest level down, so
// the result does not depend on visiting order.
void push_excess_outwards(const GroundModel& model, const Ceiling& ceiling, const DragDirection& dir,
                          const ContactRegion& r, const std::vector<std::int64_t>& deposits, GroundState* state,
                          std::vector<std::int64_t>* touched) {
  const Grid& g = model.grid;
  auto excess_at = [&](int i, int j) { return state->height.at(i, j) - ceiling.at(i, j); };
  bool any = false;
  for (const std::int64_t c : deposits) any = any || excess_at(static_cast<int>(c % g.nx), static_cast<int>(c / g.nx)) > 0.0;
  if (!any) return;

  // the footprint and one ring around it: cells of the ring lie under no other
  // object (objects with touching footprints share one region)
  const Footprint w{std::max(0, r.fp.i0 - 1), std::max(0, r.fp.j0 - 1),
                    std::min(g.nx, r.fp.i0 + r.fp.ni + 1) - std::max(0, r.fp.i0 - 1),
                    std::min(g.ny, r.fp.j0 + r.fp.nj + 1) - std::max(0, r.fp.j0 - 1)};
  auto wl = [&](int i, int j) { return static_cast<std::size_t>((j - w.j0) * w.ni + (i - w.i0)); };
  std::vector<int> level(static_cast<std::size_t>(w.ni) * w.nj, -1);
  std::vector<std::pair<int, int>> queue;
  for (int j = w.j0; j < w.j0 + w.nj; ++j) {
    for (int i = w.i0; i < w.i0 + w.ni; ++i) {
      if (r.is_contact(i, j)) continue;
      const bool open = std::isinf(ceiling.at(i, j));
      const bool at_edge = i == 0 || j == 0 || i == g.nx - 1 || j == g.ny - 1;  // next to the open boundary
      if (open || at_edge) {
        level[wl(i, j)] = open ? 0 : 1;
        queue.emplace_back(i, j);
      }
    }
  }
  std::stable_sort(queue.begin(), queue.end(), [&](const auto& a, const auto& b) {
    return level[wl(a.first, a.second)] < level[wl(b.first, b.second)];
  });
  for (std::size_t q = 0; q < queue.size(); ++q) {
    const auto [i, j] = queue[q];
    for (const auto& o : kNeighbours) {
      const int ni = i + o[0], nj = j + o[1];
      if (!w.contains(ni, nj) || r.is_contact(ni, nj) || level[wl(ni, nj)] != -1) continue;
      level[wl(ni, nj)] = level[wl(i, j)] + 1;
      queue.emplace_back(ni, nj);
    }
  }

  // A deposit that only contact cells separate from open ground (a hole that
  // another object dug below this one's underside) would keep its excess: only
  // then, the levels go on through the contact cells, which sit at the
  // ceiling and so pass on whatever they are given.
  bool enclosed = false;
  for (const std::int64_t c : deposits) {
    const int i = static_cast<int>(c % g.nx), j = static_cast<int>(c / g.nx);
    enclosed = enclosed || (w.contains(i, j) && level[wl(i, j)] == -1 && excess_at(i, j) > 0.0);
  }
  for (std::size_t q = 0; enclosed && q < queue.size(); ++q) {
    const auto [i, j] = queue[q];
    for (const auto& o : kNeighbours) {
      const int ni = i + o[0], nj = j + o[1];
      if (!w.contains(ni, nj) || level[wl(ni, nj)] != -1) continue;
      level[wl(ni, nj)] = level[wl(i, j)] + 1;
      queue.emplace_back(ni, nj);
    }
  }

  int top = 0;
  std::vector<std::vector<std::int64_t>> by_level(1);
  auto enqueue = [&](int i, int j) {
    const int k = level[wl(i, j)];
    if (k <= 0) return;  // open cells take anything; unreachable cells keep their excess
    if (k >= static_cast<int>(by_level.size())) by_level.resize(static_cast<std::size_t>(k) + 1);
    by_level[static_cast<std::size_t>(k)].push_back(model.cell(i, j));
    top = std::max(top, k);
  };
  for (const std::int64_t c : deposits) enqueue(static_cast<int>(c % g.nx), static_cast<int>(c / g.nx));

  const double area = g.cell_area_m2();
  for (int k = top; k >= 1; --k) {
    std::vector<std::int64_t>& cells = by_level[static_cast<std::size_t>(k)];
    sort_unique(&cells);
    for (const std::int64_t c : cells) {
      const int i = static_cast<int>(c % g.nx), j = static_cast<int>(c / g.nx);
      const double e = excess_at(i, j);
      if (!(e > 0.0)) continue;
      int targets[4][2];
      int n = 0;
      // not backwards while dragging, unless backwards is the only way out:
      // staying under the object would be worse than moving back
      for (const bool allow_backward : {false, true}) {
        for (const auto& o : kNeighbours) {
          if (!allow_backward && dir.backward(o[0], o[1])) continue;
          const int ni = i + o[0], nj = j + o[1];
          const bool nearer = g.contains(ni, nj) ? w.contains(ni, nj) && level[wl(ni, nj)] == k - 1 : k == 1;
          if (nearer) targets[n][0] = ni, targets[n][1] = nj, ++n;
        }
        if (n > 0) break;
      }
      if (n == 0) continue;  // cannot happen for k >= 1 (BFS), kept for safety
      state->height.at(i, j) -= e;
      for (int t = 0; t < n; ++t) {
        const int ni = targets[t][0], nj = targets[t][1];
        if (!g.contains(ni, nj)) {
          state->ledger.left_grid_m3 += e / n * area;
          continue;
        }
        state->height.at(ni, nj) += e / n;
        touched->push_back(model.cell(ni, nj));
        enqueue(ni, nj);
      }
    }
  }
}

}  // namespace

bool is_drag(const Eigen::Vector3d& motion_m, double min_horizontal_m) {
  return motion_m.head<2>().norm() > min_horizontal_m && motion_m.z() >= 0.0;
}

DisplacementResult displace(const GroundModel& model, const GroundParams& params, const Underside& contact,
                            const Ceiling& ceiling, const Eigen::Vector3d& motion_m, GroundState* state) {
  DisplacementResult result;
  if (contact.empty()) return result;
  ContactRegion region = remove_intersection(model, params, contact, state, &result);
  result.contact_cells = static_cast<int>(region.cells.size());
  if (region.cells.empty()) return result;
  distance_to_border(model.grid, &region);

  std::vector<std::int64_t> deposits;
  Sink sink{model, state, &region, &deposits};
  const DragDirection dir = drag_direction(motion_m, model.grid.cell_size_m);
  if (dir.active) {
    spread_rear_to_front(dir, &region, &sink);
  } else {
    spread_from_inside_out(&region, &sink);
  }
  sort_unique(&deposits);
  std::vector<std::int64_t> touched = deposits;
  push_excess_outwards(model, ceiling, dir, region, deposits, state, &touched);

  for (const int l : region.cells) state->erosion.touch(model.cell(region.gi(l), region.gj(l)));
  for (const std::int64_t c : touched) state->erosion.touch(c);
  return result;
}

}  // namespace repose
