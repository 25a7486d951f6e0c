#include "models/core/geometry/faces_turned.h"

#include <gtest/gtest.h>

namespace repose {
namespace {

// A box's 12 triangles: 2 on its bottom face point down, 2 on its top point
// up, and the 8 on its sides are vertical and in neither; a tilted box has
// no vertical faces, so the two halves make up the whole.
TEST(FacesTurned, SplitsByTheNormalsVerticalComponent) {
  const TriangleMesh box = make_box({0.1, 0.2, 0.3});
  const TriangleMesh down = faces_turned(box, true), up = faces_turned(box, false);
  EXPECT_EQ(down.F.rows(), 2);
  EXPECT_EQ(up.F.rows(), 2);
  EXPECT_EQ(down.V.rows(), box.V.rows());
  for (Eigen::Index f = 0; f < down.F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(down.V(down.F(f, k), 2), -0.3);
  }
  const TriangleMesh tilted = transformed(
      box, Pose{Eigen::Vector3d::Zero(), Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d(1, 1, 0).normalized()))});
  EXPECT_EQ(faces_turned(tilted, true).F.rows() + faces_turned(tilted, false).F.rows(), tilted.F.rows());
}

}  // namespace
}  // namespace repose
