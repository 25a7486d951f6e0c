#include "models/ground/erosion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "models/core/base/error.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"

namespace repose {

namespace {

constexpr std::array<std::array<int, 2>, 4> kNeighbours = {{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};

struct Flux {
  std::int64_t from, to;
  double amount;
  double ceiling_m;  // over `to` (+inf: no object), found where its coordinates are known
};

// Per material: the height difference a pair may have, sigma and En.
struct PairRule {
  double max_dh_m;
  double sigma;
  int passes;
};

// Never above an object: scales the inflow of each capped cell (one under
// an object) down to its room. The fluxes into capped cells are grouped by
// cell, in flux order within a cell, so each inflow sums in flux order; a
// sorted list of (cell, flux index), not a hash map, so that a pass
// allocates nothing (`capped` is scratch, kept between passes).
void cap_inflow(const double* h, std::vector<Flux>* fluxes, std::vector<std::pair<std::int64_t, std::size_t>>* capped) {
  std::vector<Flux>& fx = *fluxes;
  capped->clear();
  for (std::size_t k = 0; k < fx.size(); ++k) {
    if (std::isfinite(fx[k].ceiling_m)) capped->emplace_back(fx[k].to, k);
  }
  std::sort(capped->begin(), capped->end());
  for (std::size_t first = 0, last = 0; first < capped->size(); first = last) {
    const std::int64_t cell = (*capped)[first].first;
    double inflow = 0.0;
    for (last = first; last < capped->size() && (*capped)[last].first == cell; ++last) {
      inflow += fx[(*capped)[last].second].amount;
    }
    const double room = std::max(0.0, fx[(*capped)[first].second].ceiling_m - h[cell]);
    if (!(inflow > room)) continue;
    const double scale = room / inflow;
    for (std::size_t k = first; k < last; ++k) fx[(*capped)[k].second].amount *= scale;
  }
}

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
  ErosionResult result;
  const Grid& g = model.grid;
  std::vector<PairRule> rules;
  int passes = 0;
  for (const Material& m : params.materials) {
    const double tan_theta = std::tan(m.repose_angle_rad);
    rules.push_back({g.cell_size_m * tan_theta, m.sigma, m.erosion_iterations});
    passes = std::max(passes, m.erosion_iterations);
  }
  const double tolerance_m = kErosionToleranceFraction * g.cell_size_m;
  HeightField& hf = state->height;
  double* h = hf.heights().data();
  ErosionMemory& memory = state->erosion;

  REPOSE_DEMAND(g.cell_count() <= static_cast<std::size_t>(std::numeric_limits<int>::max()));
  std::vector<Flux> fluxes;
  std::vector<std::pair<std::int64_t, std::size_t>> capped;
  std::vector<std::array<int, 2>> ij;  // of memory.cells(), divided out once: a pass would repeat it
  for (int p = 0; p < passes && !memory.empty(); ++p) {
    fluxes.clear();
    const std::vector<std::int64_t>& cells = memory.cells();
    for (std::size_t k = ij.size(); k < cells.size(); ++k) {
      const int c = static_cast<int>(cells[k]);
      ij.push_back({c % g.nx, c / g.nx});
    }
    for (std::size_t k = 0; k < cells.size(); ++k) {
      const std::int64_t c = cells[k];
      const int i = ij[k][0], j = ij[k][1];
      for (const auto& o : kNeighbours) {
        const int ni = i + o[0], nj = j + o[1];
        if (!g.contains(ni, nj)) continue;  // closed boundary
        const std::int64_t n = model.cell(ni, nj);
        if (n < c && memory.contains(n)) continue;  // each pair once
        ++result.pair_visits;
        const bool c_higher = h[c] > h[n];
        const std::int64_t hi = c_higher ? c : n, lo = c_higher ? n : c;
        const PairRule& rule = rules[model.material_at(hi)];
        if (p >= rule.passes) continue;
        const double excess = (h[hi] - h[lo]) - rule.max_dh_m;
        if (!(excess > tolerance_m)) continue;
        fluxes.push_back({hi, lo, rule.sigma * excess, c_higher ? ceiling.at(ni, nj) : ceiling.at(i, j)});
      }
    }
    if (fluxes.empty()) break;
    result.passes = p + 1;

    cap_inflow(h, &fluxes, &capped);

    for (const Flux& f : fluxes) {
      if (!(f.amount > 0.0)) continue;
      h[f.from] -= f.amount;
      h[f.to] += f.amount;
      ++result.moves;
    }
    for (const Flux& f : fluxes) {
      if (!(f.amount > 0.0)) continue;
      memory.touch(f.from);
      memory.touch(f.to);
    }
  }
  return result;
}

}  // namespace repose
