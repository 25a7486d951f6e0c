#include "models/snow/snow_params.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "models/core/base/error.h"

namespace repose {
namespace {

std::string error_of(const SnowParams& p) {
  try {
    validate(p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SnowParams, DefaultsAndExtremesAreValid) {
  EXPECT_EQ(error_of(SnowParams{}), "");
  EXPECT_EQ(error_of(SnowParams{0.0, 0.0}), "");
  EXPECT_EQ(error_of(SnowParams{std::numbers::pi / 2, std::numbers::pi}), "");
}

TEST(SnowParams, RefusalNamesTheField) {
  EXPECT_NE(error_of(SnowParams{-0.1, 0.1}).find("repose_angle_deg"), std::string::npos);
  EXPECT_NE(error_of(SnowParams{1.6, 0.1}).find("repose_angle_deg"), std::string::npos);
  EXPECT_NE(error_of(SnowParams{0.5, -1e-9}).find("spread_deg"), std::string::npos);
  EXPECT_NE(error_of(SnowParams{0.5, std::nan("")}).find("spread_deg"), std::string::npos);
  EXPECT_NE(error_of(SnowParams{0.5, 0.1, 0.0}).find("snowfall_scale"), std::string::npos);
  EXPECT_NE(error_of(SnowParams{0.5, 0.1, 101.0}).find("snowfall_scale"), std::string::npos);
  EXPECT_NE(error_of(SnowParams{0.5, 0.1, 1.0, -1e-6}).find("edge_hold_m"), std::string::npos);
  EXPECT_NE(error_of(SnowParams{0.5, 0.1, 1.0, std::nan("")}).find("edge_hold_m"), std::string::npos);
  EXPECT_EQ(error_of(SnowParams{0.5, 0.1, 1.0, 0.004}), "");
}

}  // namespace
}  // namespace repose
