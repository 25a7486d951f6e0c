#include "validation/ode/ode_options.h"

#include "validation/particles/option_fields.h"

namespace repose {

void validate(const OdeOptions& options) {
  validate(options.rigid);
  OptionFieldChecker checker;
  ode_option_fields(checker, options);
}

std::string ode_options_text(const OdeOptions& options) {
  OptionFieldText text;
  ode_option_fields(text, options);
  return text.text;
}

}  // namespace repose
