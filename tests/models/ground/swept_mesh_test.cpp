#include "models/ground/swept_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "models/core/geometry/depth_image.h"
#include "models/core/geometry/faces_turned.h"
#include "models/ground/collision.h"
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


// Calls `check(body, swept, from, to, what)` for each body pressed and
// lifted straight down/up (and by nothing) at each turn, off the grid's axes.
template <typename Check>
void for_each_vertical_move(const std::vector<std::pair<std::string, TriangleMesh>>& bodies,
                            const std::vector<Eigen::Quaterniond>& turns, Check check) {
  for (const auto& [name, body] : bodies) {
    const SweptBody swept = make_swept_body(body);
    for (std::size_t t = 0; t < turns.size(); ++t) {
      for (const double dz : {-0.004, 0.0035, -1e-7, 0.0}) {
        Pose from = at_position(0.0013, -0.0021, 0.05), to = from;
        from.orientation = to.orientation = turns[t];
        to.position_m.z() += dz;
        check(body, swept, from, to, name + " turn " + std::to_string(t) + " dz " + std::to_string(dz));
      }
    }
  }
}

// As the ground step uses it: a sphere pressed into and lifted out of a
// dented ground has the same underside through either path.
TEST(VerticalSweepFacesDown, PressAndLiftFindTheSameUndersideAsTheSweptMesh) {
  const TriangleMesh ball = make_sphere(0.03, 32);
  const SweptBody swept = make_swept_body(ball);
  const Grid g = centred_grid(27, 27, 0.005);
  HeightField ground(g, 0.0);
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) ground.at(i, j) = 0.002 * std::sin(0.7 * i) * std::cos(0.45 * j);
  }
  const auto renderer = make_cpu_underside_renderer();
  for (const double dz : {-0.00375, 0.00375}) {
    const Pose from = at_position(0.001, 0.0, 0.025), to = at_position(0.001, 0.0, 0.025 + dz);
    const Underside fast =
        find_underside_of_faces_down(vertical_sweep_faces_down(ball, swept, from, to), ground, *renderer);
    const Underside full = find_underside(swept_mesh(ball, swept, from, to), ground, *renderer);
    ASSERT_FALSE(full.empty());
    EXPECT_EQ(fast.footprint.i0, full.footprint.i0);
    EXPECT_EQ(fast.footprint.j0, full.footprint.j0);
    EXPECT_EQ(fast.footprint.ni, full.footprint.ni);
    EXPECT_EQ(fast.footprint.nj, full.footprint.nj);
    EXPECT_EQ(fast.top_m, full.top_m);
    EXPECT_TRUE((fast.z_m == full.z_m).all()) << "dz " << dz;
  }
}

TEST(VerticalSweep, IsVerticalMeansNoHorizontalPartAtAll) {
  EXPECT_TRUE(is_vertical(Eigen::Vector3d(0, 0, -0.01)));
  EXPECT_TRUE(is_vertical(Eigen::Vector3d(-0.0, 0, 0.01)));
  EXPECT_FALSE(is_vertical(Eigen::Vector3d(1e-300, 0, -0.01)));
  EXPECT_FALSE(is_vertical(Eigen::Vector3d(0, -1e-18, -0.01)));
}

// The fast path of a vertical press or lift must be seen from below exactly
// as the swept mesh is: per face the same corners at the same coordinates,
// in the same order, the whole swept mesh's box and the same depth image,
// bit for bit, for bodies with vertical faces (box, cylinder), curved ones,
// tilted ones, and motions down, up and tiny.
TEST(VerticalSweepFacesDown, IsTheSweptMeshsFacesTurnedDownOnTheVerticesTheyUse) {
  const std::vector<std::pair<std::string, TriangleMesh>> bodies = {
      {"sphere", make_sphere(0.03, 32)},
      {"box", make_box(Eigen::Vector3d(0.02, 0.03, 0.01))},
      {"cylinder", make_cylinder(0.025, 0.02, 24)},
      {"capsule", make_capsule(0.015, 0.02, 16)}};
  const std::vector<Eigen::Quaterniond> turns = {
      Eigen::Quaterniond::Identity(), Eigen::Quaterniond(Eigen::AngleAxisd(0.7, Eigen::Vector3d::UnitZ())),
      Eigen::Quaterniond(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 0.5).normalized()))};
  const Grid g = centred_grid(40, 40, 0.0025);
  for_each_vertical_move(bodies, turns, [&](const TriangleMesh& body, const SweptBody& swept, const Pose& from,
                                            const Pose& to, const std::string& what) {
    const FacesDown fast = vertical_sweep_faces_down(body, swept, from, to);
    const TriangleMesh full = faces_turned(swept_mesh(body, swept, from, to), true);
    ASSERT_EQ(fast.mesh.F.rows(), full.F.rows()) << what;
    for (Eigen::Index f = 0; f < full.F.rows(); ++f) {
      for (int k = 0; k < 3; ++k) {
        EXPECT_TRUE(fast.mesh.V.row(fast.mesh.F(f, k)) == full.V.row(full.F(f, k))) << what << " face " << f;
      }
    }
    const Aabb box = bounding_box(full);
    EXPECT_TRUE(fast.box.min == box.min && fast.box.max == box.max) << what;
    const DepthImage x = depth_image_cpu(fast.mesh, g, ViewFrom::kBelow), y = depth_image_cpu(full, g, ViewFrom::kBelow);
    EXPECT_TRUE((x.covered == y.covered).all()) << what;
    EXPECT_TRUE((x.covered == 0 || x.z_m == y.z_m).all()) << what;
  });
}

// A kept cache never changes the result: a press, a turn, a sideways step,
// a lift, a press again and one to height 0, each against a fresh
// computation and against the swept mesh's faces turned down.
TEST(VerticalSweepFacesDown, KeptCacheGivesTheSameFacesAsNone) {
  const TriangleMesh ball = make_sphere(0.03, 32);
  const SweptBody swept = make_swept_body(ball);
  VerticalSweepCache cache;
  Pose from = at_position(0.0013, -0.0021, 0.05);
  const Eigen::Quaterniond turned(Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, 2, 0.5).normalized()));
  const std::vector<std::pair<double, int>> moves = {{-0.003, 0}, {-0.003, 0}, {-0.002, 1}, {-0.002, 1},
                                                      {-0.001, 2}, {0.004, 2},  {0.004, 0},  {-0.003, 0},
                                                      {0.0, 3}};
  for (std::size_t s = 0; s < moves.size(); ++s) {
    const auto [dz, kind] = moves[s];
    if (kind == 1) from.orientation = turned;
    if (kind == 2) from.position_m.x() += 1e-4;
    Pose to = from;
    to.position_m.z() += dz;
    if (kind == 3) to.position_m.z() = 0.0;
    const FacesDown kept = vertical_sweep_faces_down(ball, swept, from, to, &cache);
    const FacesDown fresh = vertical_sweep_faces_down(ball, swept, from, to);
    EXPECT_TRUE(kept.mesh.F == fresh.mesh.F && kept.mesh.V == fresh.mesh.V) << "move " << s;
    EXPECT_TRUE(kept.box.min == fresh.box.min && kept.box.max == fresh.box.max) << "move " << s;
    const TriangleMesh full = faces_turned(swept_mesh(ball, swept, from, to), true);
    ASSERT_EQ(kept.mesh.F.rows(), full.F.rows()) << "move " << s;
    for (Eigen::Index f = 0; f < full.F.rows(); ++f) {
      for (int k = 0; k < 3; ++k) {
        ASSERT_TRUE(kept.mesh.V.row(kept.mesh.F(f, k)) == full.V.row(full.F(f, k))) << "move " << s << " face " << f;
      }
    }
    const Aabb box = bounding_box(full);
    EXPECT_TRUE(kept.box.min == box.min && kept.box.max == box.max) << "move " << s;
    from = to;
  }
}

}  // namespace
}  // namespace repose
