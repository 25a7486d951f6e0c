#include "models/terrain/bspline_contour.h"

#include <algorithm>
#include <cmath>

#include "models/core/base/error.h"

namespace repose {

namespace {

// a corner cut shorter than this fraction of the tolerance adds nothing
constexpr double kNegligibleCut = 1e-6;

Point2 bspline_point(const Point2& p0, const Point2& p1, const Point2& p2, const Point2& p3, double t) {
  const double s = 1.0 - t;
  const double b0 = s * s * s / 6.0;
  const double b1 = (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0;
  const double b2 = (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0;
  const double b3 = t * t * t / 6.0;
  return b0 * p0 + b1 * p1 + b2 * p2 + b3 * p3;
}

}  // namespace

Polygon2 bspline_control_points(const Polygon2& polygon, double tolerance_m) {
  const std::size_t n = polygon.size();
  REPOSE_DEMAND(n >= 3 && tolerance_m > 0.0);
  Polygon2 control;
  control.reserve(3 * n);
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& prev = polygon[(i + n - 1) % n];
    const Point2& v = polygon[i];
    const Point2& next = polygon[(i + 1) % n];
    const double len_in = (v - prev).norm();
    const double len_out = (next - v).norm();
    // 0.45 keeps the cuts of two neighbouring corners apart on a short edge
    const double cut = std::min({tolerance_m, 0.45 * len_in, 0.45 * len_out});
    if (cut <= kNegligibleCut * tolerance_m) {
      control.push_back(v);
      continue;
    }
    control.push_back(v + (prev - v) * (cut / len_in));
    control.push_back(v);
    control.push_back(v + (next - v) * (cut / len_out));
  }
  return control;
}

namespace {

// The curve evaluated finely: every span at least kSamplesPerSpan times and
// at most spacing / 8 apart, so thinning has points to choose from.
constexpr int kSamplesPerSpan = 8;

Polygon2 dense_curve(const Polygon2& control, double spacing_m) {
  const std::size_t n = control.size();
  Polygon2 out;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& p0 = control[(i + n - 1) % n];
    const Point2& p1 = control[i];
    const Point2& p2 = control[(i + 1) % n];
    const Point2& p3 = control[(i + 2) % n];
    // the derivative of a cubic span is a quadratic B-spline of the three
    // control differences, so the span is no longer than the longest of them
    const double span_bound = std::max({(p1 - p0).norm(), (p2 - p1).norm(), (p3 - p2).norm()});
    const int samples = std::max(kSamplesPerSpan, static_cast<int>(std::ceil(8.0 * span_bound / spacing_m)));
    for (int k = 0; k < samples; ++k) out.push_back(bspline_point(p0, p1, p2, p3, static_cast<double>(k) / samples));
  }
  return out;
}

// dense[i..j] (cyclic indices, j > i) stays within max_deviation_m of the chord
bool chord_fits(const Polygon2& dense, std::size_t i, std::size_t j, double max_deviation_m) {
  const std::size_t n = dense.size();
  const Point2& a = dense[i % n];
  const Point2& b = dense[j % n];
  for (std::size_t k = i + 1; k < j; ++k) {
    if (point_segment_distance_m(dense[k % n], a, b) > max_deviation_m) return false;
  }
  return true;
}

}  // namespace

Polygon2 sample_closed_bspline(const Polygon2& control, double spacing_m, double max_deviation_m) {
  REPOSE_DEMAND(control.size() >= 3 && spacing_m > 0.0 && max_deviation_m > 0.0);
  const Polygon2 dense = dense_curve(control, spacing_m);
  const std::size_t n = dense.size();
  // greedy thinning: from each kept point, the farthest point whose chord is
  // no longer than spacing_m and no farther than max_deviation_m from the curve
  Polygon2 out;
  std::size_t i = 0;
  while (i < n) {
    out.push_back(dense[i]);
    std::size_t j = i + 1;
    while (j + 1 <= n && (dense[(j + 1) % n] - dense[i]).norm() <= spacing_m &&
           chord_fits(dense, i, j + 1, max_deviation_m)) {
      ++j;
    }
    i = j;
  }
  return out;
}

Polygon2 smoothed_contour(const Polygon2& polygon, double tolerance_m, double spacing_m) {
  return sample_closed_bspline(bspline_control_points(polygon, tolerance_m), spacing_m,
                               kChordDeviationFraction * tolerance_m);
}

}  // namespace repose
