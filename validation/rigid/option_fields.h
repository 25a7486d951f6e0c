#pragma once
// Visitors over an options struct's one field list (numbers and integers),
// so that one list drives reading a scene section, validate(), the allowed
// keys and the manifest copy. A field list is a function
//   template <class V> void fields(V& v, Options& o) { v.number("time_step_s", o.time_step_s, Range::...); ... }
// The range given there is the rule: the reader and validate() both check it.
// (Stands in for models/core/config/fields.h until the solver interface lands.)

#include <cstdint>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/yaml_reader.h"
#include "models/core/io/json_writer.h"

namespace repose {

// Collects the keys of a field list.
struct OptionFieldNames {
  std::vector<std::string> names;
  void number(const char* key, double&, const Range&) { names.emplace_back(key); }
  void integer(const char* key, int&, const IntRange&) { names.emplace_back(key); }
};

// Reads the keys present in a map (absent keys keep their default).
class OptionFieldReader {
 public:
  explicit OptionFieldReader(const YamlMap& map) : map_(map) {}
  void number(const char* key, double& x, const Range& r) {
    if (auto v = map_.get(key)) x = v->number(r);
  }
  void integer(const char* key, int& x, const IntRange& r) {
    if (auto v = map_.get(key)) x = static_cast<int>(v->integer(r));
  }

 private:
  const YamlMap& map_;
};

// Throws InputError "SECTION.KEY: expected RULE, got VALUE" for the first field outside its rule.
class OptionFieldChecker {
 public:
  explicit OptionFieldChecker(std::string section) : section_(std::move(section)) {}
  void number(const char* key, const double& x, const Range& r) const {
    if (!r.contains(x)) throw InputError(fmt::format("{}.{}: expected {}, got {}", section_, key, r.describe(), x));
  }
  void integer(const char* key, const int& x, const IntRange& r) const {
    if (x < r.min || x > r.max) throw InputError(fmt::format("{}.{}: expected {}, got {}", section_, key, r.describe(), x));
  }

 private:
  std::string section_;
};

// Writes every field as a JSON member (inside an open object).
class OptionFieldJson {
 public:
  explicit OptionFieldJson(JsonWriter& json) : json_(json) {}
  void number(const char* key, const double& x, const Range&) { json_.key(key).number(x); }
  void integer(const char* key, const int& x, const IntRange&) { json_.key(key).integer(x); }

 private:
  JsonWriter& json_;
};

// Writes every field as "key=value" lines, numbers round-trip exact (for cache keys).
class OptionFieldText {
 public:
  std::string text;
  void number(const char* key, const double& x, const Range&) { text += fmt::format("{}={}\n", key, x); }
  void integer(const char* key, const int& x, const IntRange&) { text += fmt::format("{}={}\n", key, x); }
};

}  // namespace repose
