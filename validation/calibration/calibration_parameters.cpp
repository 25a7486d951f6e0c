#include "validation/calibration/calibration_parameters.h"

#include <algorithm>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

void resolve_parameter(ParameterSpec& param, const ParameterInfo& info) {
  param.unit = info.unit;
  param.si_per_unit = info.si_per_unit;
  const double allowed_lower = info.lower_si / info.si_per_unit, allowed_upper = info.upper_si / info.si_per_unit;
  const double lower = param.file_lower.value_or(allowed_lower), upper = param.file_upper.value_or(allowed_upper);
  if (lower < allowed_lower || upper > allowed_upper) {
    throw InputError(fmt::format("{}: parameters: {}: bounds [{}, {}] {} reach outside the solver's interval [{}, {}]",
                                 param.location, param.label(), lower, upper, info.unit, allowed_lower, allowed_upper));
  }
  if (param.file_initial < lower || param.file_initial > upper) {
    throw InputError(fmt::format("{}: parameters: {}: initial {} {} is outside the bounds [{}, {}]", param.location,
                                 param.label(), param.file_initial, info.unit, lower, upper));
  }
  const double step = std::min(param.file_step.value_or(0.05 * (upper - lower)), 0.5 * (upper - lower));
  param.initial = param.file_initial * info.si_per_unit;
  param.lower = lower * info.si_per_unit;
  param.upper = upper * info.si_per_unit;
  param.step = step * info.si_per_unit;
}

}  // namespace repose
