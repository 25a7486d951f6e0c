#include "models/heightspan/span_map.h"

#include <algorithm>
#include <cmath>

namespace repose {

namespace {

bool lex_less(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
}

// Twice the signed area of (u, v, p), evaluated from the lexicographically
// smaller end of the edge, so both triangles of an edge get the same number
// with opposite signs (no round-off can make a centre miss both or hit both).
double edge_function(const Eigen::Vector2d& u, const Eigen::Vector2d& v, const Eigen::Vector2d& p) {
  auto raw = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& q) {
    return (b.x() - a.x()) * (q.y() - a.y()) - (b.y() - a.y()) * (q.x() - a.x());
  };
  return lex_less(u, v) ? raw(u, v, p) : -raw(v, u, p);
}

// Top-left rule for a counter-clockwise triangle (y up): a centre exactly on
// an edge is inside only for left edges (going down) and top edges
// (horizontal, going left).
bool owns_edge(const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
  return v.y() < u.y() || (v.y() == u.y() && v.x() < u.x());
}

// One edge (u, v) of a triangle being rasterised: what edge_function and
// covers work out from its ends alone, once per triangle instead of once per
// cell. at(p) is edge_function(u, v, p), to the bit: the same operations
// from the same end, then negated or not.
struct Edge {
  double ox, oy, dx, dy;  // the lexicographically smaller end and the vector to the other
  bool negate, owned;

  Edge(const Eigen::Vector2d& u, const Eigen::Vector2d& v) : negate(!lex_less(u, v)), owned(owns_edge(u, v)) {
    const Eigen::Vector2d& a = negate ? v : u;
    const Eigen::Vector2d& b = negate ? u : v;
    ox = a.x(), oy = a.y(), dx = b.x() - a.x(), dy = b.y() - a.y();
  }
  double at(double px, double py) const { return from_row(row(py), px); }
  // at(px, py) in two parts: row(py) is the same for a row of centres, so it is worked out once per row
  // (the same product as at() forms, so the same bits).
  double row(double py) const { return dx * (py - oy); }
  double from_row(double row_term, double px) const {
    const double w = row_term - dy * (px - ox);
    return negate ? -w : w;
  }
  bool covers(double w) const { return w > 0.0 || (w == 0.0 && owned); }
};

void rasterise(Eigen::Vector3d a, Eigen::Vector3d b, Eigen::Vector3d c, const Grid& grid, std::vector<SpanHit>* hits) {
  const double area = edge_function(a.head<2>(), b.head<2>(), c.head<2>());
  if (area == 0.0) return;  // vertical: seen edge-on
  const int winding = area < 0.0 ? +1 : -1;  // counter-clockwise from above: turned up, the ray leaves
  if (area < 0.0) std::swap(b, c);
  const Eigen::Vector2d a2 = a.head<2>(), b2 = b.head<2>(), c2 = c.head<2>();
  const double h = grid.cell_size_m;
  auto range = [&](double lo, double hi, double origin, int n, int* first, int* last) {
    *first = std::max(0, static_cast<int>(std::ceil((lo - origin) / h - 0.5)) - 1);
    *last = std::min(n - 1, static_cast<int>(std::floor((hi - origin) / h - 0.5)) + 1);
  };
  int i0, i1, j0, j1;
  range(std::min({a.x(), b.x(), c.x()}), std::max({a.x(), b.x(), c.x()}), grid.origin_x_m, grid.nx, &i0, &i1);
  range(std::min({a.y(), b.y(), c.y()}), std::max({a.y(), b.y(), c.y()}), grid.origin_y_m, grid.ny, &j0, &j1);
  const Edge ea(b2, c2), eb(c2, a2), ec(a2, b2);
  for (int j = j0; j <= j1; ++j) {
    const double py = grid.centre_y(j);
    const double ra = ea.row(py), rb = eb.row(py), rc = ec.row(py);
    for (int i = i0; i <= i1; ++i) {
      const double px = grid.centre_x(i);
      const double wa = ea.from_row(ra, px);
      if (!ea.covers(wa)) continue;  // the other edges only where this one covers the centre
      const double wb = eb.from_row(rb, px);
      if (!eb.covers(wb)) continue;
      const double wc = ec.from_row(rc, px);
      if (!ec.covers(wc)) continue;
      const double sum = wa + wb + wc;
      if (!(sum > 0.0)) continue;
      const double z = (wa * a.z() + wb * b.z() + wc * c.z()) / sum;
      hits->push_back({static_cast<std::int64_t>(j) * grid.nx + i, z, winding});
    }
  }
}

// Sorts the hits by cell, then height, entries before exits at one height:
// by cell with a counting sort (a cell has a few hits), then each cell's
// by insertion. Hits that compare equal are equal in every field, so the
// order is the one any sort gives.
void sort_hits(std::vector<SpanHit>* hits, std::size_t cell_count) {
  std::vector<std::size_t> start(cell_count + 1, 0);
  for (const SpanHit& h : *hits) ++start[static_cast<std::size_t>(h.cell) + 1];
  for (std::size_t c = 0; c < cell_count; ++c) start[c + 1] += start[c];
  std::vector<SpanHit> sorted(hits->size());
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  for (const SpanHit& h : *hits) sorted[next[static_cast<std::size_t>(h.cell)]++] = h;
  auto before = [](const SpanHit& a, const SpanHit& b) { return a.z < b.z || (a.z == b.z && a.winding > b.winding); };
  for (std::size_t c = 0; c < cell_count; ++c) {
    for (std::size_t k = start[c] + 1; k < start[c + 1]; ++k) {
      const SpanHit h = sorted[k];
      std::size_t m = k;
      for (; m > start[c] && before(h, sorted[m - 1]); --m) sorted[m] = sorted[m - 1];
      sorted[m] = h;
    }
  }
  *hits = std::move(sorted);
}

}  // namespace

double SpanMap::material_m3() const {
  double sum = 0.0;
  for (const Span& s : spans) sum += s.material_m;
  return sum * grid.cell_area_m2();
}

bool SpanMap::cell_at(double x_m, double y_m, int* i, int* j) const {
  const double fi = std::floor((x_m - grid.origin_x_m) / grid.cell_size_m);
  const double fj = std::floor((y_m - grid.origin_y_m) / grid.cell_size_m);
  if (!(fi >= 0.0 && fj >= 0.0 && fi < grid.nx && fj < grid.ny)) return false;
  *i = static_cast<int>(fi);
  *j = static_cast<int>(fj);
  return true;
}

SpanMap peel_spans(const TriangleMesh& mesh, const Grid& grid) {
  std::vector<SpanHit> hits;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    rasterise(mesh.V.row(mesh.F(f, 0)), mesh.V.row(mesh.F(f, 1)), mesh.V.row(mesh.F(f, 2)), grid, &hits);
  }
  return spans_from_hits(std::move(hits), grid);
}

SpanMap spans_from_hits(std::vector<SpanHit> hits, const Grid& grid) {
  // bottom to top per cell; at one height entries first, so touching parts merge
  sort_hits(&hits, grid.cell_count());
  SpanMap map;
  map.grid = grid;
  map.first.assign(grid.cell_count() + 1, 0);
  const double thin_m = 1e-9 * grid.cell_size_m;
  std::size_t k = 0;
  for (std::int64_t c = 0; c < static_cast<std::int64_t>(grid.cell_count()); ++c) {
    map.first[c] = static_cast<std::int32_t>(map.spans.size());
    int inside = 0;
    double bottom = 0.0;
    for (; k < hits.size() && hits[k].cell == c; ++k) {
      const int before = inside;
      inside += hits[k].winding;
      if (before <= 0 && inside > 0) bottom = hits[k].z;
      if (before > 0 && inside <= 0 && hits[k].z - bottom > thin_m) {
        const std::size_t first = static_cast<std::size_t>(map.first[c]);
        if (map.spans.size() > first && bottom - map.spans.back().top_m <= thin_m) {
          map.spans.back().top_m = hits[k].z;  // touching: one span
        } else {
          map.spans.push_back({bottom, hits[k].z, 0.0});
        }
      }
    }
  }
  map.first[grid.cell_count()] = static_cast<std::int32_t>(map.spans.size());
  return map;
}

int span_under(const SpanMap& map, std::int64_t cell, double z_m) {
  const Span* s = map.begin(cell);
  for (int k = map.count(cell) - 1; k >= 0; --k) {
    if (s[k].bottom_m <= z_m) return k;
  }
  return -1;
}

double push_overflow_up(SpanMap* map, std::int64_t cell) {
  Span* s = map->begin(cell);
  const int n = map->count(cell);
  double moved = 0.0;
  for (int k = 0; k + 1 < n; ++k) {
    const double over = s[k].level_m() - s[k + 1].bottom_m;
    if (!(over > 0.0)) continue;
    const double amount = std::min(over, s[k].material_m);
    s[k].material_m -= amount;
    s[k + 1].material_m += amount;
    moved += amount;
  }
  return moved;
}

}  // namespace repose
