#include "models/ground/collision.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

TEST(Collision, FootprintCoversTheCentresInsideTheBox) {
  const Grid g = centred_grid(10, 10, 0.1);  // centres at -0.45 .. 0.45
  Aabb box;
  box.extend(Eigen::Vector3d(-0.2, -0.5, 0));
  box.extend(Eigen::Vector3d(0.06, 5.0, 1));
  const Footprint f = footprint_of(box, g);
  EXPECT_EQ(f.i0, 3);   // -0.15
  EXPECT_EQ(f.ni, 3);   // .. 0.05
  EXPECT_EQ(f.j0, 0);
  EXPECT_EQ(f.nj, 10);  // clamped to the grid
  Aabb outside;
  outside.extend(Eigen::Vector3d(2, 2, 0));
  outside.extend(Eigen::Vector3d(3, 3, 1));
  EXPECT_TRUE(footprint_of(outside, g).empty());
}

TEST(Collision, AboveTheGroundIsNoContact) {
  const HeightField ground(centred_grid(16, 16, 0.01), 0.05);
  auto cpu = make_cpu_underside_renderer();
  EXPECT_TRUE(find_underside(transformed(make_sphere(0.03), Pose{Eigen::Vector3d(0, 0, 0.09), {}}), ground, *cpu).empty());
  const Underside u = find_underside(transformed(make_sphere(0.03), Pose{Eigen::Vector3d(0, 0, 0.07), {}}), ground, *cpu);
  ASSERT_FALSE(u.empty());
  EXPECT_NEAR(u.at(8, 8), 0.04, 1e-3);
  EXPECT_TRUE(std::isinf(u.at(0, 0)));
}

// The two collision paths agree to 1e-4 m (1 % of a cell).
TEST(Collision, CpuAndOsmesaAgree) {
  std::unique_ptr<UndersideRenderer> gl;
  try {
    gl = make_osmesa_underside_renderer();
  } catch (const InputError& e) {
    GTEST_SKIP() << e.what();
  }
  auto cpu = make_cpu_underside_renderer();
  const HeightField ground(centred_grid(64, 48, 0.01), 0.05);
  const TriangleMesh ball = transformed(make_sphere(0.1, 24), Pose{Eigen::Vector3d(0.013, -0.021, 0.12), {}});
  const Underside a = find_underside(ball, ground, *cpu);
  const Underside b = find_underside(ball, ground, *gl);
  ASSERT_EQ(a.footprint.ni, b.footprint.ni);
  ASSERT_EQ(a.footprint.nj, b.footprint.nj);
  int covered = 0, disagree = 0;
  for (int j = 0; j < a.footprint.nj; ++j) {
    for (int i = 0; i < a.footprint.ni; ++i) {
      const double za = a.z_m(j, i), zb = b.z_m(j, i);
      if (std::isinf(za) != std::isinf(zb)) {
        ++disagree;  // a centre on a silhouette edge may fall either way
        continue;
      }
      if (std::isinf(za)) continue;
      ++covered;
      // float vertex positions: on steep flanks a tiny xy error is a larger z error
      EXPECT_NEAR(za, zb, 1e-4) << i << "," << j;
    }
  }
  EXPECT_GT(covered, 100);
  EXPECT_LE(disagree, covered / 50);
}

}  // namespace
}  // namespace repose
