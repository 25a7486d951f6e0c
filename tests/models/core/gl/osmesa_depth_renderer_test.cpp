// OSMesa depth images against the independent CPU reference (depth_image_cpu),
// cell by cell, on a sphere, a box, a concave bucket and rotated meshes, seen
// from below and from above.
//
// Where the two may differ, and by how much:
//  - Coverage: GL snaps vertices to llvmpipe's 1/256-pixel sub-pixel grid
//    (moving an edge by at most 1/512 pixel), so a cell whose centre lies
//    within kEdgeEps = 1/256 cell of a projected silhouette edge may be
//    covered in one image and not in the other. Everywhere else the coverage
//    must agree exactly. (Interior edges cannot change the coverage: GL's
//    rasterisation is watertight.)
//  - Depth, where both cover the cell: the depth buffer has 24 bits over the
//    range R, step q = R / (2^24 - 1). One q for the quantisation (rounded or
//    truncated), one for the float32 vertex depth (relative error 2^-24 of
//    NDC z in [-1, 1] is at most half a q), two for llvmpipe's float32
//    plane-equation interpolation: kDepthSteps = 4 q. On top of that the
//    snapped vertices shift the plane sideways by up to kEdgeEps, which changes
//    z by |grad z| * kEdgeEps * h: steep triangles near a cell centre (a
//    sphere's rim) get that much more, with |grad z| the largest slope of any
//    triangle within kEdgeEps of the centre.

#include "models/core/gl/osmesa_depth_renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "models/core/geometry/depth_image.h"
#include "models/core/base/error.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {
namespace {

constexpr double kEdgeEps = 1.0 / 256.0;  // cells
constexpr double kDepthSteps = 4.0;

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

double distance_to_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double len2 = ab.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Per cell: whether its centre is within eps of a projected silhouette edge,
// and the largest |grad z| of the triangles within eps of its centre.
struct EdgeProximity {
  ArrayXXu8R near_silhouette;
  ArrayXXdR slope;
};

// Calls visit(i, j, centre) for the cells whose centre lies in the xy box of
// the points, grown by pad.
template <class Visit>
void for_cells_near(const Grid& g, std::initializer_list<Eigen::Vector2d> pts, double pad, Visit visit) {
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const auto& p : pts) {
    x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x()), y0 = std::min(y0, p.y()), y1 = std::max(y1, p.y());
  }
  const int i0 = std::max(0, static_cast<int>(std::floor((x0 - pad - g.origin_x_m) / g.cell_size_m - 0.5)));
  const int i1 = std::min(g.nx - 1, static_cast<int>(std::ceil((x1 + pad - g.origin_x_m) / g.cell_size_m - 0.5)));
  const int j0 = std::max(0, static_cast<int>(std::floor((y0 - pad - g.origin_y_m) / g.cell_size_m - 0.5)));
  const int j1 = std::min(g.ny - 1, static_cast<int>(std::ceil((y1 + pad - g.origin_y_m) / g.cell_size_m - 0.5)));
  for (int j = j0; j <= j1; ++j) {
    for (int i = i0; i <= i1; ++i) visit(i, j, Eigen::Vector2d(g.centre_x(i), g.centre_y(j)));
  }
}

EdgeProximity edge_proximity(const std::vector<TriangleMesh>& meshes, const Grid& g) {
  const double eps = kEdgeEps * g.cell_size_m;
  EdgeProximity out;
  out.near_silhouette.setZero(g.ny, g.nx);
  out.slope.setZero(g.ny, g.nx);
  for (const TriangleMesh& m : meshes) {
    // faces per undirected edge, with the sign of each face's projected area
    std::map<std::pair<int, int>, std::vector<double>> edge_faces;
    for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
      const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
      const Eigen::Vector3d n = (b - a).cross(c - a);
      const double area2 = n.z();
      for (int k = 0; k < 3; ++k) {
        const int u = m.F(f, k), v = m.F(f, (k + 1) % 3);
        edge_faces[{std::min(u, v), std::max(u, v)}].push_back(area2);
      }
      const double slope = area2 != 0.0 ? n.head<2>().norm() / std::abs(area2) : std::numeric_limits<double>::infinity();
      const Eigen::Vector2d a2 = a.head<2>(), b2 = b.head<2>(), c2 = c.head<2>();
      for_cells_near(g, {a2, b2, c2}, eps, [&](int i, int j, const Eigen::Vector2d& p) {
        const double s1 = cross2(b2 - a2, p - a2), s2 = cross2(c2 - b2, p - b2), s3 = cross2(a2 - c2, p - c2);
        const bool inside = (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
        const double d = std::min({distance_to_segment(p, a2, b2), distance_to_segment(p, b2, c2),
                                   distance_to_segment(p, c2, a2)});
        if (inside || d <= eps) out.slope(j, i) = std::max(out.slope(j, i), slope);
      });
    }
    // a silhouette edge: on the boundary, or between a face seen from below and one seen from above
    for (const auto& [edge, areas] : edge_faces) {
      const bool silhouette = areas.size() != 2 || !(areas[0] * areas[1] > 0.0);
      if (!silhouette) continue;
      const Eigen::Vector2d a2 = m.V.row(edge.first).head<2>(), b2 = m.V.row(edge.second).head<2>();
      for_cells_near(g, {a2, b2}, eps, [&](int i, int j, const Eigen::Vector2d& p) {
        if (distance_to_segment(p, a2, b2) <= eps) out.near_silhouette(j, i) = 1;
      });
    }
  }
  return out;
}

struct Agreement {
  int covered_cpu = 0;
  int compared = 0;              // cells covered in both
  int near_silhouette = 0;       // cells excused from the coverage rule
  int coverage_mismatch = 0;     // anywhere
  int unexplained_mismatch = 0;  // away from every silhouette edge: must be 0
  int depth_violations = 0;      // beyond the tolerance: must be 0
  double max_depth_error_m = 0.0;
};

Agreement compare(const std::vector<TriangleMesh>& meshes, const Grid& grid, ViewFrom view, DepthRange range,
                  OsmesaDepthRenderer& renderer) {
  const DepthImage gl = renderer.render(meshes, grid, view, range);
  const DepthImage cpu = depth_image_cpu(meshes, grid, view);
  EXPECT_EQ(gl.grid, grid);
  EXPECT_EQ(gl.view, view);
  EXPECT_EQ(gl.z_m.rows(), grid.ny);
  EXPECT_EQ(gl.z_m.cols(), grid.nx);
  const EdgeProximity near = edge_proximity(meshes, grid);
  const double tol_z = kDepthSteps * renderer.depth_step_m(range);
  const double eps_m = kEdgeEps * grid.cell_size_m;
  Agreement a;
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      a.covered_cpu += cpu.is_covered(i, j);
      a.near_silhouette += near.near_silhouette(j, i);
      if (gl.is_covered(i, j) != cpu.is_covered(i, j)) {
        ++a.coverage_mismatch;
        if (!near.near_silhouette(j, i)) {
          ++a.unexplained_mismatch;
          ADD_FAILURE() << "coverage differs at cell (" << i << ", " << j << ") away from any silhouette edge: gl "
                        << int(gl.is_covered(i, j)) << " cpu " << int(cpu.is_covered(i, j));
        }
        continue;
      }
      if (!cpu.is_covered(i, j)) continue;
      ++a.compared;
      const double err = std::abs(gl.z(i, j) - cpu.z(i, j));
      a.max_depth_error_m = std::max(a.max_depth_error_m, err);
      const double allowed = tol_z + near.slope(j, i) * eps_m;
      if (!(err <= allowed)) {
        ++a.depth_violations;
        ADD_FAILURE() << "depth differs at cell (" << i << ", " << j << "): gl " << gl.z(i, j) << " cpu "
                      << cpu.z(i, j) << " |diff| " << err << " > " << allowed;
      }
    }
  }
  return a;
}

// Both views agree, and the comparison is not vacuous: most covered cells are
// compared and few are excused as near a silhouette.
void expect_agreement(const std::vector<TriangleMesh>& meshes, const Grid& grid, DepthRange range,
                      OsmesaDepthRenderer& renderer, int min_covered) {
  for (ViewFrom view : {ViewFrom::kBelow, ViewFrom::kAbove}) {
    SCOPED_TRACE(view == ViewFrom::kBelow ? "from below" : "from above");
    const Agreement a = compare(meshes, grid, view, range, renderer);
    EXPECT_EQ(a.unexplained_mismatch, 0);
    EXPECT_EQ(a.depth_violations, 0);
    EXPECT_GE(a.covered_cpu, min_covered);
    EXPECT_GE(a.compared, a.covered_cpu - a.near_silhouette);
    EXPECT_LE(a.near_silhouette, a.covered_cpu / 10 + 4);
    ::testing::Test::RecordProperty(view == ViewFrom::kBelow ? "max_depth_error_below_m" : "max_depth_error_above_m",
                   std::to_string(a.max_depth_error_m));
  }
}

TriangleMesh placed(const TriangleMesh& m, const Eigen::Vector3d& position,
                    const Eigen::Quaterniond& orientation = Eigen::Quaterniond::Identity()) {
  Pose pose;
  pose.position_m = position;
  pose.orientation = orientation;
  return transformed(m, pose);
}

// An open-topped bucket from five boxes: a floor and four walls (concave:
// from above the floor is seen between the walls).
TriangleMesh make_bucket(double half_width_m, double height_m, double wall_m) {
  const double w = half_width_m, t = wall_m / 2, hh = height_m / 2;
  TriangleMesh m = placed(make_box({w, w, t}), {0, 0, t});
  m = merged(m, placed(make_box({t, w, hh}), {-w + t, 0, hh}));
  m = merged(m, placed(make_box({t, w, hh}), {w - t, 0, hh}));
  m = merged(m, placed(make_box({w - 2 * t, t, hh}), {0, -w + t, hh}));
  m = merged(m, placed(make_box({w - 2 * t, t, hh}), {0, w - t, hh}));
  return m;
}

// Odd sizes, a non-zero origin that is not a multiple of the cell size.
Grid odd_grid() { return Grid{61, 47, 0.02, -0.637, -0.411}; }
const DepthRange kRange{-1.0, 1.0};

class OsmesaDepthRendererTest : public ::testing::Test {
 protected:
  OsmesaDepthRenderer renderer_;
};

TEST_F(OsmesaDepthRendererTest, ContextHasAtLeast24DepthBits) {
  // 24 bits over 2 m: 0.12 um
  EXPECT_LE(renderer_.depth_step_m(kRange), 2.0 / ((1 << 24) - 1) * (1 + 1e-12));
  EXPECT_GT(renderer_.depth_step_m(kRange), 0.0);
}

TEST_F(OsmesaDepthRendererTest, SphereAgreesWithCpu) {
  const TriangleMesh sphere = placed(make_sphere(0.3, 32), {-0.03, -0.05, 0.07});
  ASSERT_GT(sphere.F.rows(), 1500);
  expect_agreement({sphere}, odd_grid(), kRange, renderer_, 500);
}

TEST_F(OsmesaDepthRendererTest, SphereOnAFinerOddGridAgreesWithCpu) {
  const Grid fine{301, 257, 0.004, -0.571, -0.463};
  const TriangleMesh sphere = placed(make_sphere(0.4, 32), {0.02, 0.04, -0.1});
  expect_agreement({sphere}, fine, DepthRange{-0.6, 0.4}, renderer_, 20000);
}

TEST_F(OsmesaDepthRendererTest, SphereCrossingTheGridEdgeAgreesWithCpu) {
  const TriangleMesh sphere = placed(make_sphere(0.25, 24), {0.58, 0.5, -0.2});
  expect_agreement({sphere}, odd_grid(), kRange, renderer_, 100);
}

TEST_F(OsmesaDepthRendererTest, BoxAgreesWithCpu) {
  const TriangleMesh box = placed(make_box({0.31, 0.17, 0.12}), {-0.1, 0.02, 0.3});
  expect_agreement({box}, odd_grid(), kRange, renderer_, 300);
}

TEST_F(OsmesaDepthRendererTest, ConcaveBucketAgreesWithCpu) {
  const TriangleMesh bucket = placed(make_bucket(0.3, 0.4, 0.06), {-0.02, 0.01, -0.2});
  expect_agreement({bucket}, odd_grid(), kRange, renderer_, 600);
  // the concavity is seen from above: the floor's top between the walls
  const Grid g = odd_grid();
  const DepthImage above = renderer_.render({bucket}, g, ViewFrom::kAbove, kRange);
  const int i = static_cast<int>((-0.02 - g.origin_x_m) / g.cell_size_m);
  const int j = static_cast<int>((0.01 - g.origin_y_m) / g.cell_size_m);
  ASSERT_TRUE(above.is_covered(i, j));
  EXPECT_NEAR(above.z(i, j), -0.2 + 0.06, 1e-5);
}

TEST_F(OsmesaDepthRendererTest, RotatedBoxAgreesWithCpu) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()));
  const TriangleMesh box = placed(make_box({0.25, 0.12, 0.08}), {0.05, -0.02, 0.1}, q);
  expect_agreement({box}, odd_grid(), kRange, renderer_, 200);
}

TEST_F(OsmesaDepthRendererTest, RotatedBucketShowsItsInnerFaces) {
  const Eigen::Quaterniond q(Eigen::AngleAxisd(2.1, Eigen::Vector3d(-0.4, 1.0, 0.3).normalized()));
  const TriangleMesh bucket = placed(make_bucket(0.25, 0.3, 0.05), {0.0, 0.0, 0.1}, q);
  expect_agreement({bucket}, odd_grid(), kRange, renderer_, 300);
}

TEST_F(OsmesaDepthRendererTest, SeveralMeshesAgreeWithCpu) {
  const std::vector<TriangleMesh> meshes = {placed(make_sphere(0.15, 16), {-0.3, -0.2, 0.3}),
                                            placed(make_box({0.2, 0.2, 0.05}), {-0.2, -0.1, 0.0}),
                                            placed(make_capsule(0.08, 0.1, 16), {0.2, 0.1, -0.3})};
  expect_agreement(meshes, odd_grid(), kRange, renderer_, 300);
}

TEST(OsmesaDepthRendererTiles, TiledRenderingAgreesWithCpu) {
  OsmesaDepthRenderer small_tiles(16);
  ASSERT_EQ(small_tiles.tile_px(), 16);
  const TriangleMesh sphere = placed(make_sphere(0.3, 32), {-0.03, -0.05, 0.07});
  expect_agreement({sphere}, odd_grid(), kRange, small_tiles, 500);
}

TEST_F(OsmesaDepthRendererTest, OneByOneGrid) {
  const Grid g{1, 1, 0.1, 2.0, -3.0};
  const TriangleMesh sphere = placed(make_sphere(0.2, 16), {2.05, -2.95, 0.3});
  for (ViewFrom view : {ViewFrom::kBelow, ViewFrom::kAbove}) {
    const DepthImage gl = renderer_.render({sphere}, g, view, kRange);
    const DepthImage cpu = depth_image_cpu({sphere}, g, view);
    ASSERT_TRUE(cpu.is_covered(0, 0));
    ASSERT_TRUE(gl.is_covered(0, 0));
    EXPECT_NEAR(gl.z(0, 0), cpu.z(0, 0), 1e-5);
  }
}

TEST_F(OsmesaDepthRendererTest, NothingInViewLeavesEveryCellUncovered) {
  const Grid g = odd_grid();
  // beside the grid, and above the depth range (clipped)
  const std::vector<TriangleMesh> outside = {placed(make_sphere(0.2, 16), {3.0, 0.0, 0.0}),
                                             placed(make_box({0.2, 0.2, 0.2}), {0.0, 0.0, 1.5})};
  for (ViewFrom view : {ViewFrom::kBelow, ViewFrom::kAbove}) {
    const DepthImage gl = renderer_.render(outside, g, view, kRange);
    EXPECT_EQ(gl.covered.cast<int>().sum(), 0);
    const DepthImage empty = renderer_.render({}, g, view, kRange);
    EXPECT_EQ(empty.covered.cast<int>().sum(), 0);
  }
}

TEST_F(OsmesaDepthRendererTest, SurfacesOutsideTheRangeAreClipped) {
  // a box from z = -0.1 to 0.1 under a range [0, 1]: from below, the bottom
  // face is clipped and the top face (z = 0.1) is what remains in range
  const Grid g = odd_grid();
  const TriangleMesh box = placed(make_box({0.2, 0.2, 0.1}), {0.0, 0.0, 0.0});
  const DepthImage below = renderer_.render({box}, g, ViewFrom::kBelow, DepthRange{0.0, 1.0});
  const int i = static_cast<int>(-g.origin_x_m / g.cell_size_m), j = static_cast<int>(-g.origin_y_m / g.cell_size_m);
  ASSERT_TRUE(below.is_covered(i, j));
  EXPECT_NEAR(below.z(i, j), 0.1, 1e-6);
}

TEST_F(OsmesaDepthRendererTest, InvalidRangeIsRefused) {
  EXPECT_THROW(renderer_.render({}, odd_grid(), ViewFrom::kBelow, DepthRange{1.0, 1.0}), InputError);
  EXPECT_THROW(renderer_.render({}, Grid{0, 3, 0.1}, ViewFrom::kBelow, kRange), InputError);
}

TEST_F(OsmesaDepthRendererTest, GroundPassMarksWhereTheObjectDipsBelowTheGround) {
  // a sloped ground h = 0.05 + 0.2 x and a sphere partly below it
  const Grid g = odd_grid();
  HeightField ground(g, 0.0);
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) ground.at(i, j) = 0.05 + 0.2 * g.centre_x(i);
  }
  const TriangleMesh sphere = placed(make_sphere(0.25, 32), {0.02, -0.03, 0.18});
  const GroundContactImage contact = renderer_.render_with_ground({sphere}, ground, ViewFrom::kBelow, kRange);
  const DepthImage cpu = depth_image_cpu({sphere}, g, ViewFrom::kBelow);
  const EdgeProximity near = edge_proximity({sphere}, g);
  const double tol = kDepthSteps * renderer_.depth_step_m(kRange);
  int dipping = 0;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double h = ground.at(i, j);
      ASSERT_TRUE(contact.nearest.is_covered(i, j));
      if (near.near_silhouette(j, i)) continue;
      const double slack = tol + near.slope(j, i) * kEdgeEps * g.cell_size_m;
      const bool cpu_covered = cpu.is_covered(i, j);
      if (cpu_covered && std::abs(cpu.z(i, j) - h) <= slack) continue;  // a tie within the resolution
      const bool dips = cpu_covered && cpu.z(i, j) < h;
      dipping += dips;
      EXPECT_EQ(contact.object_nearer(j, i) != 0, dips) << "cell (" << i << ", " << j << ")";
      EXPECT_NEAR(contact.nearest.z(i, j), dips ? cpu.z(i, j) : h, slack) << "cell (" << i << ", " << j << ")";
    }
  }
  EXPECT_GT(dipping, 50);
}

}  // namespace
}  // namespace repose
