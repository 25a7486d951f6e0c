#include "models/terrain/terrain_options.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "models/core/config/fields.h"

namespace repose {

namespace {

void require_positive(double value, const char* field) {
  if (!(std::isfinite(value) && value > 0.0)) throw FieldError(field, "a finite number > 0", fmt::format("{}", value));
}

}  // namespace

void TerrainOptions::validate() const {
  require_positive(contour_interval_m, "contour_interval_m");
  require_positive(smoothing_tolerance_m, "smoothing_tolerance_m");
  require_positive(sample_spacing_m, "sample_spacing_m");
  require_positive(cell_size_m, "cell_size_m");
  if (!(slope_rad > 0.0 && slope_rad < std::numbers::pi / 2)) {
    throw FieldError("slope_deg", "a number in (0, 90)", fmt::format("{}", slope_rad * 180.0 / std::numbers::pi));
  }
}

}  // namespace repose
