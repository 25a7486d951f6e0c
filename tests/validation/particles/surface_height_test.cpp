#include "validation/particles/surface_height.h"

#include <cmath>

#include <gtest/gtest.h>

namespace repose {
namespace {

// n x n touching equal spheres (radius r, spacing 2r) with centres at height z0.
GrainSet square_lattice(int n, double r, double z0) {
  GrainSet grains;
  grains.position_m.resize(n * n, 3);
  grains.radius_m = Eigen::VectorXd::Constant(n * n, r);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < n; ++b) grains.position_m.row(a * n + b) << (2 * a + 1) * r, (2 * b + 1) * r, z0;
  }
  return grains;
}

// A square lattice of touching equal spheres (radius r, spacing 2r) with
// centres at height z0. The surface at (x, y) is z0 + sqrt(r^2 - d^2), d the
// horizontal distance to the nearest centre, where d < r.
TEST(SurfaceHeight, MatchesAnAnalyticLatticeOfSpheres) {
  const double r = 0.002, z0 = 0.01;
  const int n = 8;
  const GrainSet grains = square_lattice(n, r, z0);
  // cells of r/3 over the lattice's square footprint
  const Grid grid{n * 6, n * 6, r / 3, 0.0, 0.0};
  const HeightField h = surface_height(grains, grid);
  int covered = 0, gaps = 0;
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      const double x = grid.centre_x(i), y = grid.centre_y(j);
      const double cx = (2 * std::floor(x / (2 * r)) + 1) * r, cy = (2 * std::floor(y / (2 * r)) + 1) * r;
      const double d2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
      if (d2 < r * r) {
        EXPECT_NEAR(h.at(i, j), z0 + std::sqrt(r * r - d2), 1e-12) << i << "," << j;
        ++covered;
      } else {
        // gaps between four spheres: below the covered neighbours, above the centres' plane
        EXPECT_GT(h.at(i, j), z0) << i << "," << j;
        EXPECT_LT(h.at(i, j), z0 + r) << i << "," << j;
        ++gaps;
      }
    }
  }
  EXPECT_GT(covered, 0);
  EXPECT_GT(gaps, 0);
  // the top of each sphere is seen at the cell nearest its centre
  EXPECT_NEAR(h.max_height_m(), z0 + std::sqrt(r * r - 2 * (r / 6) * (r / 6)), 1e-12);
}

// The probe surface of the same lattice: a probe of radius p lowered at
// (x, y) stops on the nearest grain, at z0 + sqrt((r + p)^2 - d^2) - p, with
// d now up to r*sqrt(2) (the centre of a gap) for p >= (sqrt(2) - 1) r, so
// every cell is covered and the surface dips less between grains than the
// grains' own tops do.
TEST(SurfaceHeight, ProbeSurfaceOfALatticeIsAnalyticAndBridgesTheGaps) {
  const double r = 0.002, z0 = 0.01, p = r;
  const int n = 8;
  const GrainSet grains = square_lattice(n, r, z0);
  const Grid grid{n * 6, n * 6, r / 3, 0.0, 0.0};
  SurfaceHeightOptions probe;
  probe.probe_radius_m = p;
  const HeightField h = surface_height(grains, grid, probe);
  const HeightField tops = surface_height(grains, grid);
  const double R = r + p;
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      const double x = grid.centre_x(i), y = grid.centre_y(j);
      const double cx = (2 * std::floor(x / (2 * r)) + 1) * r, cy = (2 * std::floor(y / (2 * r)) + 1) * r;
      const double d2 = (x - cx) * (x - cx) + (y - cy) * (y - cy);
      EXPECT_NEAR(h.at(i, j), z0 + std::sqrt(R * R - d2) - p, 1e-12) << i << "," << j;
      EXPECT_LE(h.at(i, j), z0 + r + 1e-12);
    }
  }
  // over the lattice, the probe surface varies less than the grains' tops
  const auto spread = [](const HeightField& f) { return f.max_height_m() - f.heights().minCoeff(); };
  EXPECT_LT(spread(h), 0.6 * spread(tops));
  // probe radius 0 is the grains' tops exactly
  probe.probe_radius_m = 0.0;
  EXPECT_TRUE((surface_height(grains, grid, probe).heights() == tops.heights()).all());
}

TEST(SurfaceHeight, BareFloorIsZeroAndTheHighestGrainWins) {
  const Grid grid{10, 10, 0.001, 0.0, 0.0};
  GrainSet grains;
  grains.position_m.resize(2, 3);
  grains.position_m << 0.0025, 0.0025, 0.003, 0.0025, 0.0025, 0.004;  // stacked
  grains.radius_m = Eigen::VectorXd::Constant(2, 0.0008);
  const HeightField h = surface_height(grains, grid);
  EXPECT_DOUBLE_EQ(h.at(2, 2), 0.004 + std::sqrt(0.0008 * 0.0008));
  EXPECT_EQ(h.at(8, 8), 0.0);  // far from every grain
  EXPECT_EQ(h.at(2, 4), 0.0);  // centre 2 mm away: uncovered, too few covered neighbours for a gap
}

// An odd number of samples per axis includes the centre, so it is never
// lower than the centre alone, and nearer a grain's top.
TEST(SurfaceHeight, SubsamplingTakesTheHighestPointInTheCell) {
  const Grid grid{6, 6, 0.002, 0.0, 0.0};
  GrainSet grains;
  grains.position_m.resize(3, 3);
  grains.position_m << 0.004, 0.004, 0.003, 0.0051, 0.0083, 0.002, 0.009, 0.003, 0.001;
  grains.radius_m = Eigen::VectorXd::Constant(3, 0.0015);
  SurfaceHeightOptions o;
  o.gap_covered_fraction = 2.0;  // no gap filling: uncovered cells are 0
  const HeightField one = surface_height(grains, grid, o);
  o.samples_per_axis = 3;
  const HeightField three = surface_height(grains, grid, o);
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      if (one.at(i, j) > 0) {
        EXPECT_GE(three.at(i, j), one.at(i, j) - 1e-15) << i << "," << j;
      }
    }
  }
  // the first grain's centre is a corner shared by 4 cells: each sees a point
  // h/6 * sqrt(2) from it with 3 samples per axis, only h/2 * sqrt(2) with 1
  const double r = 0.0015, near = 0.002 / 6 * std::sqrt(2.0), far = 0.002 / 2 * std::sqrt(2.0);
  EXPECT_NEAR(three.at(1, 1), 0.003 + std::sqrt(r * r - near * near), 1e-12);
  EXPECT_NEAR(one.at(1, 1), 0.003 + std::sqrt(r * r - far * far), 1e-12);
}

}  // namespace
}  // namespace repose
