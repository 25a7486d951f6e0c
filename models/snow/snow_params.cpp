#include "models/snow/snow_params.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

void validate(const SnowParams& params) {
  const double a = params.repose_angle_rad;
  if (!(std::isfinite(a) && a >= 0.0 && a <= std::numbers::pi / 2)) {
    throw InputError(fmt::format("snow params: repose_angle_rad = {} is outside [0, pi/2]", a));
  }
  const double s = params.direction_spread_rad;
  if (!(std::isfinite(s) && s >= 0.0 && s <= std::numbers::pi)) {
    throw InputError(fmt::format("snow params: direction_spread_rad = {} is outside [0, pi]", s));
  }
}

}  // namespace repose
