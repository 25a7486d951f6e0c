#include "validation/liggghts/liggghts_motion.h"

#include <sstream>

#include <gtest/gtest.h>

#include "tests/validation/liggghts/dem_test_scene.h"

namespace repose {
namespace {

TEST(LiggghtsMotion, PositionIsLinearBetweenKeyframesAndHeldOutside) {
  const Scene scene = testing::small_dem_scene(true);  // 0.023 m at t = 0, 0.014 m at 0.1 s, 0.023 m at 0.2 s
  const ObjectSpec& ball = scene.objects.front();
  EXPECT_NEAR(position_at(ball, 0.05).z(), 0.0185, 1e-15);
  EXPECT_NEAR(position_at(ball, 0.15).z(), 0.0185, 1e-15);
  EXPECT_DOUBLE_EQ(position_at(ball, -1.0).z(), 0.023);
  EXPECT_DOUBLE_EQ(position_at(ball, 5.0).z(), 0.023);
  EXPECT_FALSE(rotates(ball));
}

TEST(LiggghtsMotion, EverySegmentRunsItsStepsAndUnfixesItsFixes) {
  const Scene scene = testing::small_dem_scene(true);
  std::ostringstream s;
  const long steps = write_motion(s, scene, *dem_of(scene), {"obj0"});
  EXPECT_EQ(steps, liggghts_steps(0.2, 1e-5));
  const std::string text = s.str();
  EXPECT_NE(text.find("fix move0_0 all move/mesh mesh obj0 linear 0 0 -0.0"), std::string::npos) << text;
  EXPECT_NE(text.find("run 10000\nunfix move0_0\n"), std::string::npos) << text;
  EXPECT_NE(text.find("fix move0_1 all move/mesh mesh obj0 linear 0 0 0.0"), std::string::npos) << text;
  EXPECT_NE(text.find("run 10000\nunfix move0_1\n"), std::string::npos) << text;
}

}  // namespace
}  // namespace repose
