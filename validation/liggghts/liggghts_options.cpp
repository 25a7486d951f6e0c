#include "validation/liggghts/liggghts_options.h"

#include "validation/particles/option_fields.h"

namespace repose {

void validate(const LiggghtsOptions& options) {
  OptionFieldChecker checker;
  liggghts_option_fields(checker, options);
}

}  // namespace repose
