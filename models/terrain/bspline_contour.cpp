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

Polygon2 sample_closed_bspline(const Polygon2& control, double spacing_m) {
  const std::size_t n = control.size();
  REPOSE_DEMAND(n >= 3 && spacing_m > 0.0);
  Polygon2 out;
  for (std::size_t i = 0; i < n; ++i) {
    const Point2& p0 = control[(i + n - 1) % n];
    const Point2& p1 = control[i];
    const Point2& p2 = control[(i + 1) % n];
    const Point2& p3 = control[(i + 2) % n];
    // the derivative of a cubic span is a quadratic B-spline of the three
    // control differences, so the span is no longer than the longest of them
    const double span_bound = std::max({(p1 - p0).norm(), (p2 - p1).norm(), (p3 - p2).norm()});
    const int samples = std::max(1, static_cast<int>(std::ceil(span_bound / spacing_m)));
    for (int k = 0; k < samples; ++k) {
      const Point2 p = bspline_point(p0, p1, p2, p3, static_cast<double>(k) / samples);
      // collinear control points repeat the same point when cuts are tiny
      if (out.empty() || (p - out.back()).norm() > 1e-9 * spacing_m) out.push_back(p);
    }
  }
  while (out.size() > 1 && (out.back() - out.front()).norm() <= 1e-9 * spacing_m) out.pop_back();
  return out;
}

Polygon2 smoothed_contour(const Polygon2& polygon, double tolerance_m, double spacing_m) {
  return sample_closed_bspline(bspline_control_points(polygon, tolerance_m), spacing_m);
}

}  // namespace repose
