// build_ground_model: the scene's objects become the model's, free bodies
// (dynamic:) too, for ODE to drive (free_body_drive.h).
#include "models/ground/ground_model.h"

#include <string>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

TEST(GroundModel, TakesTheScenesKeyframedObjects) {
  const Scene scene = flat_scene(centred_grid(8, 8, 0.01), 0.02, sand(), {sphere(0.02, {at(0, 0, 0, 0.05)})}, 1);
  const GroundModel model = build_ground_model(scene);
  ASSERT_EQ(model.objects.size(), 1u);
  EXPECT_EQ(model.swept_bodies.size(), 1u);
}

TEST(GroundModel, KeepsAFreeBodyForODEToDrive) {
  ObjectSpec ball = sphere(0.02, {at(0, 0, 0, 0.05)});
  ball.name = "dropped";
  ball.dynamic = DynamicBody{};
  ball.dynamic->mass_kg = 0.1;
  Scene scene = flat_scene(centred_grid(8, 8, 0.01), 0.02, sand(), {ball}, 1);
  scene.source_path = "free.yaml";
  const GroundModel model = build_ground_model(scene);
  ASSERT_EQ(model.objects.size(), 1u);
  EXPECT_TRUE(model.objects[0].dynamic.has_value());
  // the models built on the ground model that move objects along keyframes only still say why not
  std::string why;
  EXPECT_FALSE(keyframed_objects_only(scene, &why));
  EXPECT_NE(why.find("objects[0] ('dropped')"), std::string::npos) << why;
  EXPECT_NE(why.find("dynamic"), std::string::npos) << why;
  EXPECT_EQ(why.find('\n'), std::string::npos) << why;
}

}  // namespace
}  // namespace repose
