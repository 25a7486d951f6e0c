#include "models/snow/snow_probability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "snow_fixtures.h"

namespace repose {
namespace {

using testing::centred_grid;
using testing::plate;
using testing::plates_over_ground;

constexpr double kDeg = std::numbers::pi / 180.0;

TEST(SnowProbability, FlatOpenGroundIsLitEverywhere) {
  const HeightField ground(centred_grid(16), 0.02);
  SnowOptions o;
  o.direction_count = 32;
  o.main_direction = {20 * kDeg, 30 * kDeg};
  const SnowModel model = plates_over_ground(ground, {}, o);
  const SnowProbability p = snow_probability_shadow_maps(model, snowfall_directions(model, SnowParams{0.5, 15 * kDeg}));
  EXPECT_TRUE((p.per_map[0] == 1.0).all()) << p.per_map[0];
}

// Vertical snow at spread 0: the plate shadows exactly its footprint on the
// ground; the plate itself is lit; mirror-symmetric like the scene.
TEST(SnowProbability, PlateUnderVerticalSnowShadowsExactlyItsFootprint) {
  const HeightField ground(centred_grid(20));
  const SnowModel model = plates_over_ground(ground, {plate(0.04, 0.03, 0.05)}, testing::vertical_snow_options(4));
  const SnowProbability p = snow_probability_shadow_maps(model, snowfall_directions(model, SnowParams{0.5, 0.0}));
  const Grid& g = model.grid;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const bool under = model.maps[1].covered(i, j);
      EXPECT_EQ(p.per_map[0](j, i), under ? 0.0 : 1.0) << i << "," << j;
      EXPECT_EQ(p.per_map[1](j, i), under ? 1.0 : 0.0) << i << "," << j;
    }
  }
  EXPECT_TRUE((p.per_map[0] == p.per_map[0].rowwise().reverse()).all());
  EXPECT_TRUE((p.per_map[0] == p.per_map[0].colwise().reverse()).all());
}

// Spread > 0: snow reaches under the plate's edges (values strictly between
// 0 and 1 appear), the middle of the footprint stays dry, and the ground's
// probability is symmetric to within the sampling error of N directions.
TEST(SnowProbability, SpreadBlursTheShadowSymmetrically) {
  const HeightField ground(centred_grid(24));
  const SnowModel model = plates_over_ground(ground, {plate(0.06, 0.06, 0.04)}, testing::vertical_snow_options(1024));
  const SnowProbability p = snow_probability_shadow_maps(model, snowfall_directions(model, SnowParams{0.5, 10 * kDeg}));
  const ArrayXXdR& ground_p = p.per_map[0];
  EXPECT_EQ(ground_p(12, 12), 0.0);  // 6 cm in from every edge under a 3 cm high underside: needs 63 deg, > 6 sigma
  const int partial = ((ground_p > 0.0) && (ground_p < 1.0)).count();
  EXPECT_GT(partial, 40) << ground_p;
  // binomial error of one cell is at most 0.5 / sqrt(1024) = 0.016
  EXPECT_LT((ground_p - ground_p.rowwise().reverse()).abs().maxCoeff(), 6 * 0.016);
  EXPECT_LT((ground_p - ground_p.transpose()).abs().maxCoeff(), 6 * 0.016);
  EXPECT_TRUE((p.per_map[1] == 1.0 || !model.maps[1].base.covered.cast<bool>()).all());
}

// The RMS error of P over the ground's cells against N = 1024 falls as
// 1/sqrt(N) for N = 4 ... 256 (a mean of N Bernoulli draws per cell). Each
// N uses its own seed so the estimates are independent of the reference;
// the reference's own error (~1/32 of a single draw's) adds a floor that
// flattens the curve at large N, hence the loose bounds on the slope.
TEST(SnowProbability, ErrorFallsAsOneOverSquareRootOfDirections) {
  const HeightField ground(centred_grid(16));
  const std::vector<TriangleMesh> plates = {plate(0.03, 0.03, 0.03)};
  auto probability = [&](int n, std::uint64_t seed) {
    SnowOptions o = testing::vertical_snow_options(n);
    o.main_direction = {15 * kDeg, 0.0};
    const SnowModel model = plates_over_ground(ground, plates, o, seed);
    return snow_probability_shadow_maps(model, snowfall_directions(model, SnowParams{0.5, 15 * kDeg})).per_map[0];
  };
  const ArrayXXdR reference = probability(1024, 1000);
  std::vector<double> log_n, log_err;
  for (int n = 4; n <= 256; n *= 4) {
    double mean_square = 0.0;
    const int seeds = 4;
    for (int s = 0; s < seeds; ++s) {
      mean_square += (probability(n, 10 + s) - reference).square().mean() / seeds;
    }
    log_n.push_back(std::log(n));
    log_err.push_back(0.5 * std::log(mean_square));
    std::printf("  N = %4d  RMS error vs N = 1024: %.4f\n", n, std::sqrt(mean_square));
  }
  // least-squares slope of log(error) against log(N)
  const double mx = (log_n[0] + log_n[1] + log_n[2] + log_n[3]) / 4, my = (log_err[0] + log_err[1] + log_err[2] + log_err[3]) / 4;
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < log_n.size(); ++k) {
    sxy += (log_n[k] - mx) * (log_err[k] - my);
    sxx += (log_n[k] - mx) * (log_n[k] - mx);
  }
  const double slope = sxy / sxx;
  std::printf("  slope of log(error) against log(N): %.3f (1/sqrt(N): -0.5)\n", slope);
  EXPECT_LT(slope, -0.35);
  EXPECT_GT(slope, -0.65);
  EXPECT_GT(std::exp(log_err.front() - log_err.back()), 4.0);  // 64x the directions: ~8x less error
}

// The OSMesa shadow maps give the same probability as the CPU ones, up to
// cells whose point sits within the depth step of a shadow's edge.
TEST(SnowProbability, OsmesaAndCpuShadowMapsAgree) {
  const HeightField ground(centred_grid(24));
  SnowOptions o = testing::vertical_snow_options(16);
  o.main_direction = {25 * kDeg, 40 * kDeg};
  const SnowModel model = plates_over_ground(ground, {plate(0.05, 0.04, 0.05)}, o);
  const auto dirs = snowfall_directions(model, SnowParams{0.5, 10 * kDeg});
  TopDownRenderer cpu(SnowRenderer::kCpu), gl(SnowRenderer::kOsmesa);
  const SnowProbability a = snow_probability_shadow_maps(model, dirs, &cpu);
  const SnowProbability b = snow_probability_shadow_maps(model, dirs, &gl);
  for (std::size_t m = 0; m < a.per_map.size(); ++m) {
    EXPECT_LE((a.per_map[m] - b.per_map[m]).abs().mean(), 0.005) << "map " << m;
    EXPECT_LE((a.per_map[m] - b.per_map[m]).abs().maxCoeff(), 2.0 / 16 + 1e-12) << "map " << m;
  }
}

}  // namespace
}  // namespace repose
