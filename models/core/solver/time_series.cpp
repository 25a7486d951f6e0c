#include "models/core/solver/time_series.h"

#include <algorithm>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

double TimeSeries::at(double t) const {
  if (time_s.empty() || time_s.size() != value.size()) {
    throw InputError(fmt::format("time series: {} times and {} values; expected the same, at least one", time_s.size(),
                                 value.size()));
  }
  if (t <= time_s.front()) return value.front();
  if (t >= time_s.back()) return value.back();
  const std::size_t k = static_cast<std::size_t>(std::upper_bound(time_s.begin(), time_s.end(), t) - time_s.begin());
  const double t0 = time_s[k - 1], t1 = time_s[k];
  const double a = t1 > t0 ? (t - t0) / (t1 - t0) : 1.0;
  return (1.0 - a) * value[k - 1] + a * value[k];
}

}  // namespace repose
