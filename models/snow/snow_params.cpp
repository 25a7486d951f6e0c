#include "models/snow/snow_params.h"

#include <cmath>
#include <numbers>

#include "models/core/config/fields.h"

namespace repose {

void validate(const SnowParams& params) {
  const double a = params.repose_angle_rad;
  if (!(std::isfinite(a) && a >= 0.0 && a <= std::numbers::pi / 2)) {
    throw FieldError("repose_angle_deg", "an angle in [0, 90] deg", yaml_degrees(a / kRadPerDeg));
  }
  const double s = params.direction_spread_rad;
  if (!(std::isfinite(s) && s >= 0.0 && s <= std::numbers::pi)) {
    throw FieldError("spread_deg", "an angle in [0, 180] deg", yaml_degrees(s / kRadPerDeg));
  }
  const double f = params.snowfall_scale;
  if (!(std::isfinite(f) && f > 0.0 && f <= 100.0)) throw FieldError("snowfall_scale", "a number in (0, 100]", yaml_number(f));
  const double e = params.edge_hold_m;
  if (!(std::isfinite(e) && e >= 0.0 && e <= 1.0)) throw FieldError("edge_hold_m", "a length in [0, 1] m", yaml_number(e));
}

}  // namespace repose
