#include "models/snow/stabilisation.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

#include "models/core/base/error.h"
#include "models/snow/snow_model.h"
#include "models/snow/snow_params.h"
#include "models/snow/snow_state.h"

namespace repose {

namespace {

// Directions a cell sends to: west, east, south, north; kOpposite[d] is the
// direction the same pair is seen from the other cell.
constexpr std::array<int, 4> kDi = {-1, 1, 0, 0};
constexpr std::array<int, 4> kDj = {0, 0, -1, 1};
constexpr std::array<int, 4> kOpposite = {1, 0, 3, 2};

constexpr std::int8_t kNoTarget = -1;
constexpr std::int8_t kLeavesScene = -2;

// Where snow of map m at surface height h_source goes when pushed to grid
// position (i, j), and the surface height there.
struct Target {
  std::int8_t map = kNoTarget;
  double surface_m = 0.0;
};

Target find_target(const std::vector<SnowMap>& maps, const std::vector<ArrayXXdR>& depth, std::size_t m, int i,
                   int j, double h_source) {
  if (maps[m].covered(i, j)) return {static_cast<std::int8_t>(m), maps[m].base_z(i, j) + depth[m](j, i)};
  Target best;
  bool any_cover = false;
  for (std::size_t k = 0; k < maps.size(); ++k) {
    if (k == m || !maps[k].covered(i, j)) continue;
    any_cover = true;
    const double h = maps[k].base_z(i, j) + depth[k](j, i);
    if (h < h_source && (best.map == kNoTarget || h > best.surface_m)) best = {static_cast<std::int8_t>(k), h};
  }
  if (best.map == kNoTarget && !any_cover) return {kLeavesScene, -std::numeric_limits<double>::infinity()};
  return best;
}

// What each cell of one map sends: the share per receiving neighbour and
// where each direction's share goes (kNoTarget: nothing goes that way).
struct Outflow {
  ArrayXXdR sent_m;   // A, ny x nx
  ArrayXXdR share_m;  // A / k
  std::vector<std::array<std::int8_t, 4>> target;  // per cell (row-major), per direction
};

Outflow outflow_of_map(const std::vector<SnowMap>& maps, const std::vector<ArrayXXdR>& depth, std::size_t m,
                       const StabilisationRule& rule) {
  const Grid& g = maps[m].grid();
  const double drop_at_repose = g.cell_size_m * rule.tan_repose;
  Outflow out{ArrayXXdR::Zero(g.ny, g.nx), ArrayXXdR::Zero(g.ny, g.nx), {}};
  out.target.assign(g.cell_count(), {kNoTarget, kNoTarget, kNoTarget, kNoTarget});
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double s = depth[m](j, i);
      if (!(s > 0.0) || !maps[m].covered(i, j)) continue;
      const double h = maps[m].base_z(i, j) + s;
      auto& targets = out.target[static_cast<std::size_t>(j) * g.nx + i];
      std::array<double, 4> excess_of = {0.0, 0.0, 0.0, 0.0};
      int receivers = 0;
      for (int d = 0; d < 4; ++d) {
        const int ni = i + kDi[d], nj = j + kDj[d];
        if (!g.contains(ni, nj)) continue;
        const Target t = find_target(maps, depth, m, ni, nj, h);
        if (t.map == kNoTarget) continue;
        const double held = t.map == static_cast<std::int8_t>(m) ? 0.0 : rule.edge_hold_m;  // falling off the map
        const double excess = std::min(h - t.surface_m - drop_at_repose, s - held);
        if (!(excess > rule.tolerance_m)) continue;
        targets[d] = t.map;
        excess_of[d] = excess;
        ++receivers;
      }
      if (receivers == 0) continue;
      // summed in mirror pairs, so that mirrored and transposed scenes give the same bits
      const double excess_sum = (excess_of[0] + excess_of[1]) + (excess_of[2] + excess_of[3]);
      const double sent = std::min(s, rule.moved_fraction * excess_sum);
      out.sent_m(j, i) = sent;
      out.share_m(j, i) = sent / receivers;
    }
  }
  return out;
}

// Snow arriving at cell (i, j) of map k from direction d's neighbour, over all maps.
double arriving(const std::vector<Outflow>& flows, const Grid& g, std::size_t k, int i, int j, int d) {
  const int si = i + kDi[d], sj = j + kDj[d];  // the source sits in direction d and sends the opposite way
  if (!g.contains(si, sj)) return 0.0;
  const std::size_t cell = static_cast<std::size_t>(sj) * g.nx + si;
  double sum = 0.0;
  for (const Outflow& f : flows) {
    if (f.target[cell][kOpposite[d]] == static_cast<std::int8_t>(k)) sum += f.share_m(sj, si);
  }
  return sum;
}

// Per cell of map k, the fraction of the snow sent to it that fits under
// its ceiling (start-of-pass heights): min(1, room / demand).
ArrayXXdR accepted_fraction(const std::vector<SnowMap>& maps, const std::vector<ArrayXXdR>& depth,
                            const std::vector<Outflow>& flows, std::size_t k) {
  const Grid& g = maps[k].grid();
  ArrayXXdR accept = ArrayXXdR::Ones(g.ny, g.nx);
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double ceiling = maps[k].ceiling_z(i, j);
      if (!maps[k].covered(i, j) || ceiling == std::numeric_limits<double>::infinity()) continue;
      const double demand = (arriving(flows, g, k, i, j, 0) + arriving(flows, g, k, i, j, 1)) +
                            (arriving(flows, g, k, i, j, 2) + arriving(flows, g, k, i, j, 3));
      const double room = std::max(0.0, ceiling - (maps[k].base_z(i, j) + depth[k](j, i)));
      if (demand > room) accept(j, i) = room / demand;
    }
  }
  return accept;
}

// What cell (i, j) of map m really sends (its shares times what each
// receiver accepts), and what of it leaves the scene.
double really_sent(const Outflow& flow, const std::vector<ArrayXXdR>& accept, const Grid& g, int i, int j,
                   double* left) {
  const auto& targets = flow.target[static_cast<std::size_t>(j) * g.nx + i];
  std::array<double, 4> part = {0.0, 0.0, 0.0, 0.0};
  for (int d = 0; d < 4; ++d) {
    if (targets[d] == kNoTarget) continue;
    if (targets[d] == kLeavesScene) {
      part[d] = flow.share_m(j, i);
      *left += part[d];
    } else {
      part[d] = flow.share_m(j, i) * accept[static_cast<std::size_t>(targets[d])](j + kDj[d], i + kDi[d]);
    }
  }
  // never more than the amount computed (k shares of A / k may round above A)
  return std::min(flow.sent_m(j, i), (part[0] + part[1]) + (part[2] + part[3]));
}

}  // namespace

PassResult stabilisation_pass(const std::vector<SnowMap>& maps, const StabilisationRule& rule,
                              std::vector<ArrayXXdR>* depth) {
  REPOSE_DEMAND(depth->size() == maps.size());
  PassResult result;
  if (maps.empty()) return result;
  const Grid& g = maps.front().grid();
  std::vector<Outflow> flows;
  for (std::size_t m = 0; m < maps.size(); ++m) flows.push_back(outflow_of_map(maps, *depth, m, rule));
  std::vector<ArrayXXdR> accept;
  for (std::size_t k = 0; k < maps.size(); ++k) accept.push_back(accepted_fraction(maps, *depth, flows, k));
  double left = 0.0;
  for (std::size_t k = 0; k < maps.size(); ++k) {
    ArrayXXdR& s = (*depth)[k];
    for (int j = 0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) {
        if (!maps[k].covered(i, j)) continue;  // neither holds nor receives snow
        const double sent = flows[k].sent_m(j, i) > 0.0 ? really_sent(flows[k], accept, g, i, j, &left) : 0.0;
        const double in = (arriving(flows, g, k, i, j, 0) + arriving(flows, g, k, i, j, 1)) +
                          (arriving(flows, g, k, i, j, 2) + arriving(flows, g, k, i, j, 3));
        s(j, i) = (s(j, i) - sent) + in * accept[k](j, i);
        if (sent > 0.0) {
          ++result.moving_cells;
          result.moved_m3 += sent * g.cell_area_m2();
        }
      }
    }
  }
  result.left_scene_m3 = left * g.cell_area_m2();
  return result;
}

StabilisationResult stabilise(const SnowModel& model, const SnowParams& params, SnowState* state) {
  const StabilisationRule rule{std::tan(params.repose_angle_rad), model.options.moved_fraction,
                               model.options.settle_tolerance_m, params.edge_hold_m};
  StabilisationResult result;
  while (result.passes < model.options.max_stabilisation_passes) {
    const PassResult pass = stabilisation_pass(model.maps, rule, &state->depth_m);
    ++result.passes;
    result.moved_m3 += pass.moved_m3;
    result.left_scene_m3 += pass.left_scene_m3;
    if (pass.moving_cells == 0) {
      result.settled = true;
      break;
    }
  }
  state->ledger.left_scene_m3 += result.left_scene_m3;
  return result;
}

}  // namespace repose
