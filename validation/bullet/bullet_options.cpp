#include "validation/bullet/bullet_options.h"

#include "validation/particles/option_fields.h"

namespace repose {

void validate(const BulletOptions& options) {
  validate(options.rigid);
  OptionFieldChecker checker;
  bullet_option_fields(checker, options);
}

std::string bullet_options_text(const BulletOptions& options) {
  OptionFieldText text;
  bullet_option_fields(text, options);
  return text.text;
}

}  // namespace repose
