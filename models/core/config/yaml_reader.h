#pragma once
// A strict reader over yaml-cpp nodes. Every value knows the file it came
// from and its key path (`objects[0].motion[1].time_s`), so that every error
// is one line a user can act on:
//
//   FILE:LINE:COL: KEY.PATH: expected WHAT, got WHAT
//
// A map is read through the list of its allowed keys: a key outside the list
// is an error naming the allowed ones, a duplicated key too. A missing
// required key is reported at the map that lacks it. Errors throw InputError.

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <yaml-cpp/yaml.h>

#include "models/core/io/input_file.h"

namespace repose {

// The allowed interval of a number; infinite bounds mean unbounded. A number
// must always be finite.
struct Range {
  double min = -std::numeric_limits<double>::infinity();
  double max = std::numeric_limits<double>::infinity();
  bool min_inclusive = true;
  bool max_inclusive = true;

  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), false, true}; }
  static Range non_negative() { return {0.0, std::numeric_limits<double>::infinity(), true, true}; }
  static Range closed(double a, double b) { return {a, b, true, true}; }
  static Range left_open(double a, double b) { return {a, b, false, true}; }   // (a, b]
  static Range right_open(double a, double b) { return {a, b, true, false}; }  // [a, b)
  static Range open(double a, double b) { return {a, b, false, false}; }

  bool contains(double x) const;
  // "a finite number > 0", "a finite number in (0, 90]", ...
  std::string describe() const;
};

// [min, max] for integers.
struct IntRange {
  std::int64_t min = std::numeric_limits<std::int64_t>::min();
  std::int64_t max = std::numeric_limits<std::int64_t>::max();
  std::string describe() const;  // "an integer >= 1", "an integer in [1, 16384]"
};

// The one-line message, without throwing (for tests and wrappers).
std::string yaml_error_message(const std::string& file, const YAML::Mark& mark, const std::string& key_path,
                               const std::string& expected, const std::string& got);

class YamlMap;

// One node of a document with its file and key path.
class YamlValue {
 public:
  YamlValue(std::string file, YAML::Node node, std::string path);

  const YAML::Node& node() const { return node_; }
  const std::string& path() const { return path_; }
  const std::string& file() const { return file_; }
  // path for messages: the root document is "scene"
  std::string display_path() const { return path_.empty() ? "scene" : path_; }

  bool is_map() const { return node_.IsMap(); }
  bool is_list() const { return node_.IsSequence(); }
  bool is_scalar() const { return node_.IsScalar(); }

  // How this value reads in a message: its text for a scalar, "a map", ...
  std::string describe_got() const;
  [[noreturn]] void fail(const std::string& expected) const;                        // got: describe_got()
  [[noreturn]] void fail(const std::string& expected, const std::string& got) const;

  double number(const Range& range) const;
  std::int64_t integer(const IntRange& range) const;
  std::uint64_t unsigned_integer() const;
  bool boolean() const;
  std::string string() const;  // a non-empty scalar
  // One of a fixed set of words; returns the index into `words`.
  std::size_t choice(const std::vector<std::string>& words) const;
  Eigen::Vector2d vec2(const Range& each) const;
  Eigen::Vector3d vec3(const Range& each) const;
  std::vector<YamlValue> list(std::size_t min_items = 0) const;
  YamlMap map(std::vector<std::string> allowed_keys) const;

 private:
  std::vector<double> numbers(std::size_t n, const Range& each) const;
  std::string file_;
  YAML::Node node_;
  std::string path_;
};

// A map read through its list of allowed keys.
class YamlMap {
 public:
  YamlMap(const YamlValue& self, std::vector<std::string> allowed_keys);

  bool has(const std::string& key) const;
  // The value of a key, or nothing when absent.
  std::optional<YamlValue> get(const std::string& key) const;
  // The value of a required key: when missing, fails at this map with `expected`.
  YamlValue required(const std::string& key, const std::string& expected) const;
  // Fails at this map, naming `key` (for rules between keys).
  [[noreturn]] void fail_missing(const std::string& key, const std::string& expected) const;
  const YamlValue& self() const { return self_; }
  std::string child_path(const std::string& key) const;

  // shorthands: required (no default) and optional (with default) values
  double number(const std::string& key, const Range& r) const;
  double number_or(const std::string& key, const Range& r, double fallback) const;
  std::int64_t integer(const std::string& key, const IntRange& r) const;
  std::int64_t integer_or(const std::string& key, const IntRange& r, std::int64_t fallback) const;
  bool boolean_or(const std::string& key, bool fallback) const;
  std::string string(const std::string& key) const;
  std::string string_or(const std::string& key, const std::string& fallback) const;
  Eigen::Vector2d vec2(const std::string& key, const Range& each) const;
  Eigen::Vector3d vec3(const std::string& key, const Range& each) const;
  Eigen::Vector3d vec3_or(const std::string& key, const Range& each, const Eigen::Vector3d& fallback) const;

 private:
  YamlValue self_;
  std::vector<std::pair<std::string, YAML::Node>> entries_;  // in file order
};

// Parses a document; a YAML syntax error becomes the same one-line InputError
// (key path "yaml"). An empty document gives a null node. Refused at their
// line and column (yaml_text_checks.h): a second document in the text (even
// one that is a syntax error), and a quote that is not closed on the line
// where it opens (reported at the quote, not as a missing key further down).
YamlValue parse_yaml(const std::string& text, const std::string& file);
// Reads the file through input_file.h's checks (a regular file within
// kind's size bound: input_kind::kScene, kCalibration, kExperiment, ...) and
// parses it as parse_yaml does. Every YAML file a loader reads comes here.
YamlValue read_yaml_file(const std::string& path, const InputKind& kind);

// "a list of 3 finite numbers > 0"
std::string describe_list_of(std::size_t n, const Range& each);

}  // namespace repose
