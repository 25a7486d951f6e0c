#include "models/core/config/initial_height.h"
#include "experiments/solvers/solver_registry.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "models/core/config/scene_loader.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

const fs::path kGood = fs::path(REPOSE_SOURCE_DIR) / "tests/data/scenes/good";

// 128 x 64 cells of 1/64 m, noise around 0.1 m with a peak deviation of 0.02 m.
std::string fmt_scene(std::uint64_t seed, double correlation_m) {
  return fmt::format(R"(
seed: {}
time: {{step_s: 0.1, duration_s: 1}}
ground:
  extent_m: [2, 1]
  resolution: [128, 64]
  initial_height: {{kind: noise, mean_m: 0.1, amplitude_m: 0.02, correlation_m: {}}}
)", seed, correlation_m);
}

Scene noise_scene(std::uint64_t seed, double correlation_m) {
  return load_scene_from_string(fmt_scene(seed, correlation_m), (kGood / "noise.yaml").string(), solver_registry().sections());
}

bool bit_identical(const HeightField& a, const HeightField& b) {
  return a.grid() == b.grid() &&
         std::memcmp(a.heights().data(), b.heights().data(), a.grid().cell_count() * sizeof(double)) == 0;
}

// Correlation of horizontally neighbouring cells' deviations from the mean.
double lag1_correlation(const HeightField& f) {
  const ArrayXXdR d = f.heights() - f.heights().mean();
  const double num = (d.leftCols(d.cols() - 1) * d.rightCols(d.cols() - 1)).sum() / ((d.cols() - 1) * d.rows());
  return num / d.square().mean();
}

TEST(InitialHeight, FlatIsFlat) {
  const HeightField f = make_initial_height(load_scene((kGood / "minimal.yaml").string(), solver_registry().sections()));
  EXPECT_EQ(f.nx(), 50);
  EXPECT_EQ(f.min_height_m(), 0.02);
  EXPECT_EQ(f.max_height_m(), 0.02);
}

TEST(InitialHeight, SameSeedGivesBitIdenticalNoise) {
  const HeightField a = make_initial_height(noise_scene(7, 0.05));
  const HeightField b = make_initial_height(noise_scene(7, 0.05));
  EXPECT_TRUE(bit_identical(a, b));
  const HeightField c = make_initial_height(noise_scene(8, 0.05));
  EXPECT_FALSE(bit_identical(a, c));
  EXPECT_GT((a.heights() - c.heights()).abs().maxCoeff(), 1e-3);
}

TEST(InitialHeight, NoiseHasItsMeanAndPeakDeviation) {
  for (double correlation : {0.0, 0.05}) {
    const HeightField f = make_initial_height(noise_scene(3, correlation));
    EXPECT_NEAR(f.heights().mean(), 0.1, 1e-12);
    EXPECT_NEAR((f.heights() - 0.1).abs().maxCoeff(), 0.02, 1e-12);
    EXPECT_GE(f.min_height_m(), 0.08 - 1e-12);
  }
}

TEST(InitialHeight, CorrelationLengthSmoothsTheNoise) {
  const double white = lag1_correlation(make_initial_height(noise_scene(5, 0.0)));
  const double smooth = lag1_correlation(make_initial_height(noise_scene(5, 0.05)));  // 3.2 cells
  EXPECT_LT(std::abs(white), 0.05);
  EXPECT_GT(smooth, 0.8);
}

TEST(InitialHeight, NpyHeightsAreMetresPlusOffset) {
  const Scene s = load_scene((kGood / "npy_height.yaml").string(), solver_registry().sections());
  const HeightField f = make_initial_height(s);
  ASSERT_EQ(f.nx(), 16);
  ASSERT_EQ(f.ny(), 8);
  // the file holds 0.01 + 0.001 i + 0.002 j (tests/data/scenes/make_height_files.py); offset 0.005
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(f.at(i, j), 0.015 + 0.001 * i + 0.002 * j, 1e-15);
}

TEST(InitialHeight, PngHeightsAreScaledAndRowZeroIsSmallestY) {
  const Scene s = load_scene((kGood / "png_height.yaml").string(), solver_registry().sections());
  const HeightField f = make_initial_height(s);
  ASSERT_EQ(f.nx(), 16);
  ASSERT_EQ(f.ny(), 8);
  // the image holds 1000 i + 100 j with its top row at the largest y
  for (int j = 0; j < 8; ++j)
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(f.at(i, j), (1000.0 * i + 100.0 * j) * 0.5 / 65535.0, 1e-15);
}

TEST(MaterialAt, RegionsCoverTheirRectanglesAndLaterOnesWin) {
  const Scene s = load_scene((kGood / "all_features.yaml").string(), solver_registry().sections());
  EXPECT_EQ(material_at(s.ground, 0.25, 0.0), "snow");
  EXPECT_EQ(material_at(s.ground, 1.5, 0.1), "gravel");
  EXPECT_EQ(material_at(s.ground, 0.75, 0.0), "mud");
  GroundSpec g = s.ground;
  MaterialRegion top = g.regions[1];
  top.material = "top";
  top.x_min_m = 1.4;
  g.regions.push_back(top);
  EXPECT_EQ(material_at(g, 1.5, 0.1), "top");
  EXPECT_EQ(material_at(g, 1.2, 0.1), "gravel");
}

}  // namespace
}  // namespace repose
