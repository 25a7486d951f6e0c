// Fibre images: determinism for a seed, ranges, the composite, PNG output.
#include "models/tearing/fibre_image.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "models/core/io/png_io.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

FibreImages draw(std::uint64_t seed, const FibreOptions& options = {}) {
  std::mt19937_64 rng(seed);
  return draw_fibre_images(options, 0.03, 0.02, rng);
}

TEST(FibreImage, SameSeedGivesTheSameBitsAndAnotherSeedDoesNot) {
  const FibreImages a = draw(11), b = draw(11), c = draw(12);
  ASSERT_EQ(a.layers.size(), 3u);
  for (std::size_t k = 0; k < a.layers.size(); ++k) EXPECT_TRUE((a.layers[k] == b.layers[k]).all()) << k;
  EXPECT_TRUE((a.composite == b.composite).all());
  EXPECT_FALSE((a.composite == c.composite).all());
  // the layers are drawn independently, not copies of one another
  EXPECT_FALSE((a.layers[0] == a.layers[1]).all());
}

TEST(FibreImage, CoversTheSheetWithDensitiesBetweenBackgroundAndOne) {
  FibreOptions options;
  options.layers = 5;
  const FibreImages images = draw(3, options);
  EXPECT_EQ(images.nx(), 120);  // 0.03 m / 0.25 mm
  EXPECT_EQ(images.ny(), 80);
  for (const ArrayXXdR& layer : images.layers) {
    EXPECT_GE(layer.minCoeff(), options.background_density - 1e-15);
    EXPECT_LE(layer.maxCoeff(), 1.0);
    // clumps are there: the layer is not flat
    EXPECT_GT(layer.maxCoeff() - layer.minCoeff(), 0.3);
  }
  ArrayXXdR mean = ArrayXXdR::Zero(images.ny(), images.nx());
  for (const ArrayXXdR& layer : images.layers) mean += layer / 5.0;
  EXPECT_LT((mean - images.composite).abs().maxCoeff(), 1e-12);
}

TEST(FibreImage, NoClumpsLeavesTheBackground) {
  FibreOptions options;
  options.clumps_per_m2 = 0.0;
  const FibreImages images = draw(3, options);
  EXPECT_DOUBLE_EQ(images.composite.minCoeff(), options.background_density);
  EXPECT_DOUBLE_EQ(images.composite.maxCoeff(), options.background_density);
}

TEST(FibreImage, WritesEveryLayerAndTheCompositeAsSixteenBitPngs) {
  const FibreImages images = draw(5);
  const test_support::TempDir dir;
  const std::vector<std::string> paths = write_fibre_pngs(images, (dir.path / "sheet_").string());
  ASSERT_EQ(paths.size(), 4u);
  const ArrayXXdR back = read_png16(paths.back());
  ASSERT_EQ(back.rows(), images.ny());
  ASSERT_EQ(back.cols(), images.nx());
  EXPECT_LT((back / 65535.0 - images.composite).abs().maxCoeff(), 1.0 / 65535.0);
}

TEST(FibreImage, RefusesOptionsOutsideTheirRanges) {
  const auto message = [](const FibreOptions& o) {
    try {
      o.validate();
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  FibreOptions o;
  o.layers = 0;
  EXPECT_NE(message(o).find("layers"), std::string::npos);
  o = {};
  o.clump_length_min_m = 0.1e-3;
  EXPECT_NE(message(o).find("clump_length_min_m"), std::string::npos);
  o = {};
  o.grain_spread_rad = 2.0;
  EXPECT_NE(message(o).find("grain_spread_deg"), std::string::npos);
  o = {};
  o.background_density = 1.0;
  EXPECT_NE(message(o).find("background_density"), std::string::npos);
  EXPECT_EQ(message(FibreOptions{}), "accepted");
}

}  // namespace
}  // namespace repose
