#include "models/snow/snow_options.h"

#include <cmath>
#include <set>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

void require(bool ok, const std::string& field, double value, const char* rule) {
  if (ok) return;
  throw InputError(fmt::format("snow options: {} = {} is outside {}", field, value, rule));
}

void validate_groups(const std::vector<SnowGroupSpec>& groups) {
  if (groups.empty()) throw InputError("snow options: groups is empty; name at least one group (the ground is one)");
  std::set<std::string> names;
  int grounds = 0;
  for (std::size_t k = 0; k < groups.size(); ++k) {
    const SnowGroupSpec& g = groups[k];
    if (g.name.empty()) throw InputError(fmt::format("snow options: groups[{}].name is empty", k));
    if (!names.insert(g.name).second) {
      throw InputError(fmt::format("snow options: groups[{}].name '{}' is used twice", k, g.name));
    }
    if (g.ground) {
      ++grounds;
      if (!g.objects.empty()) {
        throw InputError(fmt::format("snow options: groups[{}] ('{}') is the ground and cannot list objects", k, g.name));
      }
    } else if (g.objects.empty()) {
      throw InputError(fmt::format("snow options: groups[{}] ('{}') lists no objects", k, g.name));
    }
  }
  if (grounds > 1) throw InputError("snow options: more than one group is the ground");
}

}  // namespace

void validate(const SnowOptions& o) {
  validate_groups(o.groups);
  const double tilt = o.main_direction.tilt_rad;
  require(std::isfinite(tilt) && tilt >= 0.0 && tilt <= kMaxFallTiltRad, "main_direction.tilt_rad", tilt,
          "[0, 85 deg] (snow must come from above)");
  require(std::isfinite(o.main_direction.azimuth_rad), "main_direction.azimuth_rad", o.main_direction.azimuth_rad,
          "the finite numbers");
  require(o.direction_count >= 1 && o.direction_count <= 65536, "direction_count", o.direction_count, "[1, 65536]");
  require(std::isfinite(o.cell_size_m) && o.cell_size_m >= 0.0, "cell_size_m", o.cell_size_m,
          "[0, inf) (0: the ground's)");
  require(o.shadow_oversampling >= 1 && o.shadow_oversampling <= 16, "shadow_oversampling", o.shadow_oversampling,
          "[1, 16]");
  require(std::isfinite(o.shadow_bias_cells) && o.shadow_bias_cells >= 0.0 && o.shadow_bias_cells <= 16.0,
          "shadow_bias_cells", o.shadow_bias_cells, "[0, 16]");
  require(o.moved_fraction > 0.0 && o.moved_fraction <= kSnowMovedFractionMax, "moved_fraction", o.moved_fraction,
          "(0, 0.25] (stabilisation diverges above 1/4, see stabilisation.h)");
  require(o.max_stabilisation_passes >= 1 && o.max_stabilisation_passes <= 1000000, "max_stabilisation_passes",
          o.max_stabilisation_passes, "[1, 1e6]");
  require(std::isfinite(o.settle_tolerance_m) && o.settle_tolerance_m > 0.0, "settle_tolerance_m",
          o.settle_tolerance_m, "(0, inf)");
}

}  // namespace repose
