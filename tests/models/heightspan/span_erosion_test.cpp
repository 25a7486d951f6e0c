#include "models/heightspan/span_erosion.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"
#include "models/core/config/initial_height.h"

namespace repose {
namespace {

using testing::bed_scene;
using testing::key;
using testing::mesh_object;

// A flat plate, 12 x 12 cm, 1 cm thick, its top at z_top over a bed of 1 cm.
struct Plate {
  HeightSpanModel model;
  GroundParams params;
  HeightSpanState state;
  Plate(double z_top, double theta_deg, double near_cells = 1.0) {
    const TriangleMesh plate = make_box({0.06, 0.06, 0.005});
    Scene s = bed_scene(48, 48, 0.005, 0.01, {mesh_object("plate", plate, {key(0.0, 0.12, 0.12, z_top - 0.005)})}, 1,
                        1.0 / 30.0, theta_deg, 0.2, 5);
    HeightSpanSection section = heightspan_section(s);
    section.options.near_ground_cells = near_cells;
    s = with_heightspan(s, section);
    model = build_heightspan_model(s);
    params = default_params(model.ground);
    state = make_heightspan_state(model, make_initial_height(s));
  }
  SpanMap& map() { return state.held[0].map; }
  SpanErosionResult erode(int times, const RigidVelocity& velocity = {}) {
    SpanErosionResult sum;
    for (int k = 0; k < times; ++k) {
      const SpanErosionResult r =
          erode_spans(model, params, velocity, &state.held[0], &state.ground, &state.particles, &state.rng);
      sum.moves += r.moves;
      sum.to_ground_m3 += r.to_ground_m3;
      sum.to_particles_m3 += r.to_particles_m3;
      sum.from_ground_m3 += r.from_ground_m3;
    }
    return sum;
  }
  Span& span_at(double x, double y) {
    int i, j;
    EXPECT_TRUE(map().cell_at(x, y, &i, &j));
    return map().begin(map().cell(i, j))[0];
  }
};

// Largest slope of the material's surface between neighbouring spans of the plate.
double max_span_slope(const SpanMap& map) {
  double m = 0.0;
  for (int j = 0; j + 1 < map.grid.ny; ++j) {
    for (int i = 0; i + 1 < map.grid.nx; ++i) {
      const std::int64_t c = map.cell(i, j);
      if (map.count(c) == 0) continue;
      for (const std::int64_t n : {map.cell(i + 1, j), map.cell(i, j + 1)}) {
        if (map.count(n) == 0) continue;
        m = std::max(m, std::abs(map.begin(c)[0].level_m() - map.begin(n)[0].level_m()) / map.grid.cell_size_m);
      }
    }
  }
  return m;
}

TEST(SpanErosion, AHeapOnAFlatPlateSettlesWithItsFlanksAtTheAngleOfRepose) {
  Plate p(0.05, 30.0);
  p.span_at(0.12, 0.12).material_m = 0.03;  // a column of 3 cm on one cell
  const double initial = accounted_m3(p.state);
  p.erode(400);
  const double tan_theta = std::tan(30.0 * testing::kDeg);
  EXPECT_LE(max_span_slope(p.map()), tan_theta * (1 + 1e-3) + 1e-6);
  EXPECT_GT(max_span_slope(p.map()), 0.9 * tan_theta);  // a heap, not flattened
  EXPECT_LT(std::abs(accounted_m3(p.state) - initial) / initial, 1e-13);
  EXPECT_FALSE(p.state.particles.built);  // it stayed on the plate
}

TEST(SpanErosion, AHeapSpreadsSymmetrically) {
  Plate p(0.05, 30.0);
  p.span_at(0.1225, 0.1225).material_m = 0.02;  // on the centre cell (0.12 .. 0.125)
  p.erode(50);
  const double a = p.span_at(0.1225 + 0.01, 0.1225).material_m, b = p.span_at(0.1225 - 0.01, 0.1225).material_m;
  const double c = p.span_at(0.1225, 0.1225 + 0.01).material_m, d = p.span_at(0.1225, 0.1225 - 0.01).material_m;
  EXPECT_GT(a, 0.0);
  EXPECT_NEAR(a, b, 1e-15);
  EXPECT_NEAR(a, c, 1e-15);
  EXPECT_NEAR(a, d, 1e-15);
}

TEST(SpanErosion, MaterialNearTheGroundSlidesOntoItAndFarAboveItFalls) {
  Plate low(0.0125, 30.0);  // the plate's top 2.5 mm (half a cell) above the bed beside it
  low.span_at(0.1775, 0.12).material_m = 0.02;  // by the +x edge (the plate ends at 0.18)
  const SpanErosionResult near = low.erode(5);
  EXPECT_GT(near.to_ground_m3, 0.0);
  EXPECT_EQ(near.to_particles_m3, 0.0);
  Plate high(0.05, 30.0);
  high.span_at(0.1775, 0.12).material_m = 0.02;
  const SpanErosionResult far = high.erode(5);
  EXPECT_EQ(far.to_ground_m3, 0.0);
  EXPECT_GT(far.to_particles_m3, 0.0);
  EXPECT_TRUE(high.state.particles.built);
  EXPECT_NEAR(high.state.particles.in_flight_m3(), far.to_particles_m3, 1e-18);
}

TEST(SpanErosion, MaterialFallingOffAnEdgeLeavesFromTheCellBeyondItAtItsLevel) {
  Plate high(0.05, 30.0);
  high.span_at(0.1775, 0.1225).material_m = 0.02;  // the plate's +x edge column (0.175 .. 0.18)
  high.params.materials.front().erosion_iterations = 1;  // one pass: only that column gives
  high.erode(1);
  ASSERT_FALSE(high.state.particles.particles.empty());
  for (const Particle& q : high.state.particles.particles) {
    // released at the centre of the column beyond the edge, (0.18 .. 0.185) x (0.12 .. 0.125)
    EXPECT_NEAR(q.position_m.x(), 0.1825, 1e-12);
    EXPECT_NEAR(q.position_m.y(), 0.1225, 1e-12);
    EXPECT_NEAR(q.position_m.z(), 0.05 + 0.02, 1e-12);  // the level it left at
  }
}

TEST(SpanErosion, MaterialFallingOffAnEdgeMovesWithTheObjectAndAtTheReleaseSpeedAlongItsWay) {
  Plate high(0.05, 30.0);
  high.model.options.particle_spread_m_s = 0.0;
  high.model.options.release_speed_m_s = 0.3;
  high.span_at(0.1775, 0.1225).material_m = 0.02;  // the plate's +x edge column: it flows off towards +x
  high.params.materials.front().erosion_iterations = 1;
  RigidVelocity carried;
  carried.linear_m_s = {0.0, 0.1, 0.0};
  carried.angular_rad_s = {0.0, 0.0, 2.0};  // turning about the plate's centre, (0.12, 0.12)
  carried.centre_m = {0.12, 0.12, 0.05};
  high.erode(1, carried);
  ASSERT_FALSE(high.state.particles.particles.empty());
  for (const Particle& q : high.state.particles.particles) {
    EXPECT_TRUE(q.velocity_m_s.isApprox(carried.at(q.position_m) + Eigen::Vector3d(0.3, 0.0, 0.0), 1e-12));
  }
}

TEST(SpanErosion, GroundHigherThanASpanSlidesOntoIt) {
  Plate p(0.0125, 30.0);
  // a heap of ground beside the plate's -x edge (0.06), 2 cm above its top
  p.state.ground.height.at(11, 24) = 0.0325;
  const double before = accounted_m3(p.state);
  const SpanErosionResult r = p.erode(5);
  EXPECT_GT(r.from_ground_m3, 0.0);
  EXPECT_GT(p.span_at(0.0625, 0.1225).material_m, 0.0);
  EXPECT_NEAR(accounted_m3(p.state), before, 1e-15);
}

TEST(SpanErosion, WallsBlockAndMaterialNeverRisesIntoTheSpanAbove) {
  // a bucket at rest holding a steep heap against one wall: it spreads over
  // the floor, never through the wall, and stays in the bucket
  Scene s = bed_scene(40, 40, 0.005, 0.01, {mesh_object("bucket", testing::bucket_mesh(), {key(0.0, 0.1, 0.1, 0.08)})}, 1);
  HeightSpanModel model = build_heightspan_model(s);
  GroundParams params = default_params(model.ground);
  HeightSpanState state = make_heightspan_state(model, make_initial_height(s));
  SpanMap& map = state.held[0].map;
  int i, j;
  ASSERT_TRUE(map.cell_at(0.1 + 0.029, 0.1, &i, &j));  // the floor by the +x wall
  map.begin(map.cell(i, j))[0].material_m = 0.04;
  const double held = map.material_m3();
  for (int k = 0; k < 200; ++k) {
    erode_spans(model, params, RigidVelocity{}, &state.held[0], &state.ground, &state.particles, &state.rng);
  }
  testing::expect_spans_valid(map, "bucket");
  EXPECT_NEAR(map.material_m3(), held, 1e-15);
  EXPECT_FALSE(state.particles.built);
}

// A layer `thickness_m` deep on every cell of a 12 x 12 cm plate pitched by
// pitch_deg about y, its centre 9 cm above a 1 cm bed; sand of 30 deg and a
// slow slope rule (sigma 0.05).
HeightSpanState layer_on_a_pitched_plate(double pitch_deg, double thickness_m, HeightSpanModel* model) {
  const TriangleMesh plate = make_box({0.06, 0.06, 0.005});
  Scene s = bed_scene(48, 48, 0.005, 0.01, {mesh_object("plate", plate, {key(0.0, 0.12, 0.12, 0.1, pitch_deg)})}, 1,
                      1.0 / 30.0, 30.0, 0.05, 5);
  *model = build_heightspan_model(s);
  HeightSpanState state = make_heightspan_state(*model, make_initial_height(s));
  for (Span& sp : state.held[0].map.spans) sp.material_m = thickness_m;
  return state;
}

TEST(SpanErosion, MaterialOnASpanSteeperThanTheReposeAngleSlidesOffInFull) {
  // pitched 40 deg (> 30): nothing can rest on the plate, whatever sigma; it leaves within
  // a few steps of En = 5 passes (the plate is 19 cells long), as a tipped bucket empties
  HeightSpanModel model;
  HeightSpanState steep = layer_on_a_pitched_plate(40.0, 0.001, &model);
  const double initial = accounted_m3(steep);
  const GroundParams params = default_params(model.ground);
  for (int k = 0; k < 8; ++k) {
    erode_spans(model, params, RigidVelocity{}, &steep.held[0], &steep.ground, &steep.particles, &steep.rng);
  }
  EXPECT_LT(steep.held[0].map.material_m3(), 1e-9 * initial);
  EXPECT_NEAR(accounted_m3(steep), initial, 1e-14 * initial);
  // pitched 20 deg (< 30): a 1 mm layer (less than a cell x (tan 30 - tan 20) = 1.07 mm)
  // rests, but for the plate's rim columns, which have nothing beyond them (about 2 of every
  // 23 columns on each side)
  HeightSpanState gentle = layer_on_a_pitched_plate(20.0, 0.001, &model);
  const double held = gentle.held[0].map.material_m3();
  for (int k = 0; k < 8; ++k) {
    erode_spans(model, params, RigidVelocity{}, &gentle.held[0], &gentle.ground, &gentle.particles,
                &gentle.rng);
  }
  EXPECT_GT(gentle.held[0].map.material_m3(), 0.75 * held);
}

}  // namespace
}  // namespace repose
