#include "models/terrain/polygon_2d.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/core/base/error.h"

namespace repose {

namespace {

double cross(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

int sign(double v) { return (v > 0.0) - (v < 0.0); }

// c is on segment [a, b] given that the three are collinear
bool within_box(const Point2& a, const Point2& b, const Point2& c) {
  return std::min(a.x(), b.x()) <= c.x() && c.x() <= std::max(a.x(), b.x()) && std::min(a.y(), b.y()) <= c.y() &&
         c.y() <= std::max(a.y(), b.y());
}

bool boxes_apart(const Point2& a, const Point2& b, const Point2& c, const Point2& d, double margin) {
  return std::max(a.x(), b.x()) + margin < std::min(c.x(), d.x()) ||
         std::max(c.x(), d.x()) + margin < std::min(a.x(), b.x()) ||
         std::max(a.y(), b.y()) + margin < std::min(c.y(), d.y()) ||
         std::max(c.y(), d.y()) + margin < std::min(a.y(), b.y());
}

}  // namespace

double signed_area_m2(const Polygon2& polygon) {
  double twice = 0.0;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

Polygon2 counter_clockwise(Polygon2 polygon) {
  if (signed_area_m2(polygon) < 0.0) std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

bool contains_point(const Polygon2& polygon, const Point2& p) {
  bool inside = false;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0, j = n - 1; i < n; j = i++) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x) inside = !inside;
    }
  }
  return inside;
}

bool segments_intersect(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  if (boxes_apart(a, b, c, d, 0.0)) return false;
  const int d1 = sign(cross(c, d, a));
  const int d2 = sign(cross(c, d, b));
  const int d3 = sign(cross(a, b, c));
  const int d4 = sign(cross(a, b, d));
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && within_box(c, d, a)) || (d2 == 0 && within_box(c, d, b)) || (d3 == 0 && within_box(a, b, c)) ||
         (d4 == 0 && within_box(a, b, d));
}

double point_segment_distance_m(const Point2& p, const Point2& a, const Point2& b) {
  const Point2 ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

double segment_distance_m(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  if (segments_intersect(a, b, c, d)) return 0.0;
  return std::min({point_segment_distance_m(a, c, d), point_segment_distance_m(b, c, d),
                   point_segment_distance_m(c, a, b), point_segment_distance_m(d, a, b)});
}

bool is_simple(const Polygon2& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    if ((polygon[(i + 1) % n] - polygon[i]).norm() == 0.0) return false;
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      const Point2& a = polygon[i];
      const Point2& b = polygon[(i + 1) % n];
      const Point2& c = polygon[j];
      const Point2& d = polygon[(j + 1) % n];
      if (adjacent) {
        // adjacent edges may only share their common vertex: reject folding back
        const Point2& shared = (j == i + 1) ? b : a;
        const Point2& far_ij = (j == i + 1) ? a : b;
        const Point2& far_other = (j == i + 1) ? d : c;
        if (cross(shared, far_ij, far_other) == 0.0 && (far_ij - shared).dot(far_other - shared) > 0.0) return false;
        continue;
      }
      if (segments_intersect(a, b, c, d)) return false;
    }
  }
  return true;
}

bool boundaries_cross(const Polygon2& a, const Polygon2& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (segments_intersect(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) return true;
    }
  }
  return false;
}

double boundary_distance_m(const Polygon2& a, const Polygon2& b) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Point2& p = a[i];
    const Point2& q = a[(i + 1) % a.size()];
    for (std::size_t j = 0; j < b.size(); ++j) {
      const Point2& r = b[j];
      const Point2& s = b[(j + 1) % b.size()];
      if (boxes_apart(p, q, r, s, best)) continue;
      best = std::min(best, segment_distance_m(p, q, r, s));
      if (best == 0.0) return 0.0;
    }
  }
  return best;
}

bool nested_inside(const Polygon2& a, const Polygon2& b) {
  return !a.empty() && !boundaries_cross(a, b) && contains_point(b, a.front());
}

Polygon2 densified(const Polygon2& polygon, double spacing_m) {
  REPOSE_DEMAND(spacing_m > 0.0);
  Polygon2 out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& a = polygon[i];
    const Point2& b = polygon[(i + 1) % n];
    const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing_m)));
    for (int k = 0; k < pieces; ++k) out.push_back(a + (b - a) * (static_cast<double>(k) / pieces));
  }
  return out;
}

}  // namespace repose
