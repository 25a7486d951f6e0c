#include "models/terrain/bspline_contour.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "tests/models/terrain/terrain_fixtures.h"

namespace repose {
namespace {

double distance_to_polygon_m(const Point2& p, const Polygon2& polygon) {
  double best = INFINITY;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    best = std::min(best, point_segment_distance_m(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  }
  return best;
}

TEST(BsplineContour, StaysWithinToleranceOfThePolygon) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    std::mt19937_64 rng(seed);
    const Polygon2 star = counter_clockwise(test::random_star_polygon(&rng, 10.0, 16));
    for (double tolerance : {0.05, 0.3, 1.0}) {
      const Polygon2 smooth = smoothed_contour(star, tolerance, 0.2);
      // the samples lie on the curve, within the tolerance; the chords
      // between them within (1 + kChordDeviationFraction) tolerances
      double worst = 0.0, worst_chord = 0.0;
      for (std::size_t i = 0; i < smooth.size(); ++i) {
        worst = std::max(worst, distance_to_polygon_m(smooth[i], star));
        const Point2& next = smooth[(i + 1) % smooth.size()];
        for (double t : {0.25, 0.5, 0.75}) {
          worst_chord = std::max(worst_chord, distance_to_polygon_m(smooth[i] + t * (next - smooth[i]), star));
        }
      }
      EXPECT_LE(worst, tolerance + 1e-12) << "seed " << seed;
      EXPECT_LE(worst_chord, (1.0 + kChordDeviationFraction) * tolerance + 1e-12) << "seed " << seed;
      EXPECT_TRUE(is_simple(smooth)) << "seed " << seed;
    }
  }
}

TEST(BsplineContour, RoundsCornersAndKeepsStraightEdges) {
  const Polygon2 square = test::rectangle_polygon(0, 0, 10, 10);
  const Polygon2 smooth = smoothed_contour(square, 0.5, 0.25);
  // the corner is cut: no sample reaches it, the closest is a / 3 inside
  double closest = INFINITY;
  for (const Point2& p : smooth) closest = std::min(closest, p.norm());
  EXPECT_GT(closest, 0.1);
  // mid-edge samples lie on the edge exactly
  int on_edge = 0;
  for (const Point2& p : smooth) {
    if (p.x() > 1.0 && p.x() < 9.0 && std::abs(p.y()) < 1e-12) ++on_edge;
  }
  EXPECT_GT(on_edge, 20);
  for (std::size_t i = 0; i < smooth.size(); ++i) {
    EXPECT_LE((smooth[(i + 1) % smooth.size()] - smooth[i]).norm(), 0.25 + 1e-12);
  }
}

TEST(BsplineContour, CrowdedControlPointsGiveNoCrowdedSamples) {
  // a polygon with a 1 mm edge: its control points crowd there, the samples do not
  const Polygon2 notch = {Point2(0, 0), Point2(10, 0), Point2(10, 5), Point2(5.001, 5), Point2(5, 5.001),
                          Point2(0, 5)};
  const Polygon2 smooth = smoothed_contour(notch, 0.5, 1.0);
  double shortest = INFINITY;
  for (std::size_t i = 0; i < smooth.size(); ++i) {
    shortest = std::min(shortest, (smooth[(i + 1) % smooth.size()] - smooth[i]).norm());
  }
  EXPECT_GT(shortest, 0.05);
}

TEST(BsplineContour, ShortEdgesLimitTheCut) {
  // corners 0.1 apart: the cut is at most 0.045 so neighbouring cuts never overlap
  const Polygon2 thin = test::rectangle_polygon(0, 0, 5, 0.1);
  const Polygon2 control = bspline_control_points(thin, 1.0);
  EXPECT_TRUE(is_simple(control));
  const Polygon2 smooth = sample_closed_bspline(control, 0.05, 0.01);
  EXPECT_TRUE(is_simple(smooth));
  EXPECT_GT(signed_area_m2(smooth), 0.0);
}

}  // namespace
}  // namespace repose
