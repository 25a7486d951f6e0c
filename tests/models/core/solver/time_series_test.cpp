#include "models/core/solver/time_series.h"

#include <gtest/gtest.h>

#include "models/core/base/error.h"

namespace repose {
namespace {

TEST(TimeSeries, InterpolatesLinearlyAndHoldsOutsideItsTimes) {
  const TimeSeries s{"kg", {0.1, 0.2, 0.4}, {1.0, 3.0, -1.0}};
  EXPECT_EQ(s.at(0.1), 1.0);
  EXPECT_DOUBLE_EQ(s.at(0.15), 2.0);
  EXPECT_EQ(s.at(0.2), 3.0);
  EXPECT_DOUBLE_EQ(s.at(0.3), 1.0);
  EXPECT_EQ(s.at(0.0), 1.0);   // before the first sample: the first value
  EXPECT_EQ(s.at(9.0), -1.0);  // after the last: the last
  const TimeSeries one{"kg", {0.5}, {2.0}};
  EXPECT_EQ(one.at(0.0), 2.0);
  EXPECT_EQ(one.at(1.0), 2.0);
}

TEST(TimeSeries, RefusesAnEmptyOrRaggedSeries) {
  EXPECT_THROW(TimeSeries{}.at(0.0), InputError);
  const TimeSeries ragged{"kg", {0.0, 1.0}, {1.0}};
  EXPECT_THROW(ragged.at(0.5), InputError);
}

}  // namespace
}  // namespace repose
