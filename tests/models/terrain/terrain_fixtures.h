#pragma once
// Polygons the terrain tests share: circles, rectangles, an L, random star
// and convex polygons from a seeded generator.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "models/terrain/polygon_2d.h"

namespace repose::test {

inline Polygon2 circle_polygon(const Point2& centre, double radius_m, int sides) {
  Polygon2 p;
  for (int k = 0; k < sides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / sides;
    p.emplace_back(centre.x() + radius_m * std::cos(a), centre.y() + radius_m * std::sin(a));
  }
  return p;
}

inline Polygon2 rectangle_polygon(double x0, double y0, double x1, double y1) {
  return {Point2(x0, y0), Point2(x1, y0), Point2(x1, y1), Point2(x0, y1)};
}

// arms of width 1, lengths 4 (along x) and 3 (along y)
inline Polygon2 l_polygon() {
  return {Point2(0, 0), Point2(4, 0), Point2(4, 1), Point2(1, 1), Point2(1, 3), Point2(0, 3)};
}

// A star-shaped polygon (simple, counter-clockwise): radii drawn in
// [0.5, 1] * radius_m at evenly spaced angles, so it has reflex vertices.
inline Polygon2 random_star_polygon(std::mt19937_64* rng, double radius_m, int sides) {
  std::uniform_real_distribution<double> r(0.5 * radius_m, radius_m);
  Polygon2 p;
  for (int k = 0; k < sides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / sides;
    const double rk = r(*rng);
    p.emplace_back(rk * std::cos(a), rk * std::sin(a));
  }
  return p;
}

// A convex polygon: points at sorted random angles on an ellipse.
inline Polygon2 random_convex_polygon(std::mt19937_64* rng, int sides) {
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  std::uniform_real_distribution<double> axis(1.0, 4.0);
  const double ax = axis(*rng), ay = axis(*rng);
  std::vector<double> angles(sides);
  for (double& a : angles) a = angle(*rng);
  std::sort(angles.begin(), angles.end());
  Polygon2 p;
  for (double a : angles) p.emplace_back(ax * std::cos(a), ay * std::sin(a));
  return p;
}

}  // namespace repose::test
