// Deposit fronts and column-collapse runout on synthetic grain sets with
// known answers: rows and rings of touching grains, grains thrown ahead,
// columns spread by a known amount.

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "validation/particles/column_collapse.h"
#include "validation/particles/particle_observables.h"

namespace repose {
namespace {

constexpr double kR = 0.002;

GrainSet grains_at(const std::vector<Eigen::Vector3d>& centres, double radius = kR) {
  GrainSet g;
  g.position_m.resize(static_cast<Eigen::Index>(centres.size()), 3);
  g.radius_m = Eigen::VectorXd::Constant(static_cast<Eigen::Index>(centres.size()), radius);
  for (std::size_t k = 0; k < centres.size(); ++k) g.position_m.row(static_cast<Eigen::Index>(k)) = centres[k].transpose();
  return g;
}

// A block of touching grains on a cubic lattice: x in [x0, x0 + nx*2r), ny by nz.
std::vector<Eigen::Vector3d> block(double x0, int nx, int ny, int nz) {
  std::vector<Eigen::Vector3d> c;
  for (int i = 0; i < nx; ++i) {
    for (int j = 0; j < ny; ++j) {
      for (int k = 0; k < nz; ++k) c.emplace_back(x0 + kR + 2 * kR * i, kR + 2 * kR * j, kR + 2 * kR * k);
    }
  }
  return c;
}

TEST(DepositFront, ARowOfTouchingGrainsEndsAtTheLastGrainsEdge) {
  const GrainSet g = grains_at(block(0.0, 10, 1, 1));
  EXPECT_NEAR(deposit_front_m(g, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 4 * kR), 20 * kR, 1e-12);
  // the direction is normalised; the origin shifts the front
  EXPECT_NEAR(deposit_front_m(g, Eigen::Vector3d(0.01, 0, 0), Eigen::Vector3d(3, 0, 0), 4 * kR), 20 * kR - 0.01, 1e-12);
}

TEST(DepositFront, GrainsThrownAheadOfTheDepositAreLeftOut) {
  auto centres = block(0.0, 10, 2, 2);
  centres.emplace_back(0.2, kR, kR);  // 16 cm ahead: thrown off
  const GrainSet g = grains_at(centres);
  EXPECT_NEAR(deposit_front_m(g, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 4 * kR), 20 * kR, 1e-12);
  // a gap rule wide enough to bridge the 16 cm takes it in
  EXPECT_NEAR(deposit_front_m(g, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.3), 0.2 + kR, 1e-12);
}

TEST(DepositFront, RefusesNoGrainsAndNonPositiveGaps) {
  EXPECT_THROW(deposit_front_m(GrainSet{}, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 1.0), InputError);
  const GrainSet g = grains_at(block(0.0, 2, 1, 1));
  EXPECT_THROW(deposit_front_m(g, Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitX(), 0.0), InputError);
  EXPECT_THROW(radial_deposit_front(g, Eigen::Vector2d::Zero(), -1.0), InputError);
}

// Grains on rings of radius 2r, 4r, ... n*2r around (cx, cy), 64 per ring.
std::vector<Eigen::Vector3d> disc(double cx, double cy, int rings) {
  std::vector<Eigen::Vector3d> c = {{cx, cy, kR}};
  for (int k = 1; k <= rings; ++k) {
    for (int a = 0; a < 64; ++a) {
      const double phi = 2 * std::numbers::pi * (a + 0.5) / 64;
      c.emplace_back(cx + 2 * kR * k * std::cos(phi), cy + 2 * kR * k * std::sin(phi), kR);
    }
  }
  return c;
}

TEST(DepositFront, RadialFrontOfADiscIsItsOuterRingsEdgeInEverySector) {
  const GrainSet g = grains_at(disc(0.1, 0.05, 8));
  const RadialFront f = radial_deposit_front(g, Eigen::Vector2d(0.1, 0.05), 4 * kR, 16);
  EXPECT_EQ(f.sector_front_m.size(), 16u);
  for (double s : f.sector_front_m) EXPECT_NEAR(s, 17 * kR, 1e-12);
  EXPECT_NEAR(f.mean_m, 17 * kR, 1e-12);
  EXPECT_NEAR(f.std_m, 0.0, 1e-12);
}

TEST(DepositFront, RadialFrontSpreadShowsALopsidedDeposit) {
  auto centres = disc(0.0, 0.0, 5);
  for (int k = 6; k <= 12; ++k) centres.emplace_back(2 * kR * k, 0.001, kR);  // a finger along +x
  const RadialFront f = radial_deposit_front(grains_at(centres), Eigen::Vector2d::Zero(), 4 * kR, 16);
  EXPECT_GT(f.std_m, 0.0);
  EXPECT_GT(f.mean_m, 11 * kR);
  EXPECT_NEAR(*std::max_element(f.sector_front_m.begin(), f.sector_front_m.end()), std::hypot(24 * kR, 0.001) + kR,
              1e-12);
}

// A quarter column's deposit lies in one quadrant: measured over the whole
// circle, three quarters of the sectors are empty and the finger along +x
// weighs a quarter; over the quadrant every sector holds the quarter disc.
TEST(DepositFront, RadialFrontOverAQuadrantUsesEverySectorOfTheQuarter) {
  std::vector<Eigen::Vector3d> quarter;
  for (const Eigen::Vector3d& c : disc(0.0, 0.0, 8)) {
    if (c.x() > 0.0 && c.y() > 0.0) quarter.push_back(c);
  }
  const AzimuthRange quadrant{0.0, 0.5 * std::numbers::pi};
  const RadialFront f = radial_deposit_front(grains_at(quarter), Eigen::Vector2d::Zero(), 4 * kR, 8, quadrant);
  EXPECT_EQ(f.sector_front_m.size(), 8u);
  for (double s : f.sector_front_m) EXPECT_NEAR(s, 17 * kR, 1e-12);
  EXPECT_EQ(radial_deposit_front(grains_at(quarter), Eigen::Vector2d::Zero(), 4 * kR, 8).sector_front_m.size(), 2u);
  // a grain a hair outside the range (on a wall) counts in the nearer end sector
  quarter.emplace_back(2 * kR, -1e-9, kR);
  EXPECT_EQ(radial_deposit_front(grains_at(quarter), Eigen::Vector2d::Zero(), 4 * kR, 8, quadrant).sector_front_m.size(),
            8u);
}

TEST(DepositFront, GrainTopIsTheHighestGrainsTop) {
  const GrainSet g = grains_at(block(0.0, 2, 2, 5));
  EXPECT_NEAR(grain_top_m(g), 10 * kR, 1e-12);
  EXPECT_THROW(grain_top_m(GrainSet{}), InputError);
}

ColumnGeometry slot_geometry(double width_m) {
  ColumnGeometry c;
  c.shape = DemSpec::ColumnShape::kSlot;
  c.back_wall_x_m = 0.0;
  c.gate_x_m = width_m;
  c.width_m = width_m;
  c.gap_m = 4 * kR;
  return c;
}

TEST(ColumnCollapse, RunoutOfASpreadColumnIsTheFrontsAdvanceOverTheWidth) {
  // a column 5 grains long and 8 high becomes a layer 20 long and 2 high
  const GrainSet initial = grains_at(block(0.0, 5, 2, 8));
  const GrainSet half = grains_at(block(0.0, 10, 2, 4));
  const GrainSet final_state = grains_at(block(0.0, 20, 2, 2));
  const ColumnGeometry c = slot_geometry(10 * kR);
  const ColumnCollapse r = measure_column_collapse(c, initial, {half, final_state}, {0.1, 0.2}, 2 * kR);
  EXPECT_NEAR(r.height_initial_m, 16 * kR, 1e-12);
  EXPECT_NEAR(r.aspect_ratio, 1.6, 1e-12);
  EXPECT_NEAR(r.front_initial_m, 10 * kR, 1e-12);
  EXPECT_NEAR(r.front_final_m, 40 * kR, 1e-12);
  EXPECT_NEAR(r.runout_normalised, 3.0, 1e-12);
  EXPECT_NEAR(r.height_final_m, 4 * kR, 1e-12);
  ASSERT_EQ(r.front_m.size(), 2u);
  EXPECT_NEAR(r.front_m[0], 20 * kR, 1e-12);
  EXPECT_EQ(r.time_s[1], 0.2);
}

TEST(ColumnCollapse, AnUnmovedColumnHasNoRunout) {
  const GrainSet initial = grains_at(block(0.0, 5, 2, 8));
  const ColumnCollapse r = measure_column_collapse(slot_geometry(10 * kR), initial, {initial}, {0.0}, 2 * kR);
  EXPECT_EQ(r.runout_normalised, 0.0);
  EXPECT_THROW(measure_column_collapse(slot_geometry(10 * kR), initial, {}, {}, 2 * kR), InputError);
}

TEST(ColumnCollapse, AxisymmetricRunoutIsRadial) {
  ColumnGeometry c;
  c.shape = DemSpec::ColumnShape::kCylinder;
  c.axis_xy_m = Eigen::Vector2d(0.1, 0.1);
  c.width_m = 9 * kR;  // rings to 4*2r: edge at 9r
  const GrainSet initial = grains_at(disc(0.1, 0.1, 4));
  const GrainSet final_state = grains_at(disc(0.1, 0.1, 13));
  const ColumnCollapse r = measure_column_collapse(c, initial, {final_state}, {1.0}, 2 * kR);
  EXPECT_NEAR(r.front_initial_m, 9 * kR, 1e-12);
  EXPECT_NEAR(r.front_final_m, 27 * kR, 1e-12);
  EXPECT_NEAR(r.runout_normalised, 2.0, 1e-12);
  EXPECT_NEAR(r.front_final_spread_m, 0.0, 1e-12);
}

}  // namespace
}  // namespace repose
