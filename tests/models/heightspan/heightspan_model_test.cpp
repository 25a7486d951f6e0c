#include "models/heightspan/heightspan_model.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"
#include "models/core/base/error.h"

namespace repose {
namespace {

using testing::bed_scene;
using testing::key;
using testing::mesh_object;

TEST(HeightSpanModel, OnlyObjectsThatHoldMaterialGetAMap) {
  Scene s = bed_scene(40, 40, 0.005, 0.01,
                      {mesh_object("bucket", testing::bucket_mesh(), {key(0, 0.1, 0.1, 0.1)}),
                       mesh_object("ball", make_sphere(0.02), {key(0, 0.05, 0.05, 0.1)})},
                      1);
  HeightSpanSection section = heightspan_section(s);
  section.holds_material.clear();  // decided by shape
  const HeightSpanModel model = build_heightspan_model(with_heightspan(s, section));
  ASSERT_EQ(model.held.size(), 1u);
  EXPECT_EQ(model.held[0].object, 0);
  EXPECT_EQ(model.ground_path, std::vector<int>{1});
}

TEST(HeightSpanModel, TheMapGridStartsOnTheGroundsCellsAndMovesWithTheObject) {
  Scene s = bed_scene(40, 40, 0.005, 0.01, {mesh_object("bucket", testing::bucket_mesh(), {key(0, 0.1013, 0.0977, 0.1)})}, 1);
  const HeightSpanModel model = build_heightspan_model(s);
  const Grid& g0 = model.held[0].grid0;
  const double h = 0.005;
  EXPECT_NEAR(std::remainder(g0.origin_x_m, h), 0.0, 1e-15);
  EXPECT_NEAR(std::remainder(g0.origin_y_m, h), 0.0, 1e-15);
  // wide enough for the body turned any way
  const double radius = testing::bucket_mesh().V.rowwise().norm().maxCoeff();
  EXPECT_LE(g0.origin_x_m, 0.1013 - radius);
  EXPECT_GE(g0.origin_x_m + g0.nx * h, 0.1013 + radius);
  Pose p;
  p.position_m = Eigen::Vector3d(0.2, 0.0, 0.3);
  const Grid moved = model.map_grid(model.held[0], p);
  EXPECT_NEAR(moved.origin_x_m - g0.origin_x_m, 0.2 - 0.1013, 1e-15);
  EXPECT_NEAR(moved.origin_y_m - g0.origin_y_m, 0.0 - 0.0977, 1e-15);
}

TEST(HeightSpanModel, AnOpenMeshThatHoldsMaterialIsRefused) {
  TriangleMesh open = make_box({0.02, 0.02, 0.02});
  open.F.conservativeResize(open.F.rows() - 2, 3);  // one face missing
  Scene s = bed_scene(20, 20, 0.005, 0.01, {mesh_object("tray", open, {key(0, 0.05, 0.05, 0.1)})}, 1);
  try {
    build_heightspan_model(s);
    FAIL() << "accepted an open mesh";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("tray"), std::string::npos) << e.what();
  }
}

TEST(HeightSpanModel, AFreeBodyIsRefusedNamingIt) {
  ObjectSpec ball = mesh_object("dropped", make_sphere(0.02), {key(0, 0.05, 0.05, 0.1)});
  ball.dynamic = DynamicBody{};
  ball.dynamic->mass_kg = 0.1;
  Scene s = bed_scene(20, 20, 0.005, 0.01, {ball}, 1);
  try {
    build_heightspan_model(s);
    FAIL() << "held a free body still";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("objects[0] ('dropped')"), std::string::npos) << m;
    EXPECT_NE(m.find("dynamic"), std::string::npos) << m;
    EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace repose
