#include "validation/observables/heap_flank.h"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "models/core/base/error.h"

namespace repose {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
const Grid kGrid{120, 100, 0.0025, 0.0, 0.0};  // 30 x 25 cm of 2.5 mm cells, as the scoop's

// A bed at bed_m with a cone of the given flank angle and height whose apex
// stands over (x0, y0).
HeightField cone(double x0, double y0, double angle_deg, double height_m, double bed_m = 0.025) {
  HeightField f(kGrid, bed_m);
  for (int j = 0; j < kGrid.ny; ++j) {
    for (int i = 0; i < kGrid.nx; ++i) {
      const double r = std::hypot(kGrid.centre_x(i) - x0, kGrid.centre_y(j) - y0);
      f.at(i, j) += std::max(0.0, height_m - std::tan(angle_deg * kDeg) * r);
    }
  }
  return f;
}

HeapFlankOptions on_bed(double bed_m = 0.025) {
  HeapFlankOptions o;
  o.base_height_m = bed_m;
  return o;
}

TEST(HeapFlank, AnAnalyticConeGivesItsAngleOnEveryRay) {
  // apex on a cell centre; each cone 8 cm in radius, so its 20-80 % band
  // spans 2 cm (8 cells) of flank within the 10 cm reach. Bilinear samples of
  // a cone's curved cells bias off-axis rays by up to ~1 % of the angle.
  for (const double angle : {10.0, 17.5, 23.5, 35.0}) {
    const double height = std::tan(angle * kDeg) * 0.08;
    const HeightField h = cone(kGrid.centre_x(60), kGrid.centre_y(50), angle, height);
    const HeapFlank f = heap_flank(h, on_bed());
    ASSERT_EQ(f.angle_rad.size(), 16u) << angle;
    for (const double a : f.angle_rad) EXPECT_NEAR(a / kDeg, angle, 0.01 * angle) << angle;
    EXPECT_NEAR(f.mean_rad / kDeg, angle, 0.005 * angle) << angle;
    // the median lowers the apex to its 4-neighbours' height
    EXPECT_NEAR(f.peak_height_m, height - std::tan(angle * kDeg) * kGrid.cell_size_m, 1e-12);
  }
}

TEST(HeapFlank, HeightsAreTakenAboveTheBase) {
  // the same cone on a deeper bed measured above that bed gives the same angle;
  // above a base 1 cm lower the flank band moves down onto the flat bed's edge
  const HeightField h = cone(0.15, 0.125, 20.0, 0.02, 0.035);
  EXPECT_NEAR(heap_flank(h, on_bed(0.035)).mean_rad / kDeg, 20.0, 0.2);
  EXPECT_LT(heap_flank(h, on_bed(0.025)).mean_rad / kDeg, 19.0);
}

TEST(HeapFlank, AOneCellSpikeIsNotTakenForThePeak) {
  HeightField h = cone(0.15, 0.125, 20.0, 0.02);
  h.at(20, 20) += 0.06;  // three times the heap's height, in one cell
  const HeapFlank f = heap_flank(h, on_bed());
  EXPECT_NEAR(f.mean_rad / kDeg, 20.0, 0.2);
  EXPECT_LT(f.peak_height_m, 0.02);
}

TEST(HeapFlank, ThePeakIsLookedForInItsRegionOnly) {
  HeightField h = cone(0.06, 0.125, 30.0, 0.03);
  const HeightField second = cone(0.22, 0.125, 15.0, 0.012, 0.0);
  h.heights() += second.heights();
  HeapFlankOptions o = on_bed();
  EXPECT_NEAR(heap_flank(h, o).mean_rad / kDeg, 30.0, 0.3);  // the higher cone
  o.peak_region = CalibrationRegion{0.15, 0.30, 0.0, 0.25};
  EXPECT_NEAR(heap_flank(h, o).mean_rad / kDeg, 15.0, 0.3);
}

TEST(HeapFlank, RaysStopAtTheirReachAndAtTheGridsEdge) {
  // a wide 10 deg cone (base radius 11.3 cm): a 3 cm reach sees only its top,
  // below the band's lower edge at 80 % no sample: no flank
  const HeightField h = cone(0.15, 0.125, 10.0, 0.02);
  HeapFlankOptions o = on_bed();
  o.reach_m = 0.003;
  EXPECT_TRUE(heap_flank(h, o).angle_rad.empty());
  EXPECT_EQ(heap_flank(h, o).mean_rad, 0.0);
  // apex two cells from the edge: the rays towards it stop there, leaving fewer than 3 samples
  const HeightField edge = cone(kGrid.centre_x(2), kGrid.centre_y(50), 30.0, 0.02);
  const HeapFlank f = heap_flank(edge, on_bed());
  EXPECT_GT(f.angle_rad.size(), 8u);
  EXPECT_LT(f.angle_rad.size(), 16u);
  EXPECT_NEAR(f.mean_rad / kDeg, 30.0, 0.6);
}

TEST(HeapFlank, AFlatBedHasNoFlank) {
  const HeapFlank f = heap_flank(HeightField(kGrid, 0.025), on_bed());
  EXPECT_TRUE(f.angle_rad.empty());
  EXPECT_EQ(f.mean_rad, 0.0);
}

TEST(HeapFlank, MedianKeepsAPlaneAndDropsASpike) {
  HeightField h(kGrid);
  for (int j = 0; j < kGrid.ny; ++j) {
    for (int i = 0; i < kGrid.nx; ++i) h.at(i, j) = 0.001 * i - 0.0005 * j;
  }
  const HeightField m = median3(h);
  for (int j = 1; j + 1 < kGrid.ny; ++j) {
    for (int i = 1; i + 1 < kGrid.nx; ++i) ASSERT_NEAR(m.at(i, j), h.at(i, j), 1e-15);
  }
  // a corner cell: the mean of the middle two of its four
  EXPECT_NEAR(m.at(0, 0), 0.5 * (0.001 - 0.0005), 1e-15);
  HeightField spike(kGrid, 0.0);
  spike.at(40, 40) = 1.0;
  EXPECT_EQ(median3(spike).heights().maxCoeff(), 0.0);
}

TEST(HeapFlank, OptionsNameTheirBadField) {
  const HeightField h(kGrid, 0.0);
  HeapFlankOptions o;
  o.reach_m = 0.0;
  EXPECT_THROW(
      {
        try {
          heap_flank(h, o);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("reach_m"), std::string::npos);
          throw;
        }
      },
      InputError);
  o = HeapFlankOptions{};
  o.lower_fraction = 0.9;
  EXPECT_THROW(o.validate(), InputError);
  o = HeapFlankOptions{};
  o.peak_region = CalibrationRegion{1.0, 2.0, 1.0, 2.0};  // off the grid
  EXPECT_THROW(heap_flank(h, o), InputError);
}

}  // namespace
}  // namespace repose
