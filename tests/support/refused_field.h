#pragma once
// The field an options struct's validate() names in refusing it: every
// options struct has a validate() that throws FieldError naming the field,
// and its tests ask which field one broken value trips.

#include <string>

#include "models/core/config/fields.h"

namespace repose::testing {

// The field validate(spec) names (FieldError::field), or "" when it accepts spec.
template <class Spec>
std::string refused_field(const Spec& spec) {
  try {
    validate(spec);
  } catch (const FieldError& e) {
    return e.field();
  }
  return "";
}

}  // namespace repose::testing
