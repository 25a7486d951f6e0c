// The free-body options: validate names the broken field, and the scene's
// ground_model.free_bodies refuses malformed values naming the key.
#include "models/ground/free_body_spec.h"

#include <string>

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/config/scene_loader.h"
#include "tests/support/refused_field.h"

namespace repose {
namespace {

TEST(FreeBodySpec, ValidateNamesTheField) {
  EXPECT_EQ(testing::refused_field(FreeBodySpec{}), "");
  FreeBodySpec f;
  f.ode_step_s = 0.0;
  EXPECT_EQ(testing::refused_field(f), "ode_step_s");
  f = FreeBodySpec{};
  f.solver_iterations = 0;
  EXPECT_EQ(testing::refused_field(f), "solver_iterations");
  f = FreeBodySpec{};
  f.erp = 1.5;
  EXPECT_EQ(testing::refused_field(f), "erp");
  f = FreeBodySpec{};
  f.cfm = -1e-9;
  EXPECT_EQ(testing::refused_field(f), "cfm");
  f = FreeBodySpec{};
  f.friction = -0.1;
  EXPECT_EQ(testing::refused_field(f), "friction");
  f = FreeBodySpec{};
  f.gravity_m_s2 = 1e3;
  EXPECT_EQ(testing::refused_field(f), "gravity_m_s2");
  f = FreeBodySpec{};
  f.bearing.exponent_n = -1;
  EXPECT_EQ(testing::refused_field(f), "exponent_n");
}

TEST(FreeBodySpec, SceneRefusesMalformedValuesNamingTheKey) {
  auto error = [](const std::string& free_bodies) {
    const std::string yaml = R"(
time: {step_s: 0.1, duration_s: 0.1}
ground: {extent_m: [0.1, 0.1], cell_size_m: 0.01, initial_height: {kind: flat, height_m: 0.05}}
ground_model: {free_bodies: )" + free_bodies + "}\n";
    try {
      load_scene_from_string(yaml, "free.yaml", solver_registry().sections());
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("{ode_step_s: 0.001, friction: 0.8}"), "");
  for (const std::string key : {"ode_step_s: 0", "erp: 2", "cfm: -1", "friction: -1", "solver_iterations: 0",
                                "speed: 3"}) {
    const std::string m = error("{" + key + "}");
    EXPECT_NE(m.find(key.substr(0, key.find(':'))), std::string::npos) << key << " -> " << m;
    EXPECT_NE(m.find("free_bodies"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace repose
