#include "models/snow/snow_options.h"

#include <cmath>
#include <set>

#include <fmt/format.h>

#include "models/core/config/fields.h"

namespace repose {

namespace {

void validate_groups(const std::vector<SnowGroupSpec>& groups) {
  if (groups.empty()) throw FieldError("groups", "at least one group (the ground is one)", "none");
  std::set<std::string> names;
  int grounds = 0;
  for (std::size_t k = 0; k < groups.size(); ++k) {
    const SnowGroupSpec& g = groups[k];
    const std::string at = fmt::format("groups[{}]", k);
    if (g.name.empty()) throw FieldError("groups", at + " with a name", "an empty name");
    if (!names.insert(g.name).second) throw FieldError("groups", "unique group names", "'" + g.name + "' twice");
    if (g.ground) {
      ++grounds;
      if (!g.objects.empty()) throw FieldError("groups", at + " ('" + g.name + "', the ground) without objects", "objects");
    } else if (g.objects.empty()) {
      throw FieldError("groups", at + " ('" + g.name + "') with objects, or ground: true", "no objects");
    }
  }
  if (grounds > 1) throw FieldError("groups", "at most one ground group", std::to_string(grounds));
}

void require(bool ok, const char* key, const char* expected, const std::string& got) {
  if (!ok) throw FieldError(key, expected, got);
}

}  // namespace

void validate(const SnowOptions& o) {
  validate_groups(o.groups);
  const double tilt = o.main_direction.tilt_rad;
  require(std::isfinite(tilt) && tilt >= 0.0 && tilt <= kMaxFallTiltRad, "direction_tilt_deg",
          "an angle in [0, 85] deg (snow must come from above)", yaml_degrees(tilt / kRadPerDeg));
  require(std::isfinite(o.main_direction.azimuth_rad), "direction_azimuth_deg", "a finite angle",
          yaml_degrees(o.main_direction.azimuth_rad / kRadPerDeg));
  require(o.direction_count >= 1 && o.direction_count <= 65536, "direction_count", "an integer in [1, 65536]",
          std::to_string(o.direction_count));
  require(std::isfinite(o.cell_size_m) && o.cell_size_m >= 0.0, "cell_size_m", "a length >= 0 m (0: the ground's)",
          yaml_number(o.cell_size_m));
  require(o.shadow_oversampling >= 1 && o.shadow_oversampling <= 16, "shadow_oversampling", "an integer in [1, 16]",
          std::to_string(o.shadow_oversampling));
  require(std::isfinite(o.shadow_bias_cells) && o.shadow_bias_cells >= 0.0 && o.shadow_bias_cells <= 16.0,
          "shadow_bias_cells", "a number in [0, 16]", yaml_number(o.shadow_bias_cells));
  require(o.moved_fraction > 0.0 && o.moved_fraction <= kSnowMovedFractionMax, "moved_fraction",
          "a number in (0, 0.25] (stabilisation diverges above 1/4, see stabilisation.h)",
          yaml_number(o.moved_fraction));
  require(o.max_stabilisation_passes >= 1 && o.max_stabilisation_passes <= 1000000, "max_stabilisation_passes",
          "an integer in [1, 1e6]", std::to_string(o.max_stabilisation_passes));
  require(std::isfinite(o.settle_tolerance_m) && o.settle_tolerance_m > 0.0, "settle_tolerance_m",
          "a length > 0 m", yaml_number(o.settle_tolerance_m));
  validate(o.pictures);
}

}  // namespace repose
