#include "validation/rigid/rigid_options.h"

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/rigid/option_fields.h"

namespace repose {

void validate(const RigidOptions& options, const std::string& section) {
  OptionFieldChecker checker(section);
  rigid_option_fields(checker, options);
  if (options.settle_check_interval_s < options.time_step_s) {
    throw InputError(fmt::format("{}.settle_check_interval_s: expected at least time_step_s ({}), got {}", section,
                                 options.time_step_s, options.settle_check_interval_s));
  }
}

}  // namespace repose
