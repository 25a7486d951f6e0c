#include "models/heightspan/ground_contact.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "models/ground/ground_model.h"
#include "models/ground/ground_state.h"
#include "models/heightspan/drag_wedge.h"

namespace repose {

CellOffset ground_offset(const Grid& map, const Grid& ground) {
  const double h = ground.cell_size_m;
  return {static_cast<int>(std::floor((map.origin_x_m + 0.5 * h - ground.origin_x_m) / h)),
          static_cast<int>(std::floor((map.origin_y_m + 0.5 * h - ground.origin_y_m) / h))};
}

Underside underside_of(const SpanMap& map, const Grid& ground, double top_m, double shear_layer_m) {
  const CellOffset off = ground_offset(map.grid, ground);
  int i0 = ground.nx, j0 = ground.ny, i1 = -1, j1 = -1;
  for (int j = 0; j < map.grid.ny; ++j) {
    for (int i = 0; i < map.grid.nx; ++i) {
      if (map.count(map.cell(i, j)) == 0 || !ground.contains(i + off.di, j + off.dj)) continue;
      i0 = std::min(i0, i + off.di), i1 = std::max(i1, i + off.di);
      j0 = std::min(j0, j + off.dj), j1 = std::max(j1, j + off.dj);
    }
  }
  Underside u;
  if (i1 < i0) return u;
  u.footprint = Footprint{i0, j0, i1 - i0 + 1, j1 - j0 + 1};
  u.top_m = top_m;
  u.z_m = ArrayXXdR::Constant(u.footprint.nj, u.footprint.ni, std::numeric_limits<double>::infinity());
  for (int gj = j0; gj <= j1; ++gj) {
    for (int gi = i0; gi <= i1; ++gi) {
      const std::int64_t c = map.cell(gi - off.di, gj - off.dj);
      if (map.count(c) > 0) u.z_m(gj - j0, gi - i0) = map.begin(c)[0].bottom_m - shear_layer_m;
    }
  }
  return u;
}

std::array<int, 2> back_step(const Eigen::Vector3d& motion_m) {
  if (!(std::max(std::abs(motion_m.x()), std::abs(motion_m.y())) > 0.0)) return {0, 0};
  if (std::abs(motion_m.x()) >= std::abs(motion_m.y())) return {motion_m.x() > 0.0 ? -1 : 1, 0};
  return {0, motion_m.y() > 0.0 ? -1 : 1};
}

namespace {

// Puts `amount` (m of height) scooped at map cell (i, j) onto its span k
// with its surface at most `level`: it is pushed back into the object, away
// from the way it moves, as far as the spans behind are reachable at that
// level (no solid in the way), and fills them from the farthest forward, each
// up to `level` (and the span above it); what is left stays on span k.
void push_back_into(SpanMap* map, int i, int j, int k, double level, double amount, std::array<int, 2> step) {
  struct Room {
    Span* span;
    double ceiling_m;  // the level it may be filled to
  };
  std::array<Room, 512> chain;
  std::size_t n = 0;
  for (int ci = i + step[0], cj = j + step[1];
       (step[0] != 0 || step[1] != 0) && n < chain.size() && map->grid.contains(ci, cj);
       ci += step[0], cj += step[1]) {
    const std::int64_t c = map->cell(ci, cj);
    const int under = span_under(*map, c, level);
    if (under < 0) break;  // under the object or beyond it: nothing to lie on at this level
    Span* s = map->begin(c) + under;
    if (s->top_m > level) break;  // the level is inside its solid: a wall
    const double ceiling = under + 1 < map->count(c) ? std::min(level, s[1].bottom_m) : level;
    chain[n++] = {s, ceiling};
  }
  for (std::size_t m = n; m-- > 0 && amount > 0.0;) {
    const double put = std::min(std::max(0.0, chain[m].ceiling_m - chain[m].span->level_m()), amount);
    chain[m].span->material_m += put;
    amount -= put;
  }
  map->begin(map->cell(i, j))[k].material_m += amount;
}

// The ground cell in front of the object from map cell (i, j), going
// against `back`: the first with no span of the map over it; false when it
// lies off the ground's grid (or the object does not move sideways).
bool cell_ahead(const SpanMap& map, const Grid& ground, CellOffset off, int i, int j, std::array<int, 2> back,
                int* gi, int* gj) {
  if (back[0] == 0 && back[1] == 0) return false;
  int ci = i - back[0], cj = j - back[1];
  while (map.grid.contains(ci, cj) && map.count(map.cell(ci, cj)) > 0) ci -= back[0], cj -= back[1];
  *gi = ci + off.di, *gj = cj + off.dj;
  return ground.contains(*gi, *gj);
}

}  // namespace

double take_up_ground(const GroundModel& model, SpanMap* map, GroundState* state, const Eigen::Vector3d& motion_m,
                      Intake intake, LipWedge lip) {
  const Grid& g = model.grid;
  const CellOffset off = ground_offset(map->grid, g);
  const std::array<int, 2> back = back_step(motion_m);
  double moved = 0.0;
  for (int j = 0; j < map->grid.ny; ++j) {
    for (int i = 0; i < map->grid.nx; ++i) {
      const std::int64_t c = map->cell(i, j);
      const int n = map->count(c);
      const int gi = i + off.di, gj = j + off.dj;
      if (n == 0 || !g.contains(gi, gj)) continue;
      double& h = state->height.at(gi, gj);
      Span* s = map->begin(c);
      if (!(h > s[0].top_m)) continue;
      // the ground's material is [0, h]; each piece above the lowest top goes onto a span
      auto piece = [&](double lo, double hi) { return std::max(0.0, std::min(h, hi) - std::max(lo, 0.0)); };
      double ahead = 0.0;  // pushed in front of the object (above the intake layer)
      int ai = 0, aj = 0;
      for (int k = 0; k < n; ++k) {
        const double gap_top = k + 1 < n ? s[k + 1].bottom_m : std::numeric_limits<double>::infinity();
        double scooped = piece(s[k].top_m, gap_top);
        const double admitted = std::min(intake.fraction * scooped, intake.layer_m);
        if (k == 0 && admitted < scooped && cell_ahead(*map, g, off, i, j, back, &ai, &aj)) {
          ahead = scooped - admitted;
          scooped = admitted;
        }
        if (scooped > 0.0) push_back_into(map, i, j, k, std::min(h, gap_top), scooped, back);
        if (k + 1 < n) s[k + 1].material_m += piece(s[k + 1].bottom_m, s[k + 1].top_m);  // out of the solid
      }
      const double left = std::clamp(s[0].top_m, 0.0, h);
      moved += (h - left - ahead) * g.cell_area_m2();
      h = left;
      if (ahead > 0.0) {
        const double kept = lip.wedge != nullptr ? lip.fraction * ahead : 0.0;  // m of height
        if (kept > 0.0) keep_pushed_ahead(kept * g.cell_area_m2(), back, lip.wedge);
        if (ahead - kept > 0.0) {
          state->height.at(ai, aj) += ahead - kept;
          state->erosion.touch(model.cell(ai, aj));
        }
      }
      push_overflow_up(map, c);
      state->erosion.touch(model.cell(gi, gj));
    }
  }
  return moved;
}

}  // namespace repose
