#include "models/heightspan/osmesa_span_peeling.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"

namespace repose {
namespace {

// The CPU and OSMesa span maps of a mesh: the same number of spans in every
// cell, their ends within a few depth-buffer steps over the mesh's height
// (plus the 1 % pad) and what GL's snapping of vertices to 1/256 of a pixel
// moves a sloping face by (at most a slope of 1 here: cell / 256).
void expect_agree(const TriangleMesh& mesh, const Grid& grid, const std::string& what) {
  OsmesaDepthPeeler peeler;
  const SpanMap cpu = peel_spans(mesh, grid), gl = peel_spans_osmesa(mesh, grid, peeler);
  const Aabb box = bounding_box(mesh);
  const double step = (box.max.z() - box.min.z() + 2 * std::max(1e-3, 0.01 * (box.max.z() - box.min.z()))) / 16777215.0;
  const double tolerance_m = 4 * step + grid.cell_size_m / 256;
  int compared = 0;
  for (std::int64_t c = 0; c < static_cast<std::int64_t>(grid.cell_count()); ++c) {
    ASSERT_EQ(cpu.count(c), gl.count(c)) << what << " cell " << c;
    for (int k = 0; k < cpu.count(c); ++k) {
      EXPECT_NEAR(cpu.begin(c)[k].bottom_m, gl.begin(c)[k].bottom_m, tolerance_m) << what << " cell " << c;
      EXPECT_NEAR(cpu.begin(c)[k].top_m, gl.begin(c)[k].top_m, tolerance_m) << what << " cell " << c;
      ++compared;
    }
  }
  EXPECT_GT(compared, 0) << what;
}

TEST(OsmesaSpanPeeling, AgreesWithTheCpuPathOnTheBucketUprightTiltedAndTipped) {
  const Grid grid{48, 48, 0.0025, -0.06 + 0.00037, -0.06 - 0.00051};  // centres off the mesh's edges
  for (const double pitch : {0.0, 35.0, 80.0, 135.0}) {
    const Pose pose{{0.0, 0.0, 0.1}, Eigen::Quaterniond(Eigen::AngleAxisd(pitch * testing::kDeg, Eigen::Vector3d::UnitY()))};
    expect_agree(transformed(testing::bucket_mesh(), pose), grid, "bucket at " + std::to_string(pitch) + " deg");
  }
}

TEST(OsmesaSpanPeeling, AgreesOnStackedAndOverlappingParts) {
  const TriangleMesh low = make_box({0.01, 0.01, 0.005});
  const TriangleMesh high = transformed(make_box({0.012, 0.008, 0.005}), Pose{{0.001, 0, 0.03}, Eigen::Quaterniond::Identity()});
  const TriangleMesh sphere = transformed(make_sphere(0.009, 24), Pose{{-0.003, 0.002, 0.012}, Eigen::Quaterniond::Identity()});
  expect_agree(merged(merged(low, high), sphere), Grid{32, 32, 0.001, -0.0163, -0.0157}, "stack");
}

}  // namespace
}  // namespace repose
