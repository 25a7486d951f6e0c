#include "models/tearing/fibre_options.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "models/core/config/fields.h"

namespace repose {

namespace {

// FieldError names the key, so that the scene loader points at it.
void require(bool ok, const char* field, double value, const char* rule) {
  if (!ok) throw FieldError(field, rule, fmt::format("{}", value));
}

}  // namespace

void FibreOptions::validate() const {
  require(layers >= 1 && layers <= 8, "layers", layers, "in [1, 8] (the seed uses 3 to 5)");
  require(std::isfinite(pixel_size_m) && pixel_size_m > 0.0, "pixel_size_m", pixel_size_m, "> 0");
  require(std::isfinite(clumps_per_m2) && clumps_per_m2 >= 0.0, "clumps_per_m2", clumps_per_m2, ">= 0");
  require(std::isfinite(clump_width_min_m) && clump_width_min_m > 0.0, "clump_width_min_m", clump_width_min_m,
          "> 0");
  require(std::isfinite(clump_width_max_m) && clump_width_max_m >= clump_width_min_m, "clump_width_max_m",
          clump_width_max_m, ">= clump_width_min_m");
  require(std::isfinite(clump_length_min_m) && clump_length_min_m >= clump_width_max_m, "clump_length_min_m",
          clump_length_min_m, ">= clump_width_max_m (a clump is longer than it is wide)");
  require(std::isfinite(clump_length_max_m) && clump_length_max_m >= clump_length_min_m, "clump_length_max_m",
          clump_length_max_m, ">= clump_length_min_m");
  require(std::isfinite(grain_direction_rad), "grain_direction_deg", grain_direction_rad / kRadPerDeg, "finite");
  require(grain_spread_rad >= 0.0 && grain_spread_rad <= std::numbers::pi / 2, "grain_spread_deg",
          grain_spread_rad / kRadPerDeg, "in [0, 90] deg");
  require(background_density >= 0.0 && background_density < 1.0, "background_density", background_density,
          "in [0, 1)");
}

}  // namespace repose
