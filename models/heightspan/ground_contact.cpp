#include "models/heightspan/ground_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/ground/ground_model.h"
#include "models/ground/ground_state.h"

namespace repose {

CellOffset ground_offset(const Grid& map, const Grid& ground) {
  const double h = ground.cell_size_m;
  return {static_cast<int>(std::floor((map.origin_x_m + 0.5 * h - ground.origin_x_m) / h)),
          static_cast<int>(std::floor((map.origin_y_m + 0.5 * h - ground.origin_y_m) / h))};
}

Underside underside_of(const SpanMap& map, const Grid& ground, double top_m) {
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
      if (map.count(c) > 0) u.z_m(gj - j0, gi - i0) = map.begin(c)[0].bottom_m;
    }
  }
  return u;
}

double take_up_ground(const GroundModel& model, SpanMap* map, GroundState* state) {
  const Grid& g = model.grid;
  const CellOffset off = ground_offset(map->grid, g);
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
      for (int k = 0; k < n; ++k) {
        const double gap_top = k + 1 < n ? s[k + 1].bottom_m : std::numeric_limits<double>::infinity();
        s[k].material_m += piece(s[k].top_m, gap_top);                                // scooped
        if (k + 1 < n) s[k + 1].material_m += piece(s[k + 1].bottom_m, s[k + 1].top_m);  // out of the solid
      }
      const double left = std::clamp(s[0].top_m, 0.0, h);
      moved += (h - left) * g.cell_area_m2();
      h = left;
      push_overflow_up(map, c);
      state->erosion.touch(model.cell(gi, gj));
    }
  }
  return moved;
}

}  // namespace repose
