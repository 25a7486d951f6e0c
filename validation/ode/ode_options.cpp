#include "validation/ode/ode_options.h"

#include "validation/rigid/option_fields.h"

namespace repose {

void validate(const OdeOptions& options) {
  validate(options.rigid, "ode");
  OptionFieldChecker checker("ode");
  ode_option_fields(checker, options);
}

OdeOptions read_ode_options(const YamlValue& section) {
  OptionFieldNames names;
  OdeOptions options;
  ode_option_fields(names, options);
  const YamlMap map = section.map(names.names);
  OptionFieldReader reader(map);
  ode_option_fields(reader, options);
  validate(options);
  return options;
}

std::string ode_options_text(const OdeOptions& options) {
  OptionFieldText text;
  ode_option_fields(text, options);
  return text.text;
}

}  // namespace repose
