// A series compared with the reference's seeds: its relative error, and with
// beds: each the standard error of that error the finite number of beds
// leaves, from each bed's own error (the solver paired with the seed on that
// seed's bed). Hand-made numbers.
#include "validation/calibration/series_comparison.h"

#include <cmath>

#include <gtest/gtest.h>

namespace repose {
namespace {

// Three beds, two times; the reference (the seeds' mean) 12 and 0 (the bucket emptied).
SeriesComparison three_beds() {
  SeriesComparison c;
  c.times_s = {1.0, 2.0};
  c.seeds = {{10.0, 0.0}, {12.0, 0.0}, {14.0, 0.0}};
  c.reference = {12.0, 0.0};
  c.fitted_per_bed = {{11.0, 0.0}, {12.0, 0.0}, {16.0, 0.0}};
  c.fitted = {13.0, 0.0};  // the beds' mean
  c.initial = c.fitted;
  return c;
}

TEST(SeriesComparison, ThePairedStandardErrorIsTheSpreadOfEachBedsOwnErrorOverRootBeds) {
  const SeriesComparison c = three_beds();
  // each bed's own error: (1, 0, 2) / 12, whose mean is the series' error
  EXPECT_DOUBLE_EQ(c.fitted_relative_error()[0], 1.0 / 12.0);
  const std::vector<double> se = c.paired_standard_error();
  ASSERT_EQ(se.size(), 2u);
  EXPECT_NEAR(se[0], (1.0 / 12.0) / std::sqrt(3.0), 1e-15);  // sample sd 1/12
  EXPECT_TRUE(std::isnan(se[1])) << "no relative error where the reference is 0";
}

TEST(SeriesComparison, ASolverThatMissesEveryBedByTheSameAmountHasNoPairedError) {
  SeriesComparison c = three_beds();
  c.fitted_per_bed = {{11.5, 0.0}, {13.5, 0.0}, {15.5, 0.0}};  // each seed + 1.5
  c.fitted = {13.5, 0.0};
  EXPECT_DOUBLE_EQ(c.fitted_relative_error()[0], 1.5 / 12.0);
  EXPECT_NEAR(c.paired_standard_error()[0], 0.0, 1e-15);
  // ... where the seeds' own spread (sd 2 of 12) would count if unpaired
}

TEST(SeriesComparison, WithoutBedsOrWithOneThereIsNoPairedError) {
  SeriesComparison c = three_beds();
  c.fitted_per_bed.clear();
  EXPECT_TRUE(c.paired_standard_error().empty());
  c.seeds = {{12.0, 0.0}};
  c.fitted_per_bed = {{13.0, 0.0}};
  EXPECT_TRUE(c.paired_standard_error().empty());
}

}  // namespace
}  // namespace repose
