#include "models/ground/swept_mesh.h"

#include <gtest/gtest.h>

#include "models/core/geometry/depth_image.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

Pose at_position(double x, double y, double z) {
  Pose p;
  p.position_m = Eigen::Vector3d(x, y, z);
  return p;
}

TEST(SweptMesh, BoxSweptAlongXIsALongerBox) {
  const TriangleMesh box = make_box(Eigen::Vector3d(0.1, 0.2, 0.3));
  const TriangleMesh swept = swept_mesh(box, at_position(0, 0, 0), at_position(0.5, 0, 0));
  EXPECT_TRUE(is_closed_manifold(swept));
  EXPECT_NEAR(signed_volume_m3(swept), (0.2 + 0.5) * 0.4 * 0.6, 1e-12);
}

TEST(SweptMesh, SphereSweptDiagonallyIsClosedWithTheCapsuleVolume) {
  const double r = 0.1, d = 0.3;
  const TriangleMesh ball = make_sphere(r, 48);
  const Eigen::Vector3d dir = Eigen::Vector3d(1, 1, 0.5).normalized() * d;
  const TriangleMesh swept = swept_mesh(ball, at_position(0, 0, 0), at_position(dir.x(), dir.y(), dir.z()));
  EXPECT_TRUE(is_closed_manifold(swept));
  // sphere volume plus the silhouette's area times the distance (tessellation: ~1 %)
  const double expected = signed_volume_m3(ball) + std::numbers::pi * r * r * d;
  EXPECT_NEAR(signed_volume_m3(swept), expected, 0.02 * expected);
}

TEST(SweptMesh, UndersideIsTheLowestAlongThePath) {
  const double r = 0.1;
  const TriangleMesh swept = swept_mesh(make_sphere(r, 48), at_position(-0.2, 0, r), at_position(0.2, 0, r));
  Grid g = centred_grid(60, 10, 0.01);
  const DepthImage img = depth_image_cpu({swept}, g, ViewFrom::kBelow);
  // along the path's centre line the underside is flat at ~0 (the sphere's bottom)
  for (int i = 0; i < 60; ++i) {
    if (std::abs(g.centre_x(i)) < 0.2) {
      ASSERT_TRUE(img.is_covered(i, 5));
      EXPECT_NEAR(img.z(i, 5), 0.0, 2e-3) << i;
    }
  }
}

TEST(SweptMesh, NoMotionIsTheBodyInPlace) {
  const TriangleMesh box = make_box(Eigen::Vector3d(0.1, 0.1, 0.1));
  const TriangleMesh swept = swept_mesh(box, at_position(1, 2, 3), at_position(1, 2, 3));
  EXPECT_EQ(swept.F.rows(), box.F.rows());
  EXPECT_NEAR(bounding_box(swept).min.x(), 0.9, 1e-15);
}

}  // namespace
}  // namespace repose

namespace repose {
namespace {

// make_swept_body: a closed body has a twin for every edge, and the twin's
// twin is the face itself; a body with a hole has open edges.
TEST(SweptBody, EdgeTwinsOfClosedAndOpenBodies) {
  const TriangleMesh ball = make_sphere(0.1, 12);
  const SweptBody swept = make_swept_body(ball);
  ASSERT_EQ(swept.twin_face.size(), 3 * static_cast<std::size_t>(ball.F.rows()));
  for (std::size_t e = 0; e < swept.twin_face.size(); ++e) {
    const int twin = swept.twin_face[e];
    ASSERT_GE(twin, 0) << e;
    bool back = false;
    for (int k = 0; k < 3; ++k) back |= swept.twin_face[3 * static_cast<std::size_t>(twin) + k] == static_cast<int>(e / 3);
    EXPECT_TRUE(back) << e;
  }
  TriangleMesh open = ball;
  open.F.conservativeResize(open.F.rows() - 1, 3);
  const SweptBody open_swept = make_swept_body(open);
  EXPECT_EQ(std::count(open_swept.twin_face.begin(), open_swept.twin_face.end(), -1), 3);
}

}  // namespace
}  // namespace repose
