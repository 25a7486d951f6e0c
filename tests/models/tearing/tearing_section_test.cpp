// The `tearing:` section: read with defaults, errors at the key, twist or
// grips, written back to an equal section.
#include "models/tearing/tearing_section.h"

#include <gtest/gtest.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"

namespace repose {
namespace {

std::string scene_text(const std::string& tearing) {
  return "name: t\nseed: 3\ntime: {step_s: 0.001, duration_s: 0.001}\n"
         "ground: {extent_m: [0.1, 0.1], resolution: [2, 2], initial_height: {kind: flat, height_m: 0}, material: sand}\n"
         "tearing:\n" + tearing;
}

Scene load(const std::string& tearing) {
  return load_scene_from_string(scene_text(tearing), "/tmp/tearing_section_test.yaml", solver_registry().sections());
}

std::string error_of(const std::string& tearing) {
  try {
    load(tearing);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(TearingSection, ReadsTheSheetFibresTwistAndParameters) {
  const Scene scene = load(
      "  cells_x: 20\n  tear_strain: 0.03\n  integrator: implicit\n  time_step_fraction: 5\n"
      "  fibres: {layers: 4, grain_direction_deg: 90}\n  twist: {grip_depth_m: 0.01, gap_m: 0.02, speed_m_per_s: 2}\n");
  const TearingSection* s = scene.section<TearingSection>();
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->sheet.cells_x, 20);
  EXPECT_DOUBLE_EQ(s->params.tear_strain, 0.03);
  EXPECT_DOUBLE_EQ(s->params.stiffness_n_per_m, SheetParams{}.stiffness_n_per_m);  // the default
  EXPECT_EQ(s->run.integrator, TearRunOptions::Integrator::kImplicit);
  EXPECT_EQ(s->sheet.fibres.layers, 4);
  EXPECT_NEAR(s->sheet.fibres.grain_direction_rad, std::numbers::pi / 2, 1e-15);
  ASSERT_EQ(s->sheet.grips.size(), 2u);
  EXPECT_DOUBLE_EQ(s->sheet.grips[0].x_max_m, 0.04);
  EXPECT_DOUBLE_EQ(s->sheet.grips[1].velocity_m_per_s.z(), 2.0);
}

TEST(TearingSection, WritesWhatReadsBackToTheSameSection) {
  const bool twist = !SheetSpec{}.twist_stiffness;  // not the default
  const Scene scene = load("  cells_x: 10\n  notch_length_m: 0.01\n  stiffness_damping_s: 2.0e-7\n  fibres: {grain_spread_deg: 30}\n" +
                           std::string(twist ? "  twist_stiffness: true\n" : "  twist_stiffness: false\n") +
                           "  grips: [{x_min_m: 0, x_max_m: 0.02, y_min_m: 0.09, y_max_m: 0.1, velocity_m_per_s: [0, 0, 1],"
                           " hold_z: true, hold_x: false}]\n");
  const Scene again = load_scene_from_string(scene_to_yaml(scene), "/tmp/again.yaml", solver_registry().sections());
  const TearingSection& a = *scene.section<TearingSection>();
  const TearingSection& b = *again.section<TearingSection>();
  EXPECT_EQ(a.sheet.cells_x, b.sheet.cells_x);
  EXPECT_EQ(a.sheet.notch_length_m, b.sheet.notch_length_m);
  EXPECT_EQ(a.sheet.stiffness_damping_s, 2.0e-7);
  EXPECT_EQ(a.sheet.stiffness_damping_s, b.sheet.stiffness_damping_s);
  EXPECT_EQ(a.sheet.twist_stiffness, twist);
  EXPECT_EQ(b.sheet.twist_stiffness, twist);
  EXPECT_EQ(a.sheet.fibres.grain_spread_rad, b.sheet.fibres.grain_spread_rad);
  ASSERT_EQ(b.sheet.grips.size(), 1u);
  EXPECT_EQ(a.sheet.grips[0].held_axes, b.sheet.grips[0].held_axes);
  EXPECT_FALSE(b.sheet.grips[0].held_axes[0]);
  EXPECT_EQ(a.sheet.grips[0].velocity_m_per_s, b.sheet.grips[0].velocity_m_per_s);
}

TEST(TearingSection, ErrorsNameTheKey) {
  EXPECT_NE(error_of("  cells_x: 0\n").find("cells_x"), std::string::npos);
  EXPECT_NE(error_of("  height_m: 0.0512\n").find("height_m"), std::string::npos);
  EXPECT_NE(error_of("  fibres: {layers: 0}\n").find("layers"), std::string::npos);
  EXPECT_NE(error_of("  fibres: {clump_length_min_m: 0.0001}\n").find("clump_length_min_m"), std::string::npos);
  EXPECT_NE(error_of("  tear_strain: -1\n").find("tear_strain"), std::string::npos);
  EXPECT_NE(error_of("  stiffness_damping_s: -1e-7\n").find("stiffness_damping_s"), std::string::npos);
  EXPECT_NE(error_of("  release_time_s: -1e-6\n").find("release_time_s"), std::string::npos);
  EXPECT_NE(error_of("  tear_rule: cohesiv\n").find("tear_rule"), std::string::npos);
  EXPECT_NE(error_of("  tear_rule: cohesive\n  release_time_s: 1e-6\n").find("release_time_s"), std::string::npos);
  EXPECT_EQ(load("  tear_rule: cohesive\n").section<TearingSection>()->sheet.tear_rule, TearRule::kCohesive);
  EXPECT_NE(error_of("  twist_stiffness: 3\n").find("twist_stiffness"), std::string::npos);
  EXPECT_NE(error_of("  time_step_fraction: 2\n").find("time_step_fraction"), std::string::npos);
  EXPECT_NE(error_of("  colour: red\n").find("colour"), std::string::npos);
  EXPECT_NE(error_of("  twist: {}\n  grips: []\n").find("grips"), std::string::npos);
  EXPECT_NE(error_of("  grips: [{x_min_m: 0.5, x_max_m: 0.6, y_min_m: 0, y_max_m: 0.1}]\n").find("grips[0]"),
            std::string::npos);
  EXPECT_NE(error_of("  tear_rule: stress\n").find("tear_rule"), std::string::npos);
  EXPECT_NE(error_of("  tear_energy_j_per_m: 0\n").find("tear_energy_j_per_m"), std::string::npos);
  EXPECT_NE(error_of("  fibre_anisotropy: 1\n").find("fibre_anisotropy"), std::string::npos);
  EXPECT_NE(error_of("  tensile: {speed_m_per_s: 0}\n").find("speed_m_per_s"), std::string::npos);
  EXPECT_NE(error_of("  twist: {}\n  tensile: {}\n").find("tensile"), std::string::npos);
}

TEST(TearingSection, ReadsTheTearRuleTheAnisotropyAndATensileTestAndWritesThemBack) {
  const Scene scene = load("  width_m: 0.05\n  height_m: 0.01\n  cells_x: 10\n  tear_rule: energy\n"
                           "  tear_energy_j_per_m: 0.4\n  fibre_anisotropy: 0.3\n"
                           "  tensile: {speed_m_per_s: 0.25, max_strain: 0.1}\n");
  const Scene again = load_scene_from_string(scene_to_yaml(scene), "/tmp/again.yaml", solver_registry().sections());
  for (const Scene* sc : {&scene, &again}) {
    const TearingSection& s = *sc->section<TearingSection>();
    EXPECT_EQ(s.sheet.tear_rule, TearRule::kEnergy);
    EXPECT_DOUBLE_EQ(s.params.tear_energy_j_per_m, 0.4);
    EXPECT_DOUBLE_EQ(s.params.fibre_anisotropy, 0.3);
    ASSERT_TRUE(s.tensile.has_value());
    EXPECT_DOUBLE_EQ(s.tensile->speed_m_per_s, 0.25);
    EXPECT_DOUBLE_EQ(s.tensile->max_strain, 0.1);
    ASSERT_EQ(s.sheet.grips.size(), 3u);  // tensile_grips()
    EXPECT_DOUBLE_EQ(s.sheet.grips[2].velocity_m_per_s.x(), 0.25);
  }
  // the default is the seed's rule
  EXPECT_EQ(load("  cells_x: 10\n").section<TearingSection>()->sheet.tear_rule, TearRule::kStrain);
}

}  // namespace
}  // namespace repose
