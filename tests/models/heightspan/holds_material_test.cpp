#include "models/heightspan/holds_material.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"

namespace repose {
namespace {

TEST(HoldsMaterial, ConvexBodiesAreConvexAndABucketIsNot) {
  EXPECT_TRUE(is_convex(make_box({0.1, 0.2, 0.3})));
  EXPECT_TRUE(is_convex(make_sphere(0.1, 16)));
  EXPECT_TRUE(is_convex(make_capsule(0.05, 0.1, 16)));
  EXPECT_FALSE(is_convex(testing::bucket_mesh()));
  const TriangleMesh two = merged(make_box({0.01, 0.01, 0.01}),
                                  transformed(make_box({0.01, 0.01, 0.01}), Pose{{0.05, 0, 0}, Eigen::Quaterniond::Identity()}));
  EXPECT_FALSE(is_convex(two));
}

TEST(HoldsMaterial, TheSceneDecidesElseTheShape) {
  Scene s = testing::bed_scene(10, 10, 0.01, 0.01, {}, 1);
  HeightSpanSection section;
  section.holds_material["plate"] = true;
  section.holds_material["bucket2"] = false;
  s = with_heightspan(s, section);
  EXPECT_TRUE(holds_material(s, testing::mesh_object("plate", make_box({0.1, 0.1, 0.01}), {})));
  EXPECT_FALSE(holds_material(s, testing::mesh_object("ball", make_sphere(0.1), {})));
  EXPECT_TRUE(holds_material(s, testing::mesh_object("bucket", testing::bucket_mesh(), {})));
  EXPECT_FALSE(holds_material(s, testing::mesh_object("bucket2", testing::bucket_mesh(), {})));
}

}  // namespace
}  // namespace repose
