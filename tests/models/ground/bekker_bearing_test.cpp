// Bekker's pressure-sinkage law: sinkage and pressure invert each other, a
// wider plate sinks less, law off sinks nothing, and malformed parameters
// are refused naming the key (in code and in a scene file).
#include "models/ground/bekker_bearing.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/config/scene_loader.h"

namespace repose {
namespace {

TEST(BekkerBearing, SinkageInvertsPressure) {
  const BekkerBearing dry_sand;
  for (const double width : {0.02, 0.1, 0.5}) {
    for (const double z : {1e-4, 2e-3, 0.05}) {
      const double p = bekker_pressure_pa(dry_sand, z, width);
      EXPECT_NEAR(bekker_sinkage_m(dry_sand, p, width), z, 1e-12 * (1 + z)) << width << " " << z;
    }
  }
}

TEST(BekkerBearing, MatchesTheLawByHand) {
  const BekkerBearing b;  // n 1.1, k_c 990 N/m^2.1, k_phi 1528430 N/m^3.1
  // a 10 cm plate under 1962 Pa (2 kg on 0.01 m^2): (1962 / (9900 + 1528430))^(1/1.1)
  EXPECT_NEAR(bekker_sinkage_m(b, 1962.0, 0.1), std::pow(1962.0 / 1538330.0, 1.0 / 1.1), 1e-15);
  // k_c / b: at the same pressure a narrower plate meets a stiffer modulus
  EXPECT_LT(bekker_sinkage_m(b, 1962.0, 0.05), bekker_sinkage_m(b, 1962.0, 0.5));
  EXPECT_GT(bekker_sinkage_m(b, 4000.0, 0.1), bekker_sinkage_m(b, 1962.0, 0.1));
  BekkerBearing off;
  off.law = BekkerBearing::Law::kOff;
  EXPECT_EQ(bekker_sinkage_m(off, 1e6, 0.1), 0.0);
}

TEST(BekkerBearing, ValidateNamesTheField) {
  auto field_of = [](const BekkerBearing& b) {
    try {
      validate(b);
    } catch (const FieldError& e) {
      return e.field();
    }
    return std::string("none");
  };
  BekkerBearing b;
  EXPECT_EQ(field_of(b), "none");
  b.exponent_n = 0.0;
  EXPECT_EQ(field_of(b), "exponent_n");
  b = BekkerBearing{};
  b.k_c_n_per_m_n_plus_1 = -1.0;
  EXPECT_EQ(field_of(b), "k_c_n_per_m_n_plus_1");
  b = BekkerBearing{};
  b.k_phi_n_per_m_n_plus_2 = std::nan("");
  EXPECT_EQ(field_of(b), "k_phi_n_per_m_n_plus_2");
  b.k_phi_n_per_m_n_plus_2 = 0.0;
  b.k_c_n_per_m_n_plus_1 = 0.0;
  EXPECT_EQ(field_of(b), "k_phi_n_per_m_n_plus_2");  // bears nothing
  b.law = BekkerBearing::Law::kOff;
  EXPECT_EQ(field_of(b), "none");
}

std::string load_error(const std::string& bearing) {
  const std::string yaml = R"(
time: {step_s: 0.1, duration_s: 0.1}
ground: {extent_m: [0.1, 0.1], cell_size_m: 0.01, initial_height: {kind: flat, height_m: 0.05}}
ground_model: {bearing: )" + bearing + "}\n";
  try {
    load_scene_from_string(yaml, "bearing.yaml", solver_registry().sections());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BekkerBearing, SceneRefusesMalformedParametersNamingTheKey) {
  EXPECT_EQ(load_error("{law: off}"), "");
  EXPECT_EQ(load_error("{exponent_n: 0.8, k_c_n_per_m_n_plus_1: 5270}"), "");
  for (const auto& [bearing, key] : std::vector<std::pair<std::string, std::string>>{
           {"{exponent_n: -1}", "exponent_n"},
           {"{exponent_n: 7}", "exponent_n"},
           {"{k_c_n_per_m_n_plus_1: -5}", "k_c_n_per_m_n_plus_1"},
           {"{k_phi_n_per_m_n_plus_2: 0, k_c_n_per_m_n_plus_1: 0}", "k_phi_n_per_m_n_plus_2"},
           {"{law: soft}", "law"},
           {"{k_phi: 1528}", "k_phi"}}) {
    const std::string m = load_error(bearing);
    EXPECT_NE(m.find(key), std::string::npos) << bearing << " -> " << m;
    EXPECT_NE(m.find("bearing"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace repose
