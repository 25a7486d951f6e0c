#include "models/heightspan/span_erosion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "models/ground/erosion.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"
#include "models/heightspan/ground_contact.h"
#include "models/heightspan/heightspan_model.h"
#include "models/heightspan/heightspan_state.h"

namespace repose {

namespace {

constexpr int kNeighbours[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

using namespace span_erosion_detail;

// The map's columns with spans (the box [i0, i1] x [j0, j1] of the map's
// cells holding any) and the ground under them, two rings of cells beyond
// (the second only so that a ring column's neighbours need no bounds
// check: nothing beyond the first ring has spans or takes part). Local
// indices run row-major over that padded window. Each local column's first
// span, span count (0 where it has none), lowest span's top and bottom (+inf
// without spans) and ground cell (-1 beyond the grid) are looked up once
// per call: the spans' solids and the cells do not change during erosion.
class Columns {
 public:
  static constexpr int kPad = 2;
  const SpanMap& map;
  const HeightField& ground;
  CellOffset off;
  int i0, i1, j0, j1;  // the box

  Columns(const SpanMap& m, const HeightField& g, CellOffset o, const std::array<int, 4>& box)
      : map(m), ground(g), off(o), i0(box[0]), i1(box[1]), j0(box[2]), j1(box[3]) {
    first_.assign(local_count(), 0);
    count_.assign(local_count(), 0);
    ground_cell_.assign(local_count(), -1);
    lowest_top_.assign(local_count(), kInf);
    lowest_bottom_.assign(local_count(), kInf);
    for (int j = j0; j <= j1; ++j) {  // beyond the box no column has spans
      const std::int32_t* f = map.first.data() + map.cell(0, j);
      const std::size_t l = static_cast<std::size_t>(local(0, j));
      for (int i = i0; i <= i1; ++i) {
        first_[l + i] = f[i], count_[l + i] = f[i + 1] - f[i];
        if (f[i + 1] > f[i]) lowest_top_[l + i] = map.spans[f[i]].top_m, lowest_bottom_[l + i] = map.spans[f[i]].bottom_m;
      }
    }
    const Grid& grid = ground.grid();
    // the window's columns whose ground cell is on the grid: [gi0, gi1) x [gj0, gj1)
    const int gi0 = std::max(i0 - kPad, -off.di), gi1 = std::min(i1 + kPad + 1, grid.nx - off.di);
    const int gj0 = std::max(j0 - kPad, -off.dj), gj1 = std::min(j1 + kPad + 1, grid.ny - off.dj);
    for (int j = gj0; j < gj1; ++j) {
      const std::int64_t row = static_cast<std::int64_t>(j + off.dj) * grid.nx + off.di;
      const std::size_t l = static_cast<std::size_t>(local(0, j));
      for (int i = gi0; i < gi1; ++i) ground_cell_[l + i] = row + i;
    }
    // the box and its first ring: their neighbours are all in the padded window
    neighbours_lowest_top_.assign(local_count(), kInf);
    const std::array<std::int64_t, 4>& s = steps();
    for (int j = j0 - 1; j <= j1 + 1; ++j) {
      for (std::int64_t l = local(i0 - 1, j), end = local(i1 + 1, j); l <= end; ++l) {
        const std::size_t at = static_cast<std::size_t>(l);
        neighbours_lowest_top_[at] = std::min(std::min(lowest_top_[at + s[0]], lowest_top_[at + s[1]]),
                                              std::min(lowest_top_[at + s[2]], lowest_top_[at + s[3]]));
      }
    }
  }

  int stride() const { return i1 - i0 + 1 + 2 * kPad; }
  // The local index of the map's column (i, j) (it may lie up to kPad beyond the box).
  std::int64_t local(int i, int j) const {
    return static_cast<std::int64_t>(j - j0 + kPad) * stride() + (i - i0 + kPad);
  }
  std::size_t local_count() const { return static_cast<std::size_t>(stride()) * (j1 - j0 + 1 + 2 * kPad); }
  int i_of(std::int64_t l) const { return static_cast<int>(l % stride()) - kPad + i0; }
  int j_of(std::int64_t l) const { return static_cast<int>(l / stride()) - kPad + j0; }
  // Local column l's first span (its index in map.spans) and span count.
  std::int32_t first(std::int64_t l) const { return first_[static_cast<std::size_t>(l)]; }
  int count(std::int64_t l) const { return count_[static_cast<std::size_t>(l)]; }
  // The ground cell under local column l, -1 beyond the grid.
  std::int64_t ground_cell(std::int64_t l) const { return ground_cell_[static_cast<std::size_t>(l)]; }
  // The lowest span's top and bottom in local column l, +inf where it has none.
  double lowest_top(std::int64_t l) const { return lowest_top_[static_cast<std::size_t>(l)]; }
  double lowest_bottom(std::int64_t l) const { return lowest_bottom_[static_cast<std::size_t>(l)]; }
  // The least of its four neighbours' lowest_top (local column l in the map or its first ring).
  double neighbours_lowest_top(std::int64_t l) const { return neighbours_lowest_top_[static_cast<std::size_t>(l)]; }

  // The surface material at height z entering local column l lands on; false when z is inside its solid.
  bool landing(std::int64_t l, double z, Surface* out) const {
    const std::size_t at = static_cast<std::size_t>(l);
    const int n = count_[at];
    const Span* s = map.spans.data() + first_[at];  // not read when n == 0
    int k = n - 1;
    while (k >= 0 && s[k].top_m > z) --k;
    if (k >= 0) {
      if (k + 1 < n && s[k + 1].bottom_m <= z) return false;
      *out = {Kind::kSpan, first_[at] + k, s[k].level_m(), k + 1 < n ? s[k + 1].bottom_m : kInf};
      return true;
    }
    if (n > 0 && s[0].bottom_m <= z) return false;
    if (ground_cell_[at] < 0) {
      *out = {Kind::kAir, l, 0.0, kInf};  // beyond the grid: it falls off
      return true;
    }
    *out = {Kind::kGround, l, ground.heights().data()[ground_cell_[at]], n > 0 ? s[0].bottom_m : kInf};
    return true;
  }
  // The local index steps to the neighbours, in kNeighbours' order.
  const std::array<std::int64_t, 4>& steps() const { return steps_; }

 private:
  std::array<std::int64_t, 4> steps_ = {1, -1, stride(), -stride()};
  std::vector<std::int32_t> first_, count_;
  std::vector<std::int64_t> ground_cell_;
  std::vector<double> lowest_top_, lowest_bottom_, neighbours_lowest_top_;
};

struct PassRule {
  double max_dh_m, sigma, tolerance_m, near_m;
  double slide_cap_m;  // a support drop counts for sharing a slide at most this (one cell: 45 deg)
  double dust_m;       // material below this (1e-12 cell) is round-off: it does not move
};

// The solid surface a landing surface offers: a span's top, the ground's
// height; nothing under air.
double support_of(const Columns& cols, const Surface& to) {
  if (to.kind == Kind::kSpan) return cols.map.spans[static_cast<std::size_t>(to.index)].top_m;
  if (to.kind == Kind::kGround) return to.level_m;
  return -kInf;
}

// The fluxes off the spans of local column l (one of the map's).
void add_span_fluxes(const Columns& cols, const PassRule& rule, std::int64_t l, std::vector<Flux>* fluxes) {
  const std::int32_t first_span = cols.first(l);
  const int n = cols.count(l);
  const Span* spans = cols.map.spans.data() + first_span;
  const std::array<std::int64_t, 4>& steps = cols.steps();
  for (int k = 0; k < n; ++k) {
    const Span& s = spans[k];
    if (!(s.material_m > rule.dust_m)) continue;  // round-off left by a slide stays put
    const Surface from{Kind::kSpan, first_span + k, s.level_m(), kInf};
    const std::size_t first = fluxes->size();
    double slide_total = 0.0;  // over the neighbours whose support drops more than the repose slope
    for (const std::int64_t step : steps) {
      Surface to;
      if (!cols.landing(l + step, from.level_m, &to)) continue;
      const double excess = from.level_m - to.level_m - rule.max_dh_m;
      if (!(excess > rule.tolerance_m)) continue;
      // (a layer thinner than the tolerance is round-off, left where it is as by the slope rule)
      const double steep = s.material_m > rule.tolerance_m
                               ? std::min(s.top_m - support_of(cols, to) - rule.max_dh_m, rule.slide_cap_m)
                               : 0.0;
      if (to.kind == Kind::kGround && s.top_m - to.level_m > rule.near_m) to.kind = Kind::kAir;  // falls
      // release_z_m doubles as the slide weight until the span's fluxes are complete
      fluxes->push_back({from, to, rule.sigma * excess, steep > rule.tolerance_m ? steep : 0.0});
      if (steep > rule.tolerance_m) slide_total += steep;
    }
    // unsupported: the span's own surface falls more steeply than the repose slope towards these
    // neighbours, so none of its material can rest on it; all of it slides, shared by steepness
    for (std::size_t f = first; f < fluxes->size(); ++f) {
      Flux& flux = (*fluxes)[f];
      if (slide_total > 0.0 && flux.release_z_m > 0.0) {
        flux.amount_m = std::max(flux.amount_m, s.material_m * flux.release_z_m / slide_total);
      }
      flux.release_z_m = from.level_m;
    }
  }
}

// Ground beside the object sliding onto its spans.
void add_ground_fluxes(const Columns& cols, const PassRule& rule, std::int64_t l, std::vector<Flux>* fluxes) {
  const std::int64_t gc = cols.ground_cell(l);
  if (gc < 0) return;
  const double g = cols.ground.heights().data()[gc];
  // only a span whose top is at or below g can take it: none when every neighbour's lowest one's is above
  if (cols.neighbours_lowest_top(l) > g) return;
  if (g > cols.lowest_bottom(l)) return;  // under the object: not exposed
  const Surface from{Kind::kGround, l, g, kInf};
  for (const std::int64_t step : cols.steps()) {
    // only a span whose top is at or below g can take it: none when the lowest one's is above (or there is none)
    if (cols.lowest_top(l + step) > g) continue;
    Surface to;
    if (!cols.landing(l + step, g, &to) || to.kind != Kind::kSpan) continue;
    const double excess = g - to.level_m - rule.max_dh_m;
    if (excess > rule.tolerance_m) fluxes->push_back({from, to, rule.sigma * excess, g});
  }
}

// The surfaces' amounts and one pass's sums: what each gives and takes.
// The sums live in the object's scratch (SpanErosionScratch) and only the
// entries a pass touched are cleared again, so a call costs what moves, not
// the map's size.
struct Exchange {
  const GroundModel& model;
  SpanMap& map;
  GroundState* ground;
  const Columns& cols;
  std::size_t n_spans, n_local;
  // per surface: outflow, then inflow; spans first, then the columns' ground (and air)
  std::vector<double>& out;
  std::vector<double>& in;
  std::vector<double>& released_m;
  std::vector<double>& release_z;
  std::vector<std::size_t>& released_at;  // the columns with released material, in the order they got it

  Exchange(const GroundModel& m, SpanMap& sm, GroundState* g, const Columns& c, SpanErosionScratch* scratch)
      : model(m), map(sm), ground(g), cols(c), n_spans(sm.spans.size()), n_local(c.local_count()),
        out(scratch->out), in(scratch->in), released_m(scratch->released_m), release_z(scratch->release_z),
        released_at(scratch->released_at) {
    if (out.size() < n_spans + n_local) out.resize(n_spans + n_local, 0.0), in.resize(n_spans + n_local, 0.0);
    if (released_m.size() < n_local) released_m.resize(n_local, 0.0), release_z.resize(n_local, -kInf);
    released_at.clear();
  }

  std::size_t key(const Surface& s) const {
    return static_cast<std::size_t>(s.kind == Kind::kSpan ? s.index : static_cast<std::int64_t>(n_spans) + s.index);
  }
  std::int64_t ground_cell(std::int64_t local) const { return cols.ground_cell(local); }
  double& amount_of(const Surface& s) {
    if (s.kind == Kind::kSpan) return map.spans[static_cast<std::size_t>(s.index)].material_m;
    return ground->height.heights().data()[ground_cell(s.index)];
  }

  // a surface gives at most what it has, takes at most its room
  void scale(std::vector<Flux>* fluxes) {
    for (const Flux& f : *fluxes) {
      out[key(f.from)] = 0.0;
      if (f.to.kind != Kind::kAir) in[key(f.to)] = 0.0;
    }
    for (const Flux& f : *fluxes) out[key(f.from)] += f.amount_m;
    for (Flux& f : *fluxes) {
      const double has = amount_of(f.from), total = out[key(f.from)];
      if (total > has) f.amount_m *= has / total;
      if (f.to.kind != Kind::kAir) in[key(f.to)] += f.amount_m;
    }
    for (Flux& f : *fluxes) {
      if (f.to.kind == Kind::kAir) continue;
      const double room = std::max(0.0, f.to.room_m - f.to.level_m), total = in[key(f.to)];
      if (total > room) f.amount_m *= room / total;
    }
  }

  void apply(const std::vector<Flux>& fluxes, SpanErosionResult* result) {
    const double area = model.grid.cell_area_m2();
    for (const Flux& f : fluxes) {
      if (!(f.amount_m > 0.0)) continue;
      ++result->moves;
      amount_of(f.from) -= f.amount_m;
      if (f.from.kind == Kind::kGround) {
        result->from_ground_m3 += f.amount_m * area;
        ground->erosion.touch(ground_cell(f.from.index));
      }
      if (f.to.kind == Kind::kAir) {  // released after the passes
        if (!(released_m[f.to.index] > 0.0)) released_at.push_back(static_cast<std::size_t>(f.to.index));
        released_m[f.to.index] += f.amount_m;
        release_z[f.to.index] = std::max(release_z[f.to.index], f.release_z_m);
        result->to_particles_m3 += f.amount_m * area;
        continue;
      }
      amount_of(f.to) += f.amount_m;
      if (f.to.kind == Kind::kGround) {
        result->to_ground_m3 += f.amount_m * area;
        ground->erosion.touch(ground_cell(f.to.index));
      }
    }
  }

  // one particle per column the material left into, in the columns' order; the sums are cleared
  void release(const Eigen::Vector3d& velocity_m_s, double spread_m_s, ParticleSystem* particles,
               std::mt19937_64* rng) {
    std::sort(released_at.begin(), released_at.end());
    for (const std::size_t l : released_at) {
      const std::int64_t ll = static_cast<std::int64_t>(l);
      const int i = cols.i_of(ll), j = cols.j_of(ll);
      const Eigen::Vector3d at(map.grid.centre_x(i), map.grid.centre_y(j), release_z[l]);
      particles->release({at, velocity_m_s, released_m[l] * model.grid.cell_area_m2()}, spread_m_s, rng);
      released_m[l] = 0.0;
      release_z[l] = -kInf;
    }
    released_at.clear();
  }
};

// Which columns a pass changed, so that the next pass examines only them
// and their neighbours: a column's fluxes read its own surfaces and its four
// neighbours' only, so where none of these changed it would find the same
// fluxes again, and those all came to nothing (a source with nothing to
// give or a target with no room, unchanged since): skipping it changes no
// amount. A pass that finds only such fluxes is no longer counted.
class ChangedColumns {
 public:
  ChangedColumns(const Columns& cols, std::vector<char>* flags, std::vector<std::int64_t>* local_of_span)
      : cols_(cols), flags_(*flags), local_of_span_(*local_of_span) {
    flags_.assign(cols.local_count(), 0);
    const SpanMap& map = cols.map;
    local_of_span_.resize(map.spans.size());
    for (int j = cols.j0; j <= cols.j1; ++j) {  // beyond the box no column has spans
      for (int i = cols.i0; i <= cols.i1; ++i) {
        const std::int64_t c = map.cell(i, j);
        for (std::int32_t k = map.first[c]; k < map.first[c + 1]; ++k) local_of_span_[k] = cols.local(i, j);
      }
    }
  }
  // Local column l or a 4-neighbour changed in the last pass.
  bool near(std::int64_t l) const { return flags_[static_cast<std::size_t>(l)] != 0; }
  // Some column of row j is near().
  bool row_near(int j) const { return rows_[static_cast<std::size_t>(j - cols_.j0 + Columns::kPad)] != 0; }
  // Forgets the last pass's changes, then records those of `fluxes` (applied).
  void record(const std::vector<Flux>& fluxes) {
    for (const std::int64_t l : marked_) flags_[static_cast<std::size_t>(l)] = 0;
    marked_.clear();
    std::fill(rows_.begin(), rows_.end(), 0);
    for (const Flux& f : fluxes) {
      if (!(f.amount_m > 0.0)) continue;
      mark(f.from);
      if (f.to.kind != Kind::kAir) mark(f.to);
    }
  }

 private:
  void mark(const Surface& s) {
    // a span: the column whose spans hold it
    const std::int64_t l = s.kind == Kind::kSpan ? local_of_span_[static_cast<std::size_t>(s.index)] : s.index;
    // it and its neighbours (it is in the first ring at most: the padding holds them) are near a change
    flag(l);
    for (const std::int64_t step : steps_) flag(l + step);
    const std::size_t row = static_cast<std::size_t>(l / steps_[2]);
    rows_[row - 1] = rows_[row] = rows_[row + 1] = 1;
  }
  void flag(std::int64_t l) {
    if (!flags_[static_cast<std::size_t>(l)]) flags_[static_cast<std::size_t>(l)] = 1, marked_.push_back(l);
  }
  const Columns& cols_;
  std::vector<char>& flags_;
  std::vector<std::int64_t>& local_of_span_;
  std::vector<std::int64_t> marked_;  // the flagged columns
  std::vector<char> rows_ = std::vector<char>(static_cast<std::size_t>(cols_.j1 - cols_.j0 + 1 + 2 * Columns::kPad), 0);
  const std::array<std::int64_t, 4> steps_ = cols_.steps();
};

// The columns with spans: [i0, i1] x [j0, j1] (empty when i1 < i0).
std::array<int, 4> span_columns(const SpanMap& map) {
  std::array<int, 4> box{map.grid.nx, -1, map.grid.ny, -1};
  for (int j = 0; j < map.grid.ny; ++j) {
    const std::int32_t* f = map.first.data() + map.cell(0, j);  // the row's offsets: f[nx] starts the next row
    if (f[0] == f[map.grid.nx]) continue;                          // no spans in the row
    int lo = 0, hi = map.grid.nx - 1;
    while (f[lo + 1] == f[lo]) ++lo;
    while (f[hi + 1] == f[hi]) --hi;
    box = {std::min(box[0], lo), std::max(box[1], hi), std::min(box[2], j), std::max(box[3], j)};
  }
  return box;
}

}  // namespace

SpanErosionResult erode_spans(const HeightSpanModel& model, const GroundParams& params,
                              const Eigen::Vector3d& velocity_m_s, ObjectSpans* spans, GroundState* ground,
                              ParticleSystem* particles, std::mt19937_64* rng) {
  SpanErosionResult result;
  SpanMap& map = spans->map;
  if (map.empty()) return result;
  const Grid& g = model.ground.grid;
  const Material& m = params.materials.front();  // the spans carry the ground's base material
  const PassRule rule{g.cell_size_m * std::tan(m.repose_angle_rad), m.sigma, kErosionToleranceFraction * g.cell_size_m,
                      model.options.near_ground_cells * g.cell_size_m, g.cell_size_m, 1e-12 * g.cell_size_m};
  // the columns with spans and one ring around them: nothing else can exchange with a span
  const std::array<int, 4> box = span_columns(map);  // not empty: the map has spans
  const auto [i0, i1, j0, j1] = box;
  const Columns cols{map, ground->height, ground_offset(map.grid, g), box};
  Exchange exchange(model.ground, map, ground, cols, &spans->erosion_scratch);
  std::vector<Flux>& fluxes = spans->erosion_scratch.fluxes;
  ChangedColumns changed(cols, &spans->erosion_scratch.changed, &spans->erosion_scratch.local_of_span);
  for (int p = 0; p < m.erosion_iterations; ++p) {
    fluxes.clear();
    for (int j = j0 - 1; j <= j1 + 1; ++j) {
      if (p > 0 && !changed.row_near(j)) continue;
      for (std::int64_t l = cols.local(i0 - 1, j), end = cols.local(i1 + 1, j); l <= end; ++l) {
        if (p > 0 && !changed.near(l)) continue;
        if (cols.count(l) > 0) add_span_fluxes(cols, rule, l, &fluxes);
        add_ground_fluxes(cols, rule, l, &fluxes);
      }
    }
    if (fluxes.empty()) break;
    result.passes = p + 1;
    exchange.scale(&fluxes);
    exchange.apply(fluxes, &result);
    changed.record(fluxes);
  }
  exchange.release(velocity_m_s, model.options.particle_spread_m_s, particles, rng);
  return result;
}

}  // namespace repose
