#pragma once
// One field list per options struct drives reading, writing, the allowed
// keys and the manifest copy (as Drake's Serialize(Archive*)). A field list
// is a function template over a visitor:
//
//   template <class V> void fields(V& v, DemSpec& d) {
//     v.number("grain_radius_m", d.grain_radius_m, Range::positive());
//     v.angle_deg("repose_angle_deg", d.repose_angle_rad, Range::left_open(0, 90));
//     v.choice("floor", d.floor, {{"smooth", Floor::kSmooth}, {"rough", Floor::kRough}});
//   }
//
// and the visitors below read a YAML map through it (FieldReader: absent
// optional keys keep the struct's default), list its keys (FieldNames) and
// write it back (FieldWriter: angles in degrees, numbers that read back to
// the same double). Ranges here are the file's first check; the struct's
// validate() holds the rules (validate_fields() maps its FieldError to the
// key's line and column).

#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "models/core/base/error.h"
#include "models/core/config/yaml_reader.h"

namespace repose {

inline constexpr double kRadPerDeg = std::numbers::pi / 180.0;

enum class Need { kOptional, kRequired };

// A rule of an options struct broken: thrown by validate() functions, so
// that the loader can point at the key and code that builds the struct gets
// a message naming the field.
class FieldError : public InputError {
 public:
  FieldError(std::string field, std::string expected, std::string got)
      : InputError(field + ": expected " + expected + ", got " + got),
        field_(std::move(field)), expected_(std::move(expected)), got_(std::move(got)) {}
  const std::string& field() const { return field_; }
  const std::string& expected() const { return expected_; }
  const std::string& got() const { return got_; }

 private:
  std::string field_, expected_, got_;
};

// Numbers as text: the shortest form that reads back to the same double, and
// angles in degrees to 15 digits (so that 30 deg reads 30).
inline std::string yaml_number(double x) { return fmt::format("{}", x + 0.0); }  // + 0.0: no "-0"
inline std::string yaml_degrees(double degrees) { return fmt::format("{:.15g}", degrees + 0.0); }

template <class E>
using ChoiceTable = std::vector<std::pair<std::string, E>>;

// Collects the key names of a field list.
class FieldNames {
 public:
  std::vector<std::string> names;
  void number(const char* key, double&, const Range&, Need = Need::kOptional) { names.emplace_back(key); }
  void angle_deg(const char* key, double&, const Range&, Need = Need::kOptional) { names.emplace_back(key); }
  void integer(const char* key, int&, const IntRange&, Need = Need::kOptional) { names.emplace_back(key); }
  void boolean(const char* key, bool&) { names.emplace_back(key); }
  void seed(const char* key, std::uint64_t&) { names.emplace_back(key); }
  void vec3(const char* key, Eigen::Vector3d&, const Range&) { names.emplace_back(key); }
  template <class E>
  void choice(const char* key, E&, const ChoiceTable<E>&) { names.emplace_back(key); }
};

// Reads the fields present in a map; absent optional fields keep their value.
class FieldReader {
 public:
  explicit FieldReader(const YamlMap& map) : map_(map) {}
  void number(const char* key, double& x, const Range& r, Need need = Need::kOptional) {
    if (auto v = value(key, r.describe(), need)) x = v->number(r);
  }
  void angle_deg(const char* key, double& rad, const Range& deg, Need need = Need::kOptional) {
    if (auto v = value(key, deg.describe(), need)) rad = v->number(deg) * kRadPerDeg;
  }
  void integer(const char* key, int& x, const IntRange& r, Need need = Need::kOptional) {
    if (auto v = value(key, r.describe(), need)) x = static_cast<int>(v->integer(r));
  }
  void boolean(const char* key, bool& b) {
    if (auto v = map_.get(key)) b = v->boolean();
  }
  void seed(const char* key, std::uint64_t& s) {
    if (auto v = map_.get(key)) s = v->unsigned_integer();
  }
  void vec3(const char* key, Eigen::Vector3d& x, const Range& r) {
    if (auto v = map_.get(key)) x = v->vec3(r);
  }
  template <class E>
  void choice(const char* key, E& e, const ChoiceTable<E>& table) {
    auto v = map_.get(key);
    if (!v) return;
    std::vector<std::string> words;
    for (const auto& entry : table) words.push_back(entry.first);
    e = table[v->choice(words)].second;
  }

 private:
  std::optional<YamlValue> value(const char* key, const std::string& expected, Need need) {
    return need == Need::kRequired ? std::optional<YamlValue>(map_.required(key, expected)) : map_.get(key);
  }
  const YamlMap& map_;
};

// Writes every field as a key of the current map (angles in degrees).
class FieldWriter {
 public:
  explicit FieldWriter(YAML::Emitter& out) : out_(out) {}
  void number(const char* key, double& x, const Range&, Need = Need::kOptional) {
    out_ << YAML::Key << key << YAML::Value << yaml_number(x);
  }
  void angle_deg(const char* key, double& rad, const Range&, Need = Need::kOptional) {
    out_ << YAML::Key << key << YAML::Value << yaml_degrees(rad / kRadPerDeg);
  }
  void integer(const char* key, int& x, const IntRange&, Need = Need::kOptional) {
    out_ << YAML::Key << key << YAML::Value << x;
  }
  void boolean(const char* key, bool& b) { out_ << YAML::Key << key << YAML::Value << b; }
  void seed(const char* key, std::uint64_t& s) { out_ << YAML::Key << key << YAML::Value << s; }
  void vec3(const char* key, Eigen::Vector3d& x, const Range&) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << yaml_number(x[0])
         << yaml_number(x[1]) << yaml_number(x[2]) << YAML::EndSeq;
  }
  template <class E>
  void choice(const char* key, E& e, const ChoiceTable<E>& table) {
    for (const auto& [word, value] : table) {
      if (value == e) out_ << YAML::Key << key << YAML::Value << word;
    }
  }

 private:
  YAML::Emitter& out_;
};

// The keys of a field list, after `extra` keys read by hand.
template <class Spec, class Fields>
std::vector<std::string> field_keys(Fields fields, std::vector<std::string> extra = {}) {
  FieldNames names;
  Spec spec;
  fields(names, spec);
  extra.insert(extra.end(), names.names.begin(), names.names.end());
  return extra;
}

// Reads the fields of `map` into `spec` (absent keys keep spec's values).
template <class Spec, class Fields>
void read_fields_into(const YamlMap& map, Fields fields, Spec& spec) {
  FieldReader reader(map);
  fields(reader, spec);
}

// Writes `spec` as one YAML map.
template <class Spec, class Fields>
void write_fields_map(YAML::Emitter& out, Spec spec, Fields fields) {
  out << YAML::BeginMap;
  FieldWriter writer(out);
  fields(writer, spec);
  out << YAML::EndMap;
}

// Runs a validate() and turns its FieldError into the one-line error at the
// field's key in `map` (or at the map, when the key is absent and its
// default broke the rule).
template <class Validate>
void validate_at(const YamlMap& map, Validate validate) {
  try {
    validate();
  } catch (const FieldError& e) {
    if (auto at = map.get(e.field())) at->fail(e.expected(), e.got());
    map.fail_missing(e.field(), e.expected());
  }
}

}  // namespace repose
