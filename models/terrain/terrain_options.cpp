#include "models/terrain/terrain_options.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

void require_positive(double value, const char* field) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(fmt::format("terrain: {} = {} must be finite and > 0", field, value));
  }
}

}  // namespace

void TerrainOptions::validate() const {
  require_positive(contour_interval_m, "contour_interval_m");
  require_positive(smoothing_tolerance_m, "smoothing_tolerance_m");
  require_positive(sample_spacing_m, "sample_spacing_m");
  require_positive(cell_size_m, "cell_size_m");
  if (!(slope_rad > 0.0 && slope_rad < std::numbers::pi / 2)) {
    throw InputError(fmt::format("terrain: slope_rad = {} must lie in (0, pi/2) (slope_deg in (0, 90))", slope_rad));
  }
}

}  // namespace repose
