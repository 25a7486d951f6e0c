#include "models/ground/swept_mesh.h"

#include <gtest/gtest.h>

#include "models/core/depth_image.h"
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
