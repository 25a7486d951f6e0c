#pragma once
// Small scenes shared by the height-span model's tests, built in code: the
// bucket of the scoop scenes (experiments/meshes/bucket.obj), a flat plate,
// a flat bed of sand, and checks of the model's invariants.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "models/core/config/initial_height.h"
#include "models/core/config/scene.h"
#include "models/core/io/mesh_io.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_section.h"
#include "models/heightspan/heightspan_model.h"
#include "models/heightspan/heightspan_section.h"
#include "models/heightspan/heightspan_state.h"

namespace repose::testing {

constexpr double kDeg = std::numbers::pi / 180.0;

// The bucket of experiments/meshes (8 cm across, 5 cm high, centred on its origin), scaled.
inline TriangleMesh bucket_mesh(double scale = 1.0) {
  static const TriangleMesh mesh = read_mesh(std::string(REPOSE_SOURCE_DIR) + "/experiments/meshes/bucket.obj");
  return scaled(mesh, Eigen::Vector3d::Constant(scale));
}

inline Keyframe key(double t, double x, double y, double z, double pitch_deg = 0.0) {
  Keyframe k;
  k.time_s = t;
  k.pose.position_m = Eigen::Vector3d(x, y, z);
  k.pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(pitch_deg * kDeg, Eigen::Vector3d::UnitY()));
  return k;
}

inline ObjectSpec mesh_object(const std::string& name, const TriangleMesh& body, std::vector<Keyframe> keys) {
  ObjectSpec o;
  o.name = name;
  o.shape = ObjectSpec::Shape::kMesh;
  o.body = body;
  o.keyframes = std::move(keys);
  return o;
}

// nx x ny cells of size h from the origin, a flat bed of `height_m` of sand
// (theta, sigma, En given), the objects (holds_material as given), steps of dt.
inline Scene bed_scene(int nx, int ny, double h, double height_m, std::vector<ObjectSpec> objects, int steps,
                       double dt_s = 1.0 / 30.0, double theta_deg = 30.0, double sigma = 0.2, int passes = 5) {
  Scene s;
  s.name = "heightspan_test";
  s.seed = 3;
  s.ground.grid = Grid{nx, ny, h, 0.0, 0.0};
  s.ground.initial.height_m = height_m;
  Material sand;
  material_preset("sand", &sand);
  sand.repose_angle_rad = theta_deg * kDeg;
  sand.sigma = sigma;
  sand.erosion_iterations = passes;
  s = with_material(std::move(s), sand);
  HeightSpanSection section;
  section.options.frame_interval_s = 0.0;
  for (const ObjectSpec& o : objects) section.holds_material[o.name] = true;
  s = with_heightspan(std::move(s), section);
  s.objects = std::move(objects);
  s.time.step_s = dt_s;
  s.time.duration_s = steps * dt_s;
  return s;
}

// An upright bucket (8 cm: 16 cells of 5 mm) standing at (x_m, 0.1 m) with its
// centre 8 cm up (its floor's underside at 5.5 cm) on a 40 x 40 grid with a
// bed of bed_m, at its first pose: its map and the ground, nothing stepped.
struct StandingBucket {
  HeightSpanModel model;
  HeightSpanState state;
};
inline StandingBucket standing_bucket(double x_m, double bed_m = 0.01) {
  Scene s = bed_scene(40, 40, 0.005, bed_m, {mesh_object("bucket", bucket_mesh(), {key(0.0, x_m, 0.1, 0.08)})}, 1);
  StandingBucket b{build_heightspan_model(s), {}};
  b.state = make_heightspan_state(b.model, make_initial_height(s));
  return b;
}

// No span's material lies inside the object: it is >= 0 and its level is at
// most the next span's bottom (to round-off).
inline void expect_spans_valid(const SpanMap& map, const std::string& where) {
  const double tolerance_m = 1e-12;
  for (std::int64_t c = 0; c < static_cast<std::int64_t>(map.grid.cell_count()); ++c) {
    const Span* s = map.begin(c);
    for (int k = 0; k < map.count(c); ++k) {
      ASSERT_GE(s[k].material_m, -tolerance_m) << where << " cell " << c;
      ASSERT_LT(s[k].bottom_m, s[k].top_m) << where << " cell " << c;
      if (k + 1 < map.count(c)) {
        ASSERT_LE(s[k].level_m(), s[k + 1].bottom_m + tolerance_m) << where << " cell " << c;
      }
    }
  }
}

inline double relative_imbalance(const HeightSpanState& state, double initial_m3) {
  return std::abs(accounted_m3(state) - initial_m3) / initial_m3;
}

}  // namespace repose::testing

namespace repose::testing {

// Puts `height_m` of material on the top span of every column whose top
// is at `top_z_m` (to 1 um): the floor of an upright bucket, a plate.
inline double fill_spans(SpanMap* map, double height_m, double top_z_m) {
  for (std::int64_t c = 0; c < static_cast<std::int64_t>(map->grid.cell_count()); ++c) {
    if (map->count(c) == 0) continue;
    Span& s = map->begin(c)[map->count(c) - 1];
    if (std::abs(s.top_m - top_z_m) < 1e-6) s.material_m += height_m;
  }
  return map->material_m3();
}

}  // namespace repose::testing
