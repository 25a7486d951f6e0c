#include "models/core/geometry/depth_image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace repose {
namespace {

// Every cell whose centre lies inside a triangle (edges included), by a
// brute-force test over the whole grid with the renderer's own barycentric
// weights: the renderer's index range (which cells it tries) must never
// leave one out, whether the triangle lies inside the grid, across its
// border, outside it, or has its corners and edges exactly on cell centres.
TEST(DepthImageCpu, CoversExactlyTheCentresInsideEachTriangle) {
  const Grid g{16, 12, 0.5, -1.0, -2.0};  // centres at x = -0.75, -0.25, ..., y = -1.75, ...
  std::mt19937 rng(7);
  // corners on a lattice of quarter cells (so on centres and edges exactly), reaching past the grid
  std::uniform_int_distribution<int> qx(-12, 4 * 16 - 4 + 12), qy(-12, 4 * 12 - 8 + 12);
  std::uniform_real_distribution<double> z(-1.0, 1.0);
  for (int trial = 0; trial < 300; ++trial) {
    TriangleMesh tri;
    tri.V.resize(3, 3);
    for (int k = 0; k < 3; ++k) tri.V.row(k) << -1.0 + 0.125 * qx(rng), -2.0 + 0.125 * qy(rng), z(rng);
    tri.F.resize(1, 3);
    tri.F << 0, 1, 2;
    const DepthImage img = depth_image_cpu(tri, g, ViewFrom::kBelow);
    const Eigen::Vector3d a = tri.V.row(0), b = tri.V.row(1), c = tri.V.row(2);
    auto edge = [](const Eigen::Vector3d& p, const Eigen::Vector3d& q, double x, double y) {
      return (q.x() - p.x()) * (y - p.y()) - (q.y() - p.y()) * (x - p.x());
    };
    const double area = edge(a, b, c.x(), c.y());
    for (int j = 0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) {
        const double wa = edge(b, c, g.centre_x(i), g.centre_y(j)) / area;
        const double wb = edge(c, a, g.centre_x(i), g.centre_y(j)) / area;
        const bool inside = area != 0.0 && wa >= 0.0 && wb >= 0.0 && 1.0 - wa - wb >= 0.0;
        ASSERT_EQ(img.is_covered(i, j), inside) << "trial " << trial << " cell " << i << "," << j;
        if (inside) {
          EXPECT_EQ(img.z(i, j), wa * a.z() + wb * b.z() + (1.0 - wa - wb) * c.z());
        }
      }
    }
  }
}

// One mesh or the same mesh in a list: the same image.
TEST(DepthImageCpu, OneMeshAsAList) {
  const Grid g{20, 20, 0.01, -0.1, -0.1};
  const TriangleMesh ball = make_sphere(0.06, 16);
  const DepthImage one = depth_image_cpu(ball, g, ViewFrom::kAbove);
  const DepthImage list = depth_image_cpu(std::vector<TriangleMesh>{ball}, g, ViewFrom::kAbove);
  ASSERT_TRUE((one.covered == list.covered).all());
  EXPECT_TRUE((one.covered == 0 || one.z_m == list.z_m).all());
}

// The cache draws each mesh as depth_image_cpu does, bit for bit: a mesh
// moved along z alone (drawn from the kept coverage), moved sideways by a
// hair, given other faces, or drawn on another grid or from the other side
// (each drawn afresh), in a sequence that goes back and forth between them.
TEST(DepthImageCpuCache, DrawsEveryMeshAsDepthImageCpu) {
  const Grid g{20, 20, 0.01, -0.1, -0.1}, other{10, 12, 0.013, -0.07, -0.05};
  const TriangleMesh ball = make_sphere(0.06, 16);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> dz(-0.05, 0.05);
  DepthImageCpuCache cache;
  for (int trial = 0; trial < 60; ++trial) {
    TriangleMesh m = ball;
    m.V.col(2).array() += dz(rng);
    if (trial % 7 == 3) m.V(5, 0) = std::nextafter(m.V(5, 0), 1.0);
    if (trial % 11 == 5) m.F.row(0).swap(m.F.row(1));
    const Grid& grid = trial % 5 == 4 ? other : g;
    const ViewFrom view = trial % 9 == 8 ? ViewFrom::kAbove : ViewFrom::kBelow;
    const DepthImage fresh = depth_image_cpu(m, grid, view), kept = cache.render(m, grid, view);
    ASSERT_TRUE((fresh.covered == kept.covered).all()) << "trial " << trial;
    EXPECT_TRUE((fresh.covered == 0 || fresh.z_m == kept.z_m).all()) << "trial " << trial;
  }
}

}  // namespace
}  // namespace repose
