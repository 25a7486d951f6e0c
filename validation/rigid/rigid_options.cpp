#include "validation/rigid/rigid_options.h"

#include <fmt/format.h>

#include "validation/particles/option_fields.h"

namespace repose {

void validate(const RigidOptions& options) {
  OptionFieldChecker checker;
  rigid_option_fields(checker, options);
  if (options.settle_check_interval_s < options.time_step_s) {
    throw FieldError("settle_check_interval_s", fmt::format("at least time_step_s ({})", yaml_number(options.time_step_s)),
                     yaml_number(options.settle_check_interval_s));
  }
}

}  // namespace repose
