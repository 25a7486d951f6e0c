#pragma once
// Visitors over an engine section's one field list (fields.h protocol) that
// fields.h does not have: a checker that makes each field's range its rule
// (so validate() and the reader share one list) and a key=value text (for
// cache keys). A field list is
//   template <class V, class O> void fields(V& v, O& o) { v.number("time_step_s", o.time_step_s, Range::...); ... }

#include <string>

#include <fmt/format.h>

#include <memory>

#include "models/core/config/fields.h"
#include "models/core/config/scene.h"
#include "models/core/config/scene_section.h"
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

// An engine's optional section (bullet:, ode:, liggghts:): a scene without
// the key, or with an empty one, keeps Section::options' defaults; keys are
// checked against `fields` and the result by validate(options), every error
// one line at its key.
template <class Section, class Fields>
std::shared_ptr<const SceneSection> read_option_section(const YamlValue& value, Fields fields) {
  auto section = std::make_shared<Section>();
  if (value.node().IsDefined() && !value.node().IsNull()) {
    const YamlMap map = value.map(field_keys<decltype(section->options)>(fields));
    read_fields_into(map, fields, section->options);
    validate_at(map, [&] { validate(section->options); });
  }
  return section;
}

// The scene's options of that section, or the defaults when it has none.
template <class Section>
auto options_of(const Scene& scene) {
  const Section* section = scene.section<Section>();
  return section != nullptr ? section->options : decltype(section->options){};
}

}  // namespace repose
