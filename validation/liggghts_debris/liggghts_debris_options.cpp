#include "validation/liggghts_debris/liggghts_debris_options.h"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

void demand_positive(double value, const char* field) {
  if (!(value > 0.0 && std::isfinite(value))) {
    throw InputError(fmt::format("liggghts debris: {} = {} must be > 0", field, value));
  }
}

}  // namespace

void LiggghtsDebrisOptions::validate() const {
  demand_positive(youngs_modulus_pa, "youngs_modulus_pa");
  if (!(poisson_ratio > 0.0 && poisson_ratio < 0.5)) {
    throw InputError(fmt::format("liggghts debris: poisson_ratio = {} must lie in (0, 0.5)", poisson_ratio));
  }
  demand_positive(time_step_s, "time_step_s");
  if (!(frame_interval_s >= 0.0 && std::isfinite(frame_interval_s))) {
    throw InputError(fmt::format("liggghts debris: frame_interval_s = {} must be >= 0", frame_interval_s));
  }
  demand_positive(force_interval_s, "force_interval_s");
  demand_positive(box_margin_m, "box_margin_m");
  demand_positive(box_top_margin_m, "box_top_margin_m");
  demand_positive(neighbor_skin_radii, "neighbor_skin_radii");
  if (!(front_quantile > 0.0 && front_quantile <= 1.0)) {
    throw InputError(fmt::format("liggghts debris: front_quantile = {} must lie in (0, 1]", front_quantile));
  }
}

}  // namespace repose
