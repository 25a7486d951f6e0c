#include "models/ground/heap_in_one_pass.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/ground/ground_model.h"
#include "models/ground/ground_state.h"
#include "models/ground/heap_rings.h"

namespace repose {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// The least step sums phi over the ranks, grown ring by ring, and the
// levels at which the ground beyond the grid's edge takes everything.
struct StepSums {
  const ExcessRouting& in;
  Rings& rings;
  const double* h;  // the heights, the sources' material taken off
  std::vector<double> phi{};         // per rank; +inf: not reached
  std::vector<double> sink_levels{};  // ground beyond the edge + phi
  int done = 0;                       // ranks propagated

  // A step at least the crest changes nothing (a cell reaches the crest
  // before its neighbour takes anything either way): capped there, so that
  // theta = 90 deg keeps the levels' precision.
  double step_of_material(std::size_t m) const {
    return std::min(in.repose_step_m[m], std::max(in.crest_m, in.model.grid.cell_size_m));
  }
  double step_of(std::int64_t c) const { return step_of_material(static_cast<std::size_t>(in.model.material_at(c))); }
  // Propagates every rank up to ring `last`: each reached cell to the
  // neighbours it may pass to (excess_routing.cpp, shed_of: the same tiers).
  void propagate(int last) {
    rings.at(last + 1);  // the onward neighbours have ranks
    phi.resize(static_cast<std::size_t>(rings.ranked()), kInf);
    const Grid& g = in.model.grid;
    for (; done < rings.ranked() && rings.ring_of_rank(done) <= last; ++done) {
      const double from = phi[static_cast<std::size_t>(done)];
      if (from == kInf) continue;
      const int i = rings.i_of_rank(done), j = rings.j_of_rank(done), k = rings.ring_of_rank(done);
      const std::int64_t c = rings.cell_of_rank(done);
      const double to = from + step_of(c);
      for (const auto& allows : in.tier_allows) {
        int n = 0;
        for (std::size_t m = 0; m < kNeighbours.size(); ++m) {
          if (!allows[m]) continue;
          const int ni = i + kNeighbours[m][0], nj = j + kNeighbours[m][1];
          if (!g.contains(ni, nj)) {
            sink_levels.push_back(h[c] + to), ++n;  // beyond the edge: as the edge was
          } else if (onward(rings, i, j, k, ni, nj)) {
            double& p = phi[static_cast<std::size_t>(rings.rank(ni, nj))];
            p = std::min(p, to), ++n;
          }
        }
        if (n > 0) break;
      }
    }
  }
  double ground(int r) const { return h[rings.cell_of_rank(r)]; }
};

enum class Fit { kFits, kLeaves, kFull };

// The level L at which the reached cells take `volume_m` (m of height summed
// over cells), or the level at which the ground beyond the edge takes the
// rest (kLeaves), or the highest level when every cell is at the crest
// (kFull). Sum over cells of clamp(L - phi - ground, 0, crest - ground):
// piecewise linear in L, solved from its sorted breakpoints.
std::pair<double, Fit> level_for(const StepSums& s, double crest_m, double volume_m) {
  std::vector<std::pair<double, int>> events;  // level, +1: starts taking, -1: full, 0: the edge takes all
  for (int r = 0; r < s.done; ++r) {
    const double p = s.phi[static_cast<std::size_t>(r)], g = s.ground(r);
    if (p == kInf || !(crest_m > g)) continue;
    events.emplace_back(g + p, 1);
    events.emplace_back(crest_m + p, -1);
  }
  for (const double level : s.sink_levels) events.emplace_back(level, 0);
  std::sort(events.begin(), events.end());
  double f = 0.0, level = -kInf;
  int slope = 0;
  for (const auto& [at, kind] : events) {
    if (slope > 0) {
      const double next = f + slope * (at - level);
      if (next >= volume_m) return {level + (volume_m - f) / slope, Fit::kFits};
      f = next;
    }
    level = at;
    if (kind == 0) return {level, Fit::kLeaves};
    slope += kind;
  }
  return {level, Fit::kFull};
}

// What rank r takes at level L.
double taken(const StepSums& s, int r, double crest_m, double level) {
  const double p = s.phi[static_cast<std::size_t>(r)];
  return p == kInf ? 0.0 : std::max(0.0, std::min(crest_m, level - p) - s.ground(r));
}

}  // namespace

void lay_heap_in_one_pass(const ExcessRouting& in, const std::vector<std::pair<std::int64_t, double>>& sources,
                          Rings* rings, Received* received, GroundState* state) {
  double volume_m = 0.0;
  for (const auto& [c, amount] : sources) volume_m += amount;
  if (!(volume_m > 0.0)) return;
  double* h = state->height.heights().data();
  StepSums sums{in, *rings, h};
  int last = 0;
  for (const auto& [c, amount] : sources) last = std::max(last, rings->of(c));
  rings->at(last);
  sums.phi.assign(static_cast<std::size_t>(rings->ranked()), kInf);
  for (const auto& [c, amount] : sources) sums.phi[static_cast<std::size_t>(rings->rank(c))] = 0.0;
  double least_step = kInf;
  for (std::size_t m = 0; m < in.repose_step_m.size(); ++m) least_step = std::min(least_step, sums.step_of_material(m));
  std::pair<double, Fit> fit;
  for (int add = 4;;) {
    last += add;
    sums.propagate(last);
    fit = level_for(sums, in.crest_m, volume_m);
    double outer_m = 0.0;  // the most a cell of the outer ring takes
    for (int r = sums.done - 1; r >= 0 && rings->ring_of_rank(r) == last; --r) {
      outer_m = std::max(outer_m, taken(sums, r, in.crest_m, fit.first));
    }
    if (!(outer_m > 0.0) || rings->at(last + 1).empty()) break;
    // on level ground the heap ends within outer_m / step rings more (the level only falls as rings join)
    add = 1 + static_cast<int>(std::min(std::ceil(outer_m / least_step), 4096.0));
  }
  std::vector<double> take(static_cast<std::size_t>(sums.done), 0.0);
  double laid_m = 0.0;
  int largest = -1;
  for (int r = 0; r < sums.done; ++r) {
    take[static_cast<std::size_t>(r)] = taken(sums, r, in.crest_m, fit.first);
    laid_m += take[static_cast<std::size_t>(r)];
    if (largest < 0 || take[static_cast<std::size_t>(r)] > take[static_cast<std::size_t>(largest)]) largest = r;
  }
  const double rest_m = volume_m - laid_m;  // round-off when it fits
  if (fit.second == Fit::kLeaves) {
    state->ledger.left_grid_m3 += rest_m * in.model.grid.cell_area_m2();
  } else if (fit.second == Fit::kFits) {
    take[static_cast<std::size_t>(largest)] += rest_m;
  } else {  // nowhere to go: the rest stays on the sources, in proportion
    for (const auto& [c, amount] : sources) take[static_cast<std::size_t>(rings->rank(c))] += rest_m * amount / volume_m;
  }
  for (int r = 0; r < sums.done; ++r) {
    const double t = take[static_cast<std::size_t>(r)];
    if (t == 0.0) continue;
    const std::int64_t c = rings->cell_of_rank(r);
    h[c] += t;
    (*received)[c] += t;
  }
}

}  // namespace repose
