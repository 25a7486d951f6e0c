// A free sphere in LIGGGHTS: the script makes it an atom of its own size
// among the grains (and keeps it out of the dumps), refuses other free
// shapes in one line naming the object, and a real run brings a dropped
// steel sphere to rest in a small bed, deterministically for a seed.

#include "validation/liggghts/liggghts_free_body.h"

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/support/liggghts_test.h"
#include "tests/validation/liggghts/dem_test_scene.h"
#include "validation/liggghts/liggghts_reference.h"
#include "validation/liggghts/liggghts_script.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

// The small DEM scene (12 mm bed of 2 mm grains) with a steel sphere of
// radius 6 mm dropped at 0.5 m/s from just above it.
Scene scene_with_free_sphere(ObjectSpec::Shape shape = ObjectSpec::Shape::kSphere) {
  Scene s = testing::small_dem_scene(false);
  s.time.duration_s = 0.3;
  ObjectSpec ball;
  ball.name = "ball";
  ball.shape = shape;
  ball.radius_m = 0.006;
  ball.half_extents_m = Eigen::Vector3d::Constant(0.006);
  ball.body = shape == ObjectSpec::Shape::kSphere ? make_sphere(0.006, 16) : make_box(ball.half_extents_m);
  DynamicBody d;
  d.density_kg_m3 = 7800.0;
  d.position_m = {0.02, 0.02, 0.022};
  d.velocity_m_s = {0.0, 0.0, -0.5};
  ball.dynamic = d;
  ball.keyframes = {Keyframe{0.0, Pose{d.position_m, Eigen::Quaterniond::Identity()}}};
  s.objects.push_back(ball);
  return s;
}

TEST(LiggghtsFreeBody, AFreeSphereIsAnAtomOfItsSizeAndTheDumpsKeepToTheGrains) {
  const RunScript script = run_script(scene_with_free_sphere());
  EXPECT_TRUE(script.meshes.empty());  // not a mesh
  EXPECT_NE(script.text.find("group grains union all\ncreate_atoms 1 single 0.02 0.02 0.022 units box"), std::string::npos)
      << script.text;
  EXPECT_NE(script.text.find("diameter 0.012 density 7800"), std::string::npos) << script.text;
  EXPECT_NE(script.text.find("vz -0.5"), std::string::npos);
  EXPECT_NE(script.text.find("dump grains grains custom"), std::string::npos);
  EXPECT_NE(script.text.find("file free_body_ball.txt"), std::string::npos);
  // the box reaches above the sphere's start
  EXPECT_GE(script.domain.z_max_m, 0.022 + 0.006);
  // without a free body the script is as before: every atom dumped
  EXPECT_NE(run_script(testing::small_dem_scene(true)).text.find("dump grains all custom"), std::string::npos);
}

TEST(LiggghtsFreeBody, AFreeBoxIsRefusedInOneLineNamingTheObject) {
  try {
    run_script(scene_with_free_sphere(ObjectSpec::Shape::kBox));
    FAIL() << "a free box was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos);
    EXPECT_NE(m.find("objects[0] 'ball' is a free box"), std::string::npos) << m;
  }
}

TEST(LiggghtsFreeBody, ATorqueIsRefusedInOneLineNamingTheKey) {
  Scene scene = scene_with_free_sphere(ObjectSpec::Shape::kSphere);
  scene.objects[0].dynamic->torque_n_m = Eigen::Vector3d(0.0, 1.0, 0.0);
  try {
    run_script(scene);
    FAIL() << "a torque was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos);
    EXPECT_NE(m.find("objects[0] 'ball': dynamic.torque_n_m"), std::string::npos) << m;
  }
}

class LiggghtsFreeBodyRun : public test_support::LiggghtsTest {};

TEST_F(LiggghtsFreeBodyRun, ADroppedSphereComesToRestInTheBedHeldByTheGrains) {
  const Scene scene = scene_with_free_sphere();
  LiggghtsReferenceOptions options;
  options.bed.cache_dir = (dir_ / "cache").string();
  options.bed.run.wall_clock_limit_s = 300;
  options.run.wall_clock_limit_s = 300;
  fs::create_directories(dir_ / "a");
  const LiggghtsReferenceResult r = run_liggghts_reference(scene, (dir_ / "a").string(), options);
  ASSERT_EQ(r.free_bodies.size(), 1u);
  const FreeBodyRest& rest = r.free_body_rests.at(0);
  EXPECT_EQ(r.grain_count, r.bed.grain_count);  // the sphere is not a grain
  EXPECT_LT(rest.final_speed_m_s, 0.02);
  EXPECT_GT(rest.resting_depth_m, 0.0) << "bottom " << rest.bottom_z_m << ", surface " << rest.surface_z_m;
  EXPECT_GT(rest.bottom_z_m, -0.001);
  EXPECT_NEAR(rest.resting_force_n.z(), rest.weight_n, 0.25 * rest.weight_n);
  EXPECT_GT(rest.max_force_n, rest.weight_n);
  EXPECT_TRUE(fs::exists(dir_ / "a" / "free_body_ball.csv"));
  // the same seed on the cached bed: the same rest, bit for bit (serial LIGGGHTS repeats)
  fs::create_directories(dir_ / "b");
  const LiggghtsReferenceResult again = run_liggghts_reference(scene, (dir_ / "b").string(), options);
  ASSERT_EQ(again.free_bodies.size(), 1u);
  EXPECT_EQ(again.free_body_rests[0].position_m, rest.position_m);
  EXPECT_EQ(again.free_body_rests[0].resting_depth_m, rest.resting_depth_m);
}

}  // namespace
}  // namespace repose
