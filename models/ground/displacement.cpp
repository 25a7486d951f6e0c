#include "models/ground/displacement.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "models/core/base/error.h"
#include "models/ground/contact_region.h"
#include "models/ground/excess_routing.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"
#include "models/ground/rear_to_front_order.h"

namespace repose {

namespace {

// Removes dh' from colliding cells; returns the region with the displaced
// fraction of dh' carried (alpha, or its drag value: material.h).
// The floor: the height field is material above a base at z = 0, below
// which lies bedrock, which neither moves nor compresses; an object reaching
// below the base removes the material down to the base only, and how far it
// reaches below is recorded (DisplacementResult::bedrock_m3).
ContactRegion remove_intersection(const GroundModel& model, const GroundParams& params, const Underside& contact,
                                  bool dragging, GroundState* state, DisplacementResult* result) {
  ContactRegion r;
  r.fp = contact.footprint;
  const int n = r.fp.ni * r.fp.nj;
  r.dist.assign(n, 0);
  r.carry.assign(n, 0.0);
  const double area = model.grid.cell_area_m2();
  const double tolerance_m = kContactToleranceFraction * model.grid.cell_size_m;
  for (int l = 0; l < n; ++l) {
    const int i = r.gi(l), j = r.gj(l);
    const double under = contact.z_m(j - r.fp.j0, i - r.fp.i0);
    double& h = state->height.at(i, j);
    if (!(under < h - tolerance_m)) continue;
    REPOSE_DEMAND(h >= 0.0);  // heights are material amounts (ground_state.h)
    const double floor_m = std::max(under, 0.0);
    const double dh = h - floor_m;
    const double alpha = params.materials[model.material_at(model.cell(i, j))].displaced_fraction(dragging);
    h = floor_m;
    r.carry[l] = alpha * dh;
    r.dist[l] = -1;
    r.cells.push_back(l);
    state->ledger.compressed_m3 += (1.0 - alpha) * dh * area;
    result->removed_m3 += dh * area;
    result->displaced_m3 += alpha * dh * area;
    result->bedrock_m3 += (floor_m - under) * area;
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
// (deposited, and remembered as received), or off the grid (left).
struct Sink {
  const GroundModel& model;
  GroundState* state;
  ContactRegion* region;
  Received* received;
  void give(int i, int j, double amount) {
    if (!model.grid.contains(i, j)) {
      state->ledger.left_grid_m3 += amount * model.grid.cell_area_m2();
    } else if (region->is_contact(i, j)) {
      region->carry[region->local(i, j)] += amount;
    } else {
      state->height.at(i, j) += amount;
      (*received)[model.cell(i, j)] += amount;
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

// Rear to front along the drag. A cell gives to its neighbours ahead of it
// and beside it, never behind; among contact cells beside it (o . d == 0),
// only to those nearer the border (the sideways part of pressing). Cells at
// the same position along the drag and the same distance to the border
// never give to each other, so their order (storage order) cannot matter:
// the sort puts every giver before all its receivers, and a drag is as
// symmetric as its contact region (a mirrored contact gives the mirrored
// result, to round-off).
void spread_rear_to_front(const DragDirection& dir, ContactRegion* r, Sink* sink) {
  for (const int l : rear_to_front_order(dir, *r)) {
    const double m = r->carry[l];
    if (m == 0.0) continue;
    const int i = r->gi(l), j = r->gj(l);
    int targets[4][2];
    int k = 0;
    for (const auto& o : kNeighbours) {
      if (dir.backward(o[0], o[1])) continue;
      const int ni = i + o[0], nj = j + o[1];
      const bool beside_in_contact = r->is_contact(ni, nj) && !dir.forward(o[0], o[1]);
      if (beside_in_contact && r->dist[r->local(ni, nj)] >= r->dist[l]) continue;
      targets[k][0] = ni, targets[k][1] = nj, ++k;
    }
    REPOSE_DEMAND(k > 0);  // the neighbours ahead always qualify
    for (int t = 0; t < k; ++t) sink->give(targets[t][0], targets[t][1], m / k);
  }
}

// The highest a heap beside the contact may stand (excess_routing.h): the
// object's top, or the ground around the contact if that is higher.
double crest_of(const Underside& contact, const HeightField& height) {
  const Footprint& fp = contact.footprint;
  const Grid& g = height.grid();
  const int i0 = std::max(0, fp.i0 - 1), j0 = std::max(0, fp.j0 - 1);
  const int i1 = std::min(g.nx, fp.i0 + fp.ni + 1), j1 = std::min(g.ny, fp.j0 + fp.nj + 1);
  return std::max(contact.top_m, height.heights().block(j0, i0, j1 - j0, i1 - i0).maxCoeff());
}

}  // namespace

bool is_drag(const Eigen::Vector3d& motion_m, double min_horizontal_m) {
  const double horizontal_m = motion_m.head<2>().norm();
  // A level segment between keyframes at one height is interpolated as
  // (1 - u) z + u z, which wanders by an ulp: a descent that small is
  // round-off, and counting it as pressing made half of a level drag
  // compress as a press does (ref_bulldoze: 16 of its 21 cm^3).
  const double round_off_m = 1e-9 * horizontal_m;
  return horizontal_m > min_horizontal_m && motion_m.z() >= -round_off_m;
}

DragDirection drag_direction(const Eigen::Vector3d& motion_m, double cell_size_m) {
  DragDirection d;
  if (!is_drag(motion_m, 1e-3 * cell_size_m)) return d;
  const double n = motion_m.head<2>().norm();
  d.active = true;
  d.dx = std::abs(motion_m.x() / n) <= DragDirection::kEps ? 0.0 : motion_m.x() / n;
  d.dy = std::abs(motion_m.y() / n) <= DragDirection::kEps ? 0.0 : motion_m.y() / n;
  return d;
}

DisplacementResult displace(const GroundModel& model, const GroundParams& params, const Underside& contact,
                            const Ceiling& ceiling, const Eigen::Vector3d& motion_m, GroundState* state) {
  DisplacementResult result;
  if (contact.empty()) return result;
  const double crest_m = crest_of(contact, state->height);
  const DragDirection dir = drag_direction(motion_m, model.grid.cell_size_m);
  ContactRegion region = remove_intersection(model, params, contact, dir.active, state, &result);
  result.contact_cells = static_cast<int>(region.cells.size());
  state->ledger.bedrock_m3 = std::max(state->ledger.bedrock_m3, result.bedrock_m3);
  if (region.cells.empty()) return result;
  distance_to_border(model.grid, &region);

  Received received;
  Sink sink{model, state, &region, &received};
  if (dir.active) {
    spread_rear_to_front(dir, &region, &sink);
  } else {
    spread_from_inside_out(&region, &sink);
  }
  route_excess(ExcessRouting{model, params, ceiling, dir, region, crest_m}, &received, state);
  std::vector<std::int64_t> touched;  // every cell that changed has an entry in received
  for (const auto& [c, amount] : received) touched.push_back(c);

  for (const int l : region.cells) state->erosion.touch(model.cell(region.gi(l), region.gj(l)));
  // sorted: the memory lists cells in the order they join, not in the order they received
  std::sort(touched.begin(), touched.end());
  for (const std::int64_t c : touched) state->erosion.touch(c);
  return result;
}

}  // namespace repose
