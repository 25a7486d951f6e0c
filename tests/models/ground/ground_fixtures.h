#pragma once
// Small scenes and checks shared by the ground model tests, built in code.

#include <cmath>
#include <map>
#include <utility>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "models/core/config/scene.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/ground/collision.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"
#include "models/ground/ground_step.h"

namespace repose::testing {

constexpr double kDeg = std::numbers::pi / 180.0;

// n x n cells of size h centred on the origin.
inline Grid centred_grid(int nx, int ny, double h) {
  Grid g;
  g.nx = nx;
  g.ny = ny;
  g.cell_size_m = h;
  g.origin_x_m = -0.5 * nx * h;
  g.origin_y_m = -0.5 * ny * h;
  return g;
}

inline Material sand() {
  Material m;
  material_preset("sand", &m);
  return m;
}

inline Keyframe at(double t, double x, double y, double z) {
  Keyframe k;
  k.time_s = t;
  k.pose.position_m = Eigen::Vector3d(x, y, z);
  return k;
}

inline ObjectSpec sphere(double radius_m, std::vector<Keyframe> keys, int segments = 32) {
  ObjectSpec o;
  o.name = "ball";
  o.shape = ObjectSpec::Shape::kSphere;
  o.radius_m = radius_m;
  o.body = make_sphere(radius_m, segments);
  o.keyframes = std::move(keys);
  return o;
}

// A flat ground of one material, the given objects, steps of 1 s.
inline Scene flat_scene(const Grid& grid, double height_m, const Material& material, std::vector<ObjectSpec> objects,
                        int steps) {
  Scene s;
  s.name = "test";
  s.ground.grid = grid;
  s.ground.initial.height_m = height_m;
  s = with_material(std::move(s), material);
  s.ground.material = material.name;
  s.objects = std::move(objects);
  s.time.step_s = 1.0;
  s.time.duration_s = steps;
  return s;
}

// Largest |h(i) - h(j)| / cell size over all 4-neighbour pairs.
inline double max_slope(const HeightField& h) {
  const ArrayXXdR& a = h.heights();
  double m = 0.0;
  if (a.cols() > 1) m = std::max(m, (a.rightCols(a.cols() - 1) - a.leftCols(a.cols() - 1)).abs().maxCoeff());
  if (a.rows() > 1) m = std::max(m, (a.bottomRows(a.rows() - 1) - a.topRows(a.rows() - 1)).abs().maxCoeff());
  return m / h.grid().cell_size_m;
}

// The ledger balances to round-off (relative 1e-11 of the initial volume).
inline void expect_balanced(const VolumeLedger& ledger, double final_m3) {
  EXPECT_NEAR(ledger.imbalance_m3(final_m3), 0.0, 1e-11 * std::abs(ledger.initial_m3) + 1e-15)
      << "initial " << ledger.initial_m3 << " final " << final_m3 << " compressed " << ledger.compressed_m3
      << " left " << ledger.left_grid_m3;
}

}  // namespace repose::testing

namespace repose::testing {

// A sphere made by subdividing an octahedron and projecting onto the sphere:
// unlike a UV sphere its triangulation is symmetric under x and y mirrors and
// the x-y swap, so a symmetric press must give a symmetric crater.
inline TriangleMesh make_octasphere(double radius_m, int subdivisions) {
  std::vector<Eigen::Vector3d> v = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  std::vector<Eigen::Vector3i> f = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  for (int s = 0; s < subdivisions; ++s) {
    std::map<std::pair<int, int>, int> mid;
    auto midpoint = [&](int a, int b) {
      const auto key = std::minmax(a, b);
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      v.push_back(0.5 * (v[a] + v[b]));
      return mid[key] = static_cast<int>(v.size()) - 1;
    };
    std::vector<Eigen::Vector3i> g;
    for (const auto& t : f) {
      const int ab = midpoint(t[0], t[1]), bc = midpoint(t[1], t[2]), ca = midpoint(t[2], t[0]);
      g.emplace_back(t[0], ab, ca);
      g.emplace_back(t[1], bc, ab);
      g.emplace_back(t[2], ca, bc);
      g.emplace_back(ab, bc, ca);
    }
    f = std::move(g);
  }
  TriangleMesh m;
  m.V.resize(static_cast<Eigen::Index>(v.size()), 3);
  for (std::size_t k = 0; k < v.size(); ++k) m.V.row(static_cast<Eigen::Index>(k)) = radius_m * v[k].normalized();
  m.F.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (std::size_t k = 0; k < f.size(); ++k) m.F.row(static_cast<Eigen::Index>(k)) = f[k].transpose();
  return m;
}

// The drag both displacement_test.cpp and heap_in_one_pass_test.cpp check
// for symmetry, at 5 mm cells: a sphere (an octasphere, symmetric under the
// grid's mirrors) pressed 2 cm into a bed of sand near -0.1 * dir from the
// grid's centre, dragged 0.2 m along dir, lifted. Its outline stays off rows
// of cell centres (centre 1.1 mm off the cells' corners along the drag): an
// edge through a row of centres is rasterised (depth_image.cpp) by a rule
// that does not commute with the mirrors, so the symmetry would hold only to
// that rule.
inline Scene symmetric_drag_scene(const Eigen::Vector2d& dir, double bed_m, double radius_m) {
  const double low = bed_m + radius_m - 0.02, high = bed_m + radius_m + 0.005;
  const Eigen::Vector2d a = -0.0989 * dir, b = 0.1011 * dir;
  ObjectSpec ball = sphere(radius_m, {at(0, a.x(), a.y(), high), at(0.3, a.x(), a.y(), low),
                                      at(1.3, b.x(), b.y(), low), at(1.5, b.x(), b.y(), 0.2)});
  ball.body = make_octasphere(radius_m, 4);
  Scene scene = flat_scene(centred_grid(80, 80, 0.005), bed_m, sand(), {ball}, 2);
  scene.time.step_s = 0.02;
  return scene;
}

// Runs `steps` steps of a scene on the CPU collision path; the final state.
inline GroundState run_steps(const GroundModel& model, const GroundParams& params, double initial_height_m,
                             int steps) {
  GroundState state = make_ground_state(model, HeightField(model.grid, initial_height_m));
  auto renderer = make_cpu_underside_renderer();
  for (int s = 0; s < steps; ++s) step(model, params, *renderer, &state);
  return state;
}

}  // namespace repose::testing
