#include "models/ground/erosion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <type_traits>
#include <utility>
#include <vector>

#include "models/core/base/error.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"

namespace repose {

namespace {

constexpr std::array<std::array<int, 2>, 4> kNeighbours = {{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};

using Flux = ErosionFlux;

// Per material: the height difference a pair may have, sigma and En.
struct PairRule {
  double max_dh_m;
  double sigma;
  int passes;
};

std::vector<PairRule> pair_rules(const Grid& g, const GroundParams& params) {
  std::vector<PairRule> rules;
  for (const Material& m : params.materials) {
    rules.push_back({g.cell_size_m * std::tan(m.repose_angle_rad), m.sigma, m.erosion_passes(g.cell_size_m)});
  }
  return rules;
}

// Groups the fluxes listed in `groups` (cell, flux index) by cell and
// scales each group down to what its cell can take or give,
// `capacity(cell, first flux of the group)` >= 0. A sorted list, not a hash
// map, so that a pass allocates nothing (`groups` is scratch kept between
// passes) and each group sums in flux order.
template <typename Capacity>
void scale_groups(std::vector<Flux>* fluxes, std::vector<std::pair<std::int64_t, std::size_t>>* groups,
                  Capacity capacity) {
  std::vector<Flux>& fx = *fluxes;
  std::sort(groups->begin(), groups->end());
  for (std::size_t first = 0, last = 0; first < groups->size(); first = last) {
    const std::int64_t cell = (*groups)[first].first;
    double total = 0.0;
    for (last = first; last < groups->size() && (*groups)[last].first == cell; ++last) {
      total += fx[(*groups)[last].second].amount;
    }
    const double allowed = capacity(cell, fx[(*groups)[first].second]);
    if (!(total > allowed)) continue;
    const double scale = allowed / total;
    for (std::size_t k = first; k < last; ++k) fx[(*groups)[k].second].amount *= scale;
  }
}

// Never above an object: scales the inflow of each capped cell (one under
// an object) down to its room. `inflow` is per cell, all 0 between calls:
// each capped cell's inflow is summed there in flux order (as a group of
// the cell's fluxes would be) and read; apply_fluxes clears it again (one
// loop over the fluxes fewer), so a pass costs what flows, not the grid's
// size, and sorts nothing. Returns whether any flux is capped (ends under
// an object): when none is, nothing was summed and there is nothing to clear.
bool cap_inflow(const double* h, std::vector<Flux>* fluxes, std::vector<double>* inflow) {
  std::vector<double>& in = *inflow;
  bool any = false;
  for (const Flux& f : *fluxes) {
    if (std::isfinite(f.ceiling_m)) in[static_cast<std::size_t>(f.to)] += f.amount, any = true;
  }
  if (!any) return false;
  for (Flux& f : *fluxes) {
    if (!std::isfinite(f.ceiling_m)) continue;
    const double total = in[static_cast<std::size_t>(f.to)], allowed = std::max(0.0, f.ceiling_m - h[f.to]);
    if (total > allowed) f.amount *= allowed / total;
  }
  return true;
}

// The state's per-cell inflow scratch (all 0), sized to the grid.
std::vector<double>& inflow_scratch(const Grid& g, GroundState* state) {
  std::vector<double>& inflow = state->erosion_scratch.inflow_m;
  if (inflow.size() != g.cell_count()) inflow.assign(g.cell_count(), 0.0);
  return inflow;
}

// Moves each flux's material and remembers both cells of every move, in
// flux order (touching cells changes nothing the moves read, so one loop
// does both). The inclined rule floors a drained cell at the base, so a
// cell emptied to round-off ends at 0, not 1 ulp below it. `inflow` given
// (cap_inflow summed into it): each capped flux's entry is cleared back to
// 0 on the way. Returns the moves made.
enum class FloorAtZero { kNo, kYes };
long long apply_fluxes(const std::vector<Flux>& fluxes, FloorAtZero floor, double* h, ErosionMemory* memory,
                       std::vector<double>* inflow) {
  long long moves = 0;
  double* in = inflow == nullptr ? nullptr : inflow->data();
  for (const Flux& f : fluxes) {
    if (in != nullptr && std::isfinite(f.ceiling_m)) in[f.to] = 0.0;
    if (!(f.amount > 0.0)) continue;
    h[f.from] = floor == FloorAtZero::kYes ? std::max(0.0, h[f.from] - f.amount) : h[f.from] - f.amount;
    h[f.to] += f.amount;
    ++moves;
    memory->touch(f.from);
    memory->touch(f.to);
  }
  return moves;
}

// Inclined bed (erosion.h): per material, the height differences a pair
// may have. Along x, d = h(i+1) - h(i) in [lo, hi]; along y, |d| <= across.
struct InclinedRule {
  double lo_m, hi_m, across_m;
  double sigma;
  int passes;
};

InclinedRule inclined_rule(const Material& m, double slope_rad, double cell_m) {
  const double theta = m.repose_angle_rad;
  const double hi = slope_rad + theta < std::numbers::pi / 2 ? cell_m * std::tan(slope_rad + theta)
                                                             : std::numeric_limits<double>::infinity();
  return {cell_m * std::tan(slope_rad - theta), hi, cell_m * std::tan(theta) / std::cos(slope_rad), m.sigma,
          m.erosion_passes(cell_m)};
}

// The flux of the pair (a, b), b the neighbour at +x (along_x) or +y of a:
// sigma times the excess over the pair's limits, from the cell that loses,
// or none. Each side's own material decides whether it loses.
bool inclined_flux(const std::vector<InclinedRule>& rules, int material_a, int material_b, bool along_x, double ha,
                   double hb, double tolerance_m, int pass, std::int64_t a, std::int64_t b, Flux* flux) {
  const double d = hb - ha;
  const InclinedRule& ra = rules[static_cast<std::size_t>(material_a)];
  const InclinedRule& rb = rules[static_cast<std::size_t>(material_b)];
  const double a_limit = along_x ? ra.lo_m : -ra.across_m;  // a loses below it
  const double b_limit = along_x ? rb.hi_m : rb.across_m;   // b loses above it
  if (pass < ra.passes && a_limit - d > tolerance_m && ha > 0.0) {
    *flux = {a, b, ra.sigma * (a_limit - d), 0.0};
    return true;
  }
  if (pass < rb.passes && d - b_limit > tolerance_m && hb > 0.0) {
    *flux = {b, a, rb.sigma * (d - b_limit), 0.0};
    return true;
  }
  return false;
}

// On an inclined bed a pass may ask a cell for more than it holds (a thin
// layer on a slope steeper than the angle of repose flows on): each cell's
// outflow is scaled down to its material.
void cap_outflow(const double* h, std::vector<Flux>* fluxes, std::vector<std::pair<std::int64_t, std::size_t>>* by_source) {
  by_source->clear();
  for (std::size_t k = 0; k < fluxes->size(); ++k) by_source->emplace_back((*fluxes)[k].from, k);
  scale_groups(fluxes, by_source, [h](std::int64_t cell, const Flux&) { return std::max(0.0, h[cell]); });
}

ErosionResult erode_inclined(const GroundModel& model, const GroundParams& params, const Ceiling& ceiling,
                             GroundState* state) {
  ErosionResult result;
  const Grid& g = model.grid;
  std::vector<InclinedRule> rules;
  int passes = 0;
  for (const Material& m : params.materials) {
    rules.push_back(inclined_rule(m, model.options.bed_slope_rad, g.cell_size_m));
    passes = std::max(passes, m.erosion_passes(g.cell_size_m));
  }
  const double tolerance_m = kErosionToleranceFraction * g.cell_size_m;
  double* h = state->height.heights().data();
  ErosionMemory& memory = state->erosion;
  std::vector<Flux> fluxes;
  std::vector<std::pair<std::int64_t, std::size_t>> scratch;
  std::vector<double>& inflow = inflow_scratch(g, state);
  for (int p = 0; p < passes && !memory.empty(); ++p) {
    fluxes.clear();
    for (const std::int64_t c : memory.cells()) {
      const int i = static_cast<int>(c % g.nx), j = static_cast<int>(c / g.nx);
      for (const auto& o : kNeighbours) {
        const int ni = i + o[0], nj = j + o[1];
        if (!g.contains(ni, nj)) continue;  // closed boundary
        const std::int64_t n = model.cell(ni, nj);
        if (n < c && memory.contains(n)) continue;  // each pair once
        ++result.pair_visits;
        const bool n_after = o[0] + o[1] > 0;  // n is at +x or +y of c
        const std::int64_t a = n_after ? c : n, b = n_after ? n : c;
        Flux f;
        if (!inclined_flux(rules, model.material_at(a), model.material_at(b), o[0] != 0, h[a], h[b], tolerance_m, p,
                           a, b, &f)) {
          continue;
        }
        f.ceiling_m = f.to == n ? ceiling.at(ni, nj) : ceiling.at(i, j);
        fluxes.push_back(f);
      }
    }
    if (fluxes.empty()) break;
    result.passes = p + 1;
    cap_outflow(h, &fluxes, &scratch);
    const bool capped = cap_inflow(h, &fluxes, &inflow);
    result.moves += apply_fluxes(fluxes, FloorAtZero::kYes, h, &memory, capped ? &inflow : nullptr);
  }
  return result;
}

// One pass's fluxes on a level bed from the pairs of the remembered cells:
// each pair once (a neighbour before the cell in storage is skipped when it
// is remembered too: it visits the pair itself), the cells in memory order,
// each cell's neighbours at +x, -x, +y, -y; a flux from the higher cell of
// a pair whose difference exceeds its rule by more than the tolerance.
// Two loops: the first finds the pairs whose difference exceeds the
// smallest rule (most pairs are within their limits, and only these look
// their rule up) with nothing but local values in reach, writing them to a
// buffer it cannot alias; the second makes their fluxes, in the same order.
struct PairScan {
  const GroundModel& model;
  const std::vector<PairRule>& rules;
  const Ceiling& ceiling;
  const ErosionMemory& memory;
  const double* h;
  double tolerance_m;
  int pass;
  bool one_material;
  std::vector<Flux>* fluxes;
  double min_max_dh_m;  // the smallest of the rules' max_dh_m
  long long visits = 0;

  // A pair to look at: memory cell k's neighbour in direction `dir`
  // (0..3: +x, -x, +y, -y).
  using Candidate = std::array<std::int32_t, 2>;

  // The memory's cells (ij: their (i, j) and whether they are off the grid's edge); `candidates` is scratch.
  void cells(const std::vector<std::int64_t>& cs, const std::vector<std::array<int, 3>>& ij,
             std::vector<Candidate>* candidates) {
    if (candidates->size() < 4 * cs.size()) candidates->resize(4 * cs.size());
    const std::size_t found = over_limit(cs, ij, candidates->data());
    const std::int64_t nx = model.grid.nx;
    const std::array<std::int64_t, 4> step = {1, -1, nx, -nx};
    for (std::size_t q = 0; q < found; ++q) {
      const Candidate& cand = (*candidates)[q];
      const std::int64_t c = cs[static_cast<std::size_t>(cand[0])];
      const int i = ij[static_cast<std::size_t>(cand[0])][0], j = ij[static_cast<std::size_t>(cand[0])][1];
      const auto& o = kNeighbours[static_cast<std::size_t>(cand[1])];
      add(c, i, j, c + step[static_cast<std::size_t>(cand[1])], i + o[0], j + o[1]);
    }
  }

  // The pairs whose difference exceeds the smallest limit by more than the
  // tolerance (no flux otherwise, whichever cell is higher), in visiting order.
  std::size_t over_limit(const std::vector<std::int64_t>& cs, const std::vector<std::array<int, 3>>& ij,
                         Candidate* out) {
    const int nx = model.grid.nx, ny = model.grid.ny;  // closed boundary: no pair leaves the grid
    const double* hh = h;
    const double lim = min_max_dh_m, tol = tolerance_m;
    const ErosionMemory& mem = memory;
    std::size_t found = 0;
    long long seen = 0;
    // one cell's pairs; `inner` (a cell off the grid's edge: all four neighbours on it) known at compile time
    // where it is true, so that the edge tests drop out for most cells
    auto scan = [&](auto inner, std::size_t k) {
      const std::int64_t c = cs[k];
      const double hc = hh[c];
      const std::int32_t kk = static_cast<std::int32_t>(k);
      if (inner || ij[k][0] + 1 < nx) {
        ++seen;
        if (std::abs(hc - hh[c + 1]) - lim > tol) out[found++] = {kk, 0};
      }
      if ((inner || ij[k][0] > 0) && !mem.contains(c - 1)) {
        ++seen;
        if (std::abs(hc - hh[c - 1]) - lim > tol) out[found++] = {kk, 1};
      }
      if (inner || ij[k][1] + 1 < ny) {
        ++seen;
        if (std::abs(hc - hh[c + nx]) - lim > tol) out[found++] = {kk, 2};
      }
      if ((inner || ij[k][1] > 0) && !mem.contains(c - nx)) {
        ++seen;
        if (std::abs(hc - hh[c - nx]) - lim > tol) out[found++] = {kk, 3};
      }
    };
    for (std::size_t k = 0; k < cs.size(); ++k) {
      if (ij[k][2] != 0) {
        scan(std::true_type{}, k);
      } else {
        scan(std::false_type{}, k);
      }
    }
    visits += seen;
    return found;
  }

  void add(std::int64_t c, int i, int j, std::int64_t n, int ni, int nj) {
    const double d = std::abs(h[c] - h[n]);  // the higher cell's difference h[hi] - h[lo], exactly
    const bool c_higher = h[c] > h[n];
    const std::int64_t hi = c_higher ? c : n, lo = c_higher ? n : c;
    // one material: every pass is its own (pass < passes), no material map needed
    const PairRule& rule = rules[one_material ? 0 : static_cast<std::size_t>(model.material_at(hi))];
    if (pass >= rule.passes) return;
    const double excess = d - rule.max_dh_m;
    if (!(excess > tolerance_m)) return;
    fluxes->push_back({hi, lo, rule.sigma * excess, c_higher ? ceiling.at(ni, nj) : ceiling.at(i, j)});
  }
};

}  // namespace

std::vector<double> max_height_differences(const GroundModel& model, const GroundParams& params) {
  std::vector<double> max_dh;
  for (const Material& m : params.materials) max_dh.push_back(model.grid.cell_size_m * std::tan(m.repose_angle_rad));
  return max_dh;
}

bool is_settled(const GroundModel& model, const std::vector<double>& max_dh_m, const HeightField& height,
                std::int64_t cell) {
  const Grid& g = model.grid;
  const int i = static_cast<int>(cell % g.nx), j = static_cast<int>(cell / g.nx);
  const double tolerance_m = kErosionToleranceFraction * g.cell_size_m;
  const double h = height.at(i, j);
  if (model.options.bed_slope_rad > 0.0) {
    std::vector<InclinedRule> rules;
    for (const double dh : max_dh_m) {
      Material m;
      m.repose_angle_rad = std::atan(dh / g.cell_size_m);
      rules.push_back(inclined_rule(m, model.options.bed_slope_rad, g.cell_size_m));
    }
    for (const auto& o : kNeighbours) {
      const int ni = i + o[0], nj = j + o[1];
      if (!g.contains(ni, nj)) continue;
      const std::int64_t n = model.cell(ni, nj);
      const bool n_after = o[0] + o[1] > 0;
      const std::int64_t a = n_after ? cell : n, b = n_after ? n : cell;
      const double* hs = height.heights().data();
      Flux f;
      if (inclined_flux(rules, model.material_at(a), model.material_at(b), o[0] != 0, hs[a], hs[b], tolerance_m, 0, a,
                        b, &f)) {
        return false;
      }
    }
    return true;
  }
  for (const auto& o : kNeighbours) {
    const int ni = i + o[0], nj = j + o[1];
    if (!g.contains(ni, nj)) continue;
    const double hn = height.at(ni, nj);
    const std::int64_t hi = h > hn ? cell : model.cell(ni, nj);
    if (std::abs(h - hn) - max_dh_m[static_cast<std::size_t>(model.material_at(hi))] > tolerance_m) return false;
  }
  return true;
}

ErosionResult erode(const GroundModel& model, const GroundParams& params, const Ceiling& ceiling,
                    GroundState* state) {
  if (model.options.bed_slope_rad > 0.0) return erode_inclined(model, params, ceiling, state);
  ErosionResult result;
  const Grid& g = model.grid;
  const std::vector<PairRule> rules = pair_rules(g, params);
  int passes = 0;
  for (const PairRule& r : rules) passes = std::max(passes, r.passes);
  const double tolerance_m = kErosionToleranceFraction * g.cell_size_m;
  const bool one_material = rules.size() == 1;
  double min_max_dh_m = std::numeric_limits<double>::infinity();
  for (const PairRule& r : rules) min_max_dh_m = std::min(min_max_dh_m, r.max_dh_m);
  double* h = state->height.heights().data();
  ErosionMemory& memory = state->erosion;

  REPOSE_DEMAND(g.cell_count() <= static_cast<std::size_t>(std::numeric_limits<int>::max()));
  std::vector<Flux>& fluxes = state->erosion_scratch.fluxes;
  std::vector<double>& inflow = inflow_scratch(g, state);
  std::vector<std::array<int, 3>>& ij = state->erosion_scratch.ij;  // of memory.cells(), divided out once: a pass would repeat it
  ij.clear();
  for (int p = 0; p < passes && !memory.empty(); ++p) {
    fluxes.clear();
    const std::vector<std::int64_t>& cells = memory.cells();
    for (std::size_t k = ij.size(); k < cells.size(); ++k) {
      const int c = static_cast<int>(cells[k]);
      const int i = c % g.nx, j = c / g.nx;
      ij.push_back({i, j, i > 0 && j > 0 && i + 1 < g.nx && j + 1 < g.ny ? 1 : 0});
    }
    PairScan scan{model, rules, ceiling, memory, h, tolerance_m, p, one_material, &fluxes, min_max_dh_m};
    scan.cells(cells, ij, &state->erosion_scratch.candidates);
    result.pair_visits += scan.visits;
    if (fluxes.empty()) break;
    result.passes = p + 1;

    const bool capped = cap_inflow(h, &fluxes, &inflow);
    result.moves += apply_fluxes(fluxes, FloorAtZero::kNo, h, &memory, capped ? &inflow : nullptr);
  }
  return result;
}

}  // namespace repose
