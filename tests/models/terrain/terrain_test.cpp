#include "models/terrain/terrain.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "models/core/base/error.h"
#include "models/terrain/terrain_surface.h"
#include "tests/models/terrain/terrain_checks.h"
#include "tests/models/terrain/terrain_fixtures.h"

namespace repose {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

TerrainOptions cone_options() {
  TerrainOptions o;
  o.slope_rad = 30.0 * kDeg;
  o.contour_interval_m = 2.0;
  o.smoothing_tolerance_m = 0.3;
  o.sample_spacing_m = 2.0;
  o.cell_size_m = 2.0;
  return o;
}

// Concentric circles 100 m and 70 m, the inner at the height the slope gives.
std::vector<KeyContour> cone_contours(double slope_rad) {
  return {{"foot", test::circle_polygon(Point2(0, 0), 100.0, 96), 0.0},
          {"shoulder", test::circle_polygon(Point2(0, 0), 70.0, 96), 30.0 * std::tan(slope_rad)}};
}

// Several rises: a star-shaped foot holding two peaks.
std::vector<KeyContour> multi_peak_contours(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Polygon2 foot = test::random_star_polygon(&rng, 120.0, 20);
  for (Point2& p : foot) p.x() *= 1.5;
  Polygon2 west = test::random_star_polygon(&rng, 20.0, 9);
  for (Point2& p : west) p.x() -= 45.0;
  std::uniform_real_distribution<double> height(12.0, 30.0);
  const double west_height_m = height(rng);
  return {{"foot", foot, 0.0}, {"west", west, west_height_m},
          {"east", test::circle_polygon(Point2(45, 5), 15.0, 24), height(rng)}};
}

TEST(Terrain, ConeFromConcentricCirclesHasTheConesSlope) {
  const TerrainOptions o = cone_options();
  const Terrain t = build_terrain(cone_contours(o.slope_rad), o);
  const TerrainSurface surface(t.mesh);
  // least-squares slope of h against the radius, and the worst height error,
  // over the mesh between r = 5 m and r = 95 m
  double sr = 0, sh = 0, srr = 0, srh = 0, n = 0, worst = 0;
  for (double r = 5.0; r <= 95.0; r += 2.5) {
    for (int k = 0; k < 36; ++k) {
      const double a = 2.0 * std::numbers::pi * (k + 0.5) / 36;
      const std::optional<double> h = surface.height_at(Point2(r * std::cos(a), r * std::sin(a)));
      ASSERT_TRUE(h.has_value()) << r;
      sr += r, sh += *h, srr += r * r, srh += r * *h, n += 1;
      worst = std::max(worst, std::abs(*h - (100.0 - r) * std::tan(o.slope_rad)));
    }
  }
  const double slope = -(n * srh - sr * sh) / (n * srr - sr * sr);
  EXPECT_NEAR(slope, std::tan(o.slope_rad), 0.01 * std::tan(o.slope_rad));
  // polygon circles (1 - cos(pi/96)) * 100 m = 0.05 m and smoothing (0.3 m) times tan 30
  EXPECT_LT(worst, 0.5);
  EXPECT_NEAR(t.summary.max_height_m, 100.0 * std::cos(std::numbers::pi / 96) * std::tan(o.slope_rad), 0.05);
}

TEST(Terrain, HeightsAtContourVerticesAreExact) {
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    const Terrain t = build_terrain(multi_peak_contours(seed), cone_options());
    const TerrainSurface surface(t.mesh);
    for (const TerrainContour& c : t.contours.contours) {
      for (const Point2& p : c.polygon_m) {
        const std::optional<double> h = surface.height_at(p);
        ASSERT_TRUE(h.has_value()) << "seed " << seed;
        EXPECT_NEAR(*h, c.height_m, 1e-9 * (1.0 + std::abs(c.height_m))) << "seed " << seed;
      }
    }
  }
}

TEST(Terrain, ContoursNeverCross) {
  for (std::uint64_t seed = 1; seed <= 8; ++seed) {
    const Terrain t = build_terrain(multi_peak_contours(seed), cone_options());
    EXPECT_EQ(test::first_contour_crossing(t.contours), "") << "seed " << seed;
    EXPECT_GT(t.summary.contour_count, 10) << "seed " << seed;
  }
}

TEST(Terrain, MeshIsAHeightFieldOverTheOuterContour) {
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const Terrain t = build_terrain(multi_peak_contours(seed), cone_options());
    const Polygon2& foot = t.keys[0].polygon_m;
    double area = 0.0;
    for (int f = 0; f < t.mesh.F.rows(); ++f) {
      const double a = test::xy_area_m2(t.mesh, f);
      EXPECT_GT(a, 0.0) << "seed " << seed << " face " << f;  // upward, never folded over
      area += a;
    }
    EXPECT_NEAR(area, signed_area_m2(foot), 1e-9 * signed_area_m2(foot)) << "seed " << seed;
    // every vertical line inside the foot meets exactly one face
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> x(-180.0, 180.0), y(-120.0, 120.0);
    int inside = 0;
    while (inside < 200) {
      const Point2 p(x(rng), y(rng));
      if (!contains_point(foot, p)) continue;
      ++inside;
      EXPECT_EQ(test::faces_over(t.mesh, p), 1) << "seed " << seed << " at " << p.transpose();
    }
  }
}

TEST(Terrain, FewSlivers) {
  // the B-spline samples are thinned and crowded skeleton nodes merged, so
  // under 0.5 % of the triangles have an angle below 3 deg (0.13-0.27 %
  // measured; before thinning, 30 % were below 5 deg). What remains: corners rounded by a
  // small tolerance (0.3 m here) next to contours 6 m apart.
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const Terrain t = build_terrain(multi_peak_contours(seed), cone_options());
    int slivers = 0;
    for (int f = 0; f < t.mesh.F.rows(); ++f) {
      for (int k = 0; k < 3; ++k) {
        const Eigen::Vector2d a = t.mesh.V.row(t.mesh.F(f, k)).head<2>();
        const Eigen::Vector2d b = t.mesh.V.row(t.mesh.F(f, (k + 1) % 3)).head<2>();
        const Eigen::Vector2d c = t.mesh.V.row(t.mesh.F(f, (k + 2) % 3)).head<2>();
        const double cosine = (b - a).dot(c - a) / ((b - a).norm() * (c - a).norm());
        if (cosine > std::cos(3.0 * kDeg)) {
          ++slivers;
          break;
        }
      }
    }
    EXPECT_LT(slivers, t.mesh.F.rows() / 200) << "seed " << seed;
  }
}

TEST(Terrain, SameInputSameBits) {
  const Terrain a = build_terrain(multi_peak_contours(3), cone_options());
  const Terrain b = build_terrain(multi_peak_contours(3), cone_options());
  ASSERT_EQ(a.mesh.V.rows(), b.mesh.V.rows());
  ASSERT_EQ(a.mesh.F.rows(), b.mesh.F.rows());
  EXPECT_TRUE((a.mesh.V.array() == b.mesh.V.array()).all());
  EXPECT_TRUE((a.mesh.F.array() == b.mesh.F.array()).all());
  EXPECT_TRUE((a.height_field.heights() == b.height_field.heights()).all());
}

TEST(Terrain, HeightFieldSamplesTheMeshAndThePlainOutside) {
  const TerrainOptions o = cone_options();
  const Terrain t = build_terrain(cone_contours(o.slope_rad), o);
  const TerrainSurface surface(t.mesh);
  const HeightField& hf = t.height_field;
  ASSERT_TRUE(hf.all_finite());
  for (int j = 0; j < hf.ny(); ++j) {
    for (int i = 0; i < hf.nx(); ++i) {
      const std::optional<double> h = surface.height_at(Point2(hf.grid().centre_x(i), hf.grid().centre_y(j)));
      EXPECT_DOUBLE_EQ(hf.at(i, j), h.value_or(0.0));
    }
  }
  EXPECT_DOUBLE_EQ(hf.at(0, 0), 0.0);  // a corner is outside the foot circle
}

TEST(Terrain, InvalidOptionsNameTheField) {
  TerrainOptions o = cone_options();
  o.slope_rad = 0.0;
  try {
    build_terrain(cone_contours(0.5), o);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("slope_deg"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
