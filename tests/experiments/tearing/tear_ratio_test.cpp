// The tear-ratio check of the paper fit: CD / MD from the two directions'
// measured fracture energies, seed by seed, and its residual against the
// published ratio.
#include "experiments/tearing/tear_ratio.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

namespace repose {
namespace {

const std::string kPath = "tear.fracture_energy_per_path_length_j_per_m";
const std::string kDepth = "tear.fracture_energy_per_length_j_per_m";

SeedMeasures three_seeds() {
  // per seed: along the grain (md) and across it (cd)
  return {{"md", {{{kPath, 0.10}, {kDepth, 0.10}}, {{kPath, 0.12}, {kDepth, 0.13}}, {{kPath, 0.14}, {kDepth, 0.14}}}},
          {"cd", {{{kPath, 0.20}, {kDepth, 0.40}}, {{kPath, 0.18}, {kDepth, 0.36}}, {{kPath, 0.14}, {kDepth, 0.21}}}}};
}

TEST(TearRatio, IsTheRatioOfTheDirectionsMeanEnergiesWithTheSeedsSpread) {
  const TearRatio r = tear_ratio_cd_over_md(three_seeds(), kPath);
  ASSERT_EQ(r.per_seed.size(), 3u);
  EXPECT_DOUBLE_EQ(r.per_seed[0], 2.0);
  EXPECT_DOUBLE_EQ(r.per_seed[1], 1.5);
  EXPECT_DOUBLE_EQ(r.per_seed[2], 1.0);
  EXPECT_NEAR(r.mean, (0.20 + 0.18 + 0.14) / (0.10 + 0.12 + 0.14), 1e-12);
  EXPECT_NEAR(r.seed_sd, 0.5, 1e-12);  // sample sd of 2, 1.5, 1
  // the other length gives its own ratio: the measure is the one asked for
  EXPECT_NEAR(tear_ratio_cd_over_md(three_seeds(), kDepth).mean, 0.97 / 0.37, 1e-12);
}

TEST(TearRatio, ResidualIsRelativeToThePublishedRatioAndZeroWhenItMatches) {
  TearRatio r;
  r.mean = 1.145;
  EXPECT_NEAR(tear_ratio_residual(r, 1105.0 / 965.0), 1.145 / (1105.0 / 965.0) - 1.0, 1e-15);
  r.mean = 1105.0 / 965.0;
  EXPECT_NEAR(tear_ratio_residual(r, 1105.0 / 965.0), 0.0, 1e-15);
  r.mean = 2.0 * 1.1;
  EXPECT_NEAR(tear_ratio_residual(r, 1.1), 1.0, 1e-15);
}

TEST(TearRatio, SwappingTheDirectionsInvertsIt) {
  SeedMeasures s = three_seeds();
  std::swap(s["md"], s["cd"]);
  const TearRatio r = tear_ratio_cd_over_md(s, kPath);
  EXPECT_NEAR(r.mean * tear_ratio_cd_over_md(three_seeds(), kPath).mean, 1.0, 1e-12);
}

TEST(TearRatio, RefusesUnpairedSeedsAMissingDirectionAndNoTearAlongTheGrain) {
  SeedMeasures s = three_seeds();
  s["cd"].pop_back();
  EXPECT_THROW(tear_ratio_cd_over_md(s, kPath), std::invalid_argument);
  EXPECT_THROW(tear_ratio_cd_over_md({{"md", three_seeds()["md"]}}, kPath), std::invalid_argument);
  SeedMeasures untorn = three_seeds();
  untorn["md"][1][kPath] = 0.0;
  EXPECT_THROW(tear_ratio_cd_over_md(untorn, kPath), std::invalid_argument);
  EXPECT_THROW(tear_ratio_cd_over_md(three_seeds(), "tear.no_such_measure"), std::invalid_argument);
}

}  // namespace
}  // namespace repose
