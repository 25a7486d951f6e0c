#include "validation/bullet/bullet_options.h"

#include "validation/rigid/option_fields.h"

namespace repose {

void validate(const BulletOptions& options) {
  validate(options.rigid, "bullet");
  OptionFieldChecker checker("bullet");
  bullet_option_fields(checker, options);
}

BulletOptions read_bullet_options(const YamlValue& section) {
  OptionFieldNames names;
  BulletOptions options;
  bullet_option_fields(names, options);
  const YamlMap map = section.map(names.names);
  OptionFieldReader reader(map);
  bullet_option_fields(reader, options);
  validate(options);
  return options;
}

std::string bullet_options_text(const BulletOptions& options) {
  OptionFieldText text;
  bullet_option_fields(text, options);
  return text.text;
}

}  // namespace repose
