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

// A surface material at some height lands on (Columns::View::landing).
struct Landing {
  Kind kind;
  std::int64_t index;  // a span's index in map.spans, else the local column
  double level_m;      // where material on it reaches
  double room_m;       // highest level it may reach
  double support_m;    // the solid surface it offers: a span's top, the ground's height; -inf under air
  double* amount_m;    // what it holds (a span's material, the ground's height); nullptr for air
};

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
  SpanMap& map;
  HeightField& ground;
  CellOffset off;
  int i0, i1, j0, j1;    // the box
  std::size_t n_spans;  // map.spans.size(), which divides by sizeof(Span) every time

  Columns(SpanMap& m, HeightField& g, CellOffset o, const std::array<int, 4>& box)
      : map(m), ground(g), off(o), i0(box[0]), i1(box[1]), j0(box[2]), j1(box[3]), n_spans(m.spans.size()) {
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

  // What lands() and landing() read, as plain pointers: copied into a caller's locals, they stay in
  // registers across the stores of its fluxes, where the vectors' data would be loaded for every lookup.
  struct View {
    const std::int32_t* first;
    const std::int32_t* count;
    const std::int64_t* ground_cell;
    Span* spans;
    double* heights;

    // Where material at height z entering local column l lands: false when z is inside its solid; else the
    // level there (*level_m) and the span it lands on (*k, its index in the column's; -1: the ground, or air
    // beyond the grid). Only the level: most landings make no flux, and landing() gives the rest.
    bool lands(std::int64_t l, double z, int* k, double* level_m) const {
      const int n = count[l];
      const Span* s = spans + first[l];  // not read when n == 0
      int kk = n - 1;
      while (kk >= 0 && s[kk].top_m > z) --kk;
      if (kk + 1 < n && s[kk + 1].bottom_m <= z) return false;  // the span above z (or the lowest one) reaches it
      *k = kk;
      *level_m = kk >= 0 ? s[kk].level_m() : ground_cell[l] < 0 ? 0.0 : heights[ground_cell[l]];
      return true;
    }
    // The surface of lands(): span k of local column l's, or below them the ground (air beyond the grid).
    Landing landing(std::int64_t l, int k) const {
      const int n = count[l];
      Span* s = spans + first[l];
      if (k >= 0) {
        return {Kind::kSpan, first[l] + k, s[k].level_m(), k + 1 < n ? s[k + 1].bottom_m : kInf, s[k].top_m,
                &s[k].material_m};
      }
      if (ground_cell[l] < 0) return {Kind::kAir, l, 0.0, kInf, -kInf, nullptr};  // beyond the grid: it falls off
      double* h = heights + ground_cell[l];
      return {Kind::kGround, l, *h, n > 0 ? s[0].bottom_m : kInf, *h, h};
    }
  };
  View view() const {
    return {first_.data(), count_.data(), ground_cell_.data(), map.spans.data(), ground.heights().data()};
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

// A flux of `amount_m` from a surface (what it holds: *from_m) in local column from_l onto `to` in local column to_l;
// z_m: the level it leaves at.
Flux make_flux(double amount_m, double* from_m, Kind from_kind, std::int64_t from_l, const Landing& to,
               std::int64_t to_l, double z_m, std::size_t n_spans) {
  const bool air = to.kind == Kind::kAir;
  const std::int64_t key = to.kind == Kind::kSpan ? to.index : static_cast<std::int64_t>(n_spans) + to_l;
  return {amount_m, air ? z_m : std::max(0.0, to.room_m - to.level_m), from_m, air ? nullptr : to.amount_m,
          static_cast<std::int32_t>(key), static_cast<std::int32_t>(from_l), static_cast<std::int32_t>(to_l),
          from_kind, to.kind};
}

// A surface gives at most what it has: its fluxes [begin, end) scaled down together where they would exceed it.
void limit_to(double has, Flux* begin, Flux* end) {
  double total = 0.0;
  for (const Flux* f = begin; f != end; ++f) total += f->amount_m;
  if (!(total > has)) return;
  for (Flux* f = begin; f != end; ++f) f->amount_m *= has / total;
}

// The fluxes off the spans of local column l (one of the map's).
void add_span_fluxes(const Columns& cols, const PassRule& rule, std::int64_t l, std::vector<Flux>* fluxes) {
  const Columns::View view = cols.view();
  const int n = cols.count(l);
  Span* spans = cols.map.spans.data() + cols.first(l);
  const std::size_t n_spans = cols.n_spans;
  for (int k = 0; k < n; ++k) {
    Span& s = spans[k];
    if (!(s.material_m > rule.dust_m)) continue;  // round-off left by a slide stays put
    const double level = s.level_m();
    std::array<double, 4> slide{};  // per flux: its support's drop, where steeper than the repose slope
    double slide_total = 0.0;       // over the neighbours whose support drops more than the repose slope
    std::size_t made = 0;           // fluxes made off this span
    for (const std::int64_t step : cols.steps()) {
      int k_to;
      double to_level_m;
      if (!view.lands(l + step, level, &k_to, &to_level_m)) continue;
      const double excess = level - to_level_m - rule.max_dh_m;
      if (!(excess > rule.tolerance_m)) continue;
      Landing to = view.landing(l + step, k_to);
      // (a layer thinner than the tolerance is round-off, left where it is as by the slope rule)
      const double steep =
          s.material_m > rule.tolerance_m ? std::min(s.top_m - to.support_m - rule.max_dh_m, rule.slide_cap_m) : 0.0;
      if (to.kind == Kind::kGround && s.top_m - to.level_m > rule.near_m) to.kind = Kind::kAir;  // falls
      slide[made++] = steep > rule.tolerance_m ? steep : 0.0;
      fluxes->push_back(make_flux(rule.sigma * excess, &s.material_m, Kind::kSpan, l, to, l + step, level, n_spans));
      if (steep > rule.tolerance_m) slide_total += steep;
    }
    // unsupported: the span's own surface falls more steeply than the repose slope towards these
    // neighbours, so none of its material can rest on it; all of it slides, shared by steepness
    if (made == 0) continue;
    Flux* const end = fluxes->data() + fluxes->size();
    Flux* const begin = end - made;
    if (slide_total > 0.0) {
      for (std::size_t f = 0; f < made; ++f) {
        if (slide[f] > 0.0) begin[f].amount_m = std::max(begin[f].amount_m, s.material_m * slide[f] / slide_total);
      }
    }
    limit_to(s.material_m, begin, end);
  }
}

// Ground beside the object sliding onto its spans.
void add_ground_fluxes(const Columns& cols, const PassRule& rule, std::int64_t l, std::vector<Flux>* fluxes) {
  const std::int64_t gc = cols.ground_cell(l);
  if (gc < 0) return;
  double* from = cols.ground.heights().data() + gc;
  const double g = *from;
  const Columns::View view = cols.view();
  // only a span whose top is at or below g can take it: none when every neighbour's lowest one's is above
  if (cols.neighbours_lowest_top(l) > g) return;
  if (g > cols.lowest_bottom(l)) return;  // under the object: not exposed
  const std::size_t first = fluxes->size();
  for (const std::int64_t step : cols.steps()) {
    // only a span whose top is at or below g can take it: none when the lowest one's is above (or there is none)
    if (cols.lowest_top(l + step) > g) continue;
    int k_to;
    double to_level_m;
    if (!view.lands(l + step, g, &k_to, &to_level_m) || k_to < 0) continue;  // onto a span only
    const double excess = g - to_level_m - rule.max_dh_m;
    if (excess > rule.tolerance_m) {
      fluxes->push_back(make_flux(rule.sigma * excess, from, Kind::kGround, l, view.landing(l + step, k_to), l + step,
                                  g, cols.n_spans));
    }
  }
  limit_to(g, fluxes->data() + first, fluxes->data() + fluxes->size());
}

// Which columns a pass changed, so that the next pass examines only them
// and their neighbours: a column's fluxes read its own surfaces and its four
// neighbours' only, so where none of these changed it would find the same
// fluxes again, and those all came to nothing (a source with nothing to
// give or a target with no room, unchanged since): skipping it changes no
// amount. A pass that finds only such fluxes is no longer counted.
class ChangedColumns {
 public:
  ChangedColumns(const Columns& cols, std::vector<char>* flags) : cols_(cols), flags_(*flags) {
    flags_.assign(cols.local_count(), 0);
  }
  // Local column l or a 4-neighbour changed in the last pass.
  bool near(std::int64_t l) const { return flags_[static_cast<std::size_t>(l)] != 0; }
  // Some column of row j is near().
  bool row_near(int j) const { return rows_[static_cast<std::size_t>(j - cols_.j0 + Columns::kPad)] != 0; }
  // Forgets the last pass's changes: only rows near a change have flags set.
  void forget() {
    const std::size_t stride = static_cast<std::size_t>(steps_[2]);
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      if (rows_[r]) std::fill_n(flags_.begin() + static_cast<std::ptrdiff_t>(r * stride), stride, 0), rows_[r] = 0;
    }
  }
  // Local column l changed: it and its neighbours (it is in the first ring at most: the padding holds them)
  // are near a change.
  void mark(std::int64_t l) {
    char* f = flags_.data() + l;
    if (*f & kChanged) return;  // marked already in this pass
    *f |= kChanged | kNear;
    for (const std::int64_t step : steps_) f[step] |= kNear;
    const std::size_t row = static_cast<std::size_t>(l / steps_[2]);
    rows_[row - 1] = rows_[row] = rows_[row + 1] = 1;
  }

 private:
  static constexpr char kNear = 1, kChanged = 2;  // flag bits: it or a neighbour changed; it changed
  const Columns& cols_;
  std::vector<char>& flags_;
  std::vector<char> rows_ = std::vector<char>(static_cast<std::size_t>(cols_.j1 - cols_.j0 + 1 + 2 * Columns::kPad), 0);
  const std::array<std::int64_t, 4> steps_ = cols_.steps();
};

// One pass's exchange: each target takes at most its room (a pass's inflows
// into it summed in flux order, in the object's scratch, all 0 between
// passes: only the entries a pass touched are cleared again, so a call
// costs what moves, not the map's size); the moves applied in flux order;
// material falling into air gathered per column and released as particles
// after the passes.
struct Exchange {
  const GroundModel& model;
  SpanMap& map;
  GroundState* ground;
  const Columns& cols;
  std::vector<double>& in;
  std::vector<double>& released_m;
  std::vector<double>& release_z;
  std::vector<double>& released_dx;  // the way the released material flowed: its amount-weighted sum of
  std::vector<double>& released_dy;  // column offsets
  std::vector<std::size_t>& released_at;  // the columns with released material, in the order they got it

  Exchange(const GroundModel& m, SpanMap& sm, GroundState* g, const Columns& c, SpanErosionScratch* scratch)
      : model(m), map(sm), ground(g), cols(c), in(scratch->in), released_m(scratch->released_m),
        release_z(scratch->release_z), released_dx(scratch->released_dx), released_dy(scratch->released_dy),
        released_at(scratch->released_at) {
    const std::size_t n_local = c.local_count();
    if (in.size() < sm.spans.size() + n_local) in.resize(sm.spans.size() + n_local, 0.0);
    if (released_m.size() < n_local) {
      released_m.resize(n_local, 0.0), release_z.resize(n_local, -kInf);
      released_dx.resize(n_local, 0.0), released_dy.resize(n_local, 0.0);
    }
    released_at.clear();
  }

  // Scales the fluxes (their sources' limits applied) to their targets' room, applies them, records the columns
  // they changed.
  void apply(std::vector<Flux>* fluxes, ChangedColumns* changed, SpanErosionResult* result) {
    for (const Flux& f : *fluxes) {
      if (f.to_kind != Kind::kAir) in[static_cast<std::size_t>(f.to_key)] += f.amount_m;
    }
    changed->forget();
    const double area = model.grid.cell_area_m2();
    const double* h = ground->height.heights().data();
    for (Flux& f : *fluxes) {
      if (f.to_kind != Kind::kAir) {
        const double total = in[static_cast<std::size_t>(f.to_key)];
        if (total > f.room_or_z_m) f.amount_m *= f.room_or_z_m / total;
      }
      if (!(f.amount_m > 0.0)) continue;
      ++result->moves;
      *f.from_m -= f.amount_m;
      changed->mark(f.from_local);
      if (f.from_kind == Kind::kGround) {
        result->from_ground_m3 += f.amount_m * area;
        ground->erosion.touch(f.from_m - h);
      }
      if (f.to_kind == Kind::kAir) {  // released after the passes
        const std::size_t l = static_cast<std::size_t>(f.to_local);
        if (!(released_m[l] > 0.0)) released_at.push_back(l);
        released_m[l] += f.amount_m;
        release_z[l] = std::max(release_z[l], f.room_or_z_m);
        released_dx[l] += f.amount_m * (cols.i_of(f.to_local) - cols.i_of(f.from_local));
        released_dy[l] += f.amount_m * (cols.j_of(f.to_local) - cols.j_of(f.from_local));
        result->to_particles_m3 += f.amount_m * area;
        continue;
      }
      changed->mark(f.to_local);
      *f.to_m += f.amount_m;
      if (f.to_kind == Kind::kGround) {
        result->to_ground_m3 += f.amount_m * area;
        ground->erosion.touch(f.to_m - h);
      }
    }
    for (const Flux& f : *fluxes) {
      if (f.to_kind != Kind::kAir) in[static_cast<std::size_t>(f.to_key)] = 0.0;
    }
  }

  // one particle per column the material left into, in the columns' order, moving with the object's point there and
  // at release_speed_m_s along the way it flowed; the sums are cleared
  void release(const RigidVelocity& velocity, double release_speed_m_s, double spread_m_s, ParticleSystem* particles,
               std::mt19937_64* rng) {
    std::sort(released_at.begin(), released_at.end());
    for (const std::size_t l : released_at) {
      const std::int64_t ll = static_cast<std::int64_t>(l);
      const int i = cols.i_of(ll), j = cols.j_of(ll);
      const Eigen::Vector3d at(map.grid.centre_x(i), map.grid.centre_y(j), release_z[l]);
      Eigen::Vector3d v = velocity.at(at);
      const Eigen::Vector3d way(released_dx[l], released_dy[l], 0.0);
      if (release_speed_m_s > 0.0 && way.norm() > 0.0) v += release_speed_m_s * way.normalized();
      particles->release({at, v, released_m[l] * model.grid.cell_area_m2()}, spread_m_s, rng);
      released_m[l] = 0.0;
      release_z[l] = -kInf;
      released_dx[l] = released_dy[l] = 0.0;
    }
    released_at.clear();
  }
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
                              const RigidVelocity& velocity, ObjectSpans* spans, GroundState* ground,
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
  ChangedColumns changed(cols, &spans->erosion_scratch.changed);
  for (int p = 0, passes = m.erosion_passes(g.cell_size_m); p < passes; ++p) {
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
    exchange.apply(&fluxes, &changed, &result);
  }
  exchange.release(velocity, model.options.release_speed_m_s, model.options.particle_spread_m_s, particles, rng);
  return result;
}

}  // namespace repose
