#pragma once
// Visitors over an engine section's one field list (fields.h protocol) that
// fields.h does not have: a checker that makes each field's range its rule
// (so validate() and the reader share one list) and a key=value text (for
// cache keys). A field list is
//   template <class V, class O> void fields(V& v, O& o) { v.number("time_step_s", o.time_step_s, Range::...); ... }

#include <string>

#include <fmt/format.h>

#include "models/core/config/fields.h"
#include "models/core/config/yaml_reader.h"

namespace repose {

// Throws FieldError(KEY, RULE, VALUE) for the first field outside its range.
struct OptionFieldChecker {
  void number(const char* key, const double& x, const Range& r, Need = Need::kOptional) const {
    if (!r.contains(x)) throw FieldError(key, r.describe(), yaml_number(x));
  }
  void integer(const char* key, const int& x, const IntRange& r, Need = Need::kOptional) const {
    if (x < r.min || x > r.max) throw FieldError(key, r.describe(), fmt::format("{}", x));
  }
};

// Every field as "key=value" lines, numbers round-trip exact (for cache keys).
struct OptionFieldText {
  std::string text;
  void number(const char* key, const double& x, const Range&, Need = Need::kOptional) {
    text += fmt::format("{}={}\n", key, yaml_number(x));
  }
  void integer(const char* key, const int& x, const IntRange&, Need = Need::kOptional) {
    text += fmt::format("{}={}\n", key, x);
  }
};

}  // namespace repose
