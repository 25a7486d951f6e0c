#include "models/core/config/dynamic_body.h"

#include <gtest/gtest.h>

#include <numbers>
#include <string>

#include "experiments/solvers/solver_registry.h"
#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"
#include "tests/support/refused_field.h"

namespace repose {
namespace {

const std::string kScene = R"(
time: {step_s: 0.01, duration_s: 0.1}
ground: {extent_m: [1, 1], cell_size_m: 0.1, initial_height: {kind: flat, height_m: 0.01}}
objects:
)";

Scene load(const std::string& objects) {
  return load_scene_from_string(kScene + objects, std::string(REPOSE_SOURCE_DIR) + "/tests/data/scenes/good/inline.yaml",
                                solver_registry().sections());
}

TEST(DynamicBody, ValidateNamesTheFieldThatBreaksARule) {
  DynamicBody d;
  EXPECT_EQ(testing::refused_field(d), "mass_kg");  // neither mass nor density
  d.mass_kg = 2.0;
  EXPECT_EQ(testing::refused_field(d), "");
  d.density_kg_m3 = 1000.0;
  EXPECT_EQ(testing::refused_field(d), "density_kg_m3");  // both
  d.density_kg_m3 = 0.0;
  d.velocity_m_s.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(testing::refused_field(d), "velocity_m_s");
  d.velocity_m_s.x() = 0.0;
  d.torque_n_m.y() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(testing::refused_field(d), "torque_n_m");
}

TEST(DynamicBody, AWheelsTorqueIsReadInWorldAxes) {
  const Scene s = load(R"(  - {name: wheel, shape: cylinder, radius_m: 0.1, half_height_m: 0.05,
       dynamic: {mass_kg: 5, position_m: [0, 0, 0.2], orientation_deg: [90, 0, 0], torque_n_m: [0, 2, 0]}})");
  EXPECT_EQ(s.objects.at(0).dynamic->torque_n_m, Eigen::Vector3d(0, 2, 0));
  EXPECT_EQ(load("  - {shape: sphere, radius_m: 0.1, dynamic: {mass_kg: 1, position_m: [0, 0, 1]}}\n")
                .objects.at(0)
                .dynamic->torque_n_m,
            Eigen::Vector3d::Zero());
}

TEST(DynamicBody, AFreeBodyStartsAtItsInitialPoseAndWeighsItsDensityTimesVolume) {
  const Scene s = load(R"(  - {name: b, shape: box, size_m: [0.1, 0.2, 0.4], scale: 0.5,
       dynamic: {density_kg_m3: 1000, position_m: [0.1, 0.2, 0.3], velocity_m_s: [0, 0, -2]}})");
  const ObjectSpec& o = s.objects.at(0);
  ASSERT_TRUE(o.dynamic.has_value());
  ASSERT_EQ(o.keyframes.size(), 1u);
  EXPECT_EQ(o.pose_at(0.05).position_m, Eigen::Vector3d(0.1, 0.2, 0.3));
  EXPECT_NEAR(o.volume_m3(), 0.05 * 0.1 * 0.2, 1e-15);  // scaled by 0.5 along each axis
  EXPECT_NEAR(o.mass_kg(), 1000.0 * 0.05 * 0.1 * 0.2, 1e-12);
  EXPECT_EQ(o.dynamic->velocity_m_s, Eigen::Vector3d(0, 0, -2));
}

TEST(DynamicBody, PrimitiveVolumesAreExactAndMeshesClose) {
  const Scene s = load(R"(  - {name: s, shape: sphere, radius_m: 0.1, dynamic: {mass_kg: 1, position_m: [0, 0, 1]}}
  - {name: c, shape: capsule, radius_m: 0.1, half_height_m: 0.2, dynamic: {mass_kg: 1, position_m: [0, 0, 1]}}
  - {name: y, shape: cylinder, radius_m: 0.1, half_height_m: 0.2, dynamic: {mass_kg: 3, position_m: [0, 0, 1]}})");
  const double pi = std::numbers::pi;
  EXPECT_NEAR(s.objects[0].volume_m3(), 4.0 / 3.0 * pi * 1e-3, 1e-15);
  EXPECT_NEAR(s.objects[1].volume_m3(), pi * 0.01 * 0.4 + 4.0 / 3.0 * pi * 1e-3, 1e-15);
  EXPECT_NEAR(s.objects[2].volume_m3(), pi * 0.01 * 0.4, 1e-15);
  // the tessellated body is within a few per cent of the exact volume
  EXPECT_NEAR(signed_volume_m3(s.objects[0].body) / s.objects[0].volume_m3(), 1.0, 0.03);
  EXPECT_EQ(s.objects[2].mass_kg(), 3.0);
}

TEST(DynamicBody, MotionAndDynamicTogetherAreRefusedInOneLine) {
  try {
    load(R"(  - {shape: sphere, radius_m: 0.1, motion: [{time_s: 0, position_m: [0, 0, 1]}],
     dynamic: {mass_kg: 1, position_m: [0, 0, 1]}})");
    FAIL() << "loaded";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos);
    EXPECT_NE(m.find("objects[0].dynamic: expected either motion (keyframes) or dynamic (a free body), not both"),
              std::string::npos) << m;
  }
}

TEST(DynamicBody, AnObjectWithNeitherMotionNorDynamicNamesBoth) {
  try {
    load("  - {shape: sphere, radius_m: 0.1}\n");
    FAIL() << "loaded";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("motion"), std::string::npos) << m;
    EXPECT_NE(m.find("dynamic"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace repose
