#include "models/core/config/yaml_reader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include "models/core/config/yaml_text_checks.h"

namespace repose {

namespace {

std::string format_bound(double x) { return fmt::format("{}", x); }

// A scalar as it reads in a message: one line, not too long.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

// yaml-cpp gives 0-based positions (or -1 when unknown); messages are 1-based.
int one_based(int position) { return std::max(position, 0) + 1; }

bool is_quoted(const YAML::Node& node) { return node.Tag() == "!"; }

// A plain YAML scalar as a double: the YAML core schema's .inf/.nan forms and
// decimal numbers, nothing else (no trailing text, no quoted strings).
std::optional<double> parse_double(const std::string& s) {
  if (s == ".inf" || s == ".Inf" || s == ".INF" || s == "+.inf" || s == "+.Inf" || s == "+.INF")
    return std::numeric_limits<double>::infinity();
  if (s == "-.inf" || s == "-.Inf" || s == "-.INF") return -std::numeric_limits<double>::infinity();
  if (s == ".nan" || s == ".NaN" || s == ".NAN") return std::numeric_limits<double>::quiet_NaN();
  std::string_view v = s;
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);
  double x = 0.0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x, std::chars_format::general);
  if (ec != std::errc() || end != v.data() + v.size() || v.empty()) return std::nullopt;
  return x;
}

std::optional<std::int64_t> parse_int(const std::string& s) {
  std::string_view v = s;
  if (!v.empty() && v.front() == '+') v.remove_prefix(1);
  std::int64_t x = 0;
  const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), x);
  if (ec != std::errc() || end != v.data() + v.size() || v.empty()) return std::nullopt;
  return x;
}

std::string join(const std::vector<std::string>& words, const std::string& sep) {
  std::string out;
  for (std::size_t k = 0; k < words.size(); ++k) out += (k ? sep : "") + words[k];
  return out;
}

}  // namespace

bool Range::contains(double x) const {
  if (!std::isfinite(x)) return false;
  const bool above = min_inclusive ? x >= min : x > min;
  const bool below = max_inclusive ? x <= max : x < max;
  return above && below;
}

std::string Range::describe() const {
  const bool has_min = std::isfinite(min);
  const bool has_max = std::isfinite(max);
  if (has_min && has_max) {
    return fmt::format("a finite number in {}{}, {}{}", min_inclusive ? "[" : "(", format_bound(min),
                       format_bound(max), max_inclusive ? "]" : ")");
  }
  if (has_min) return fmt::format("a finite number {} {}", min_inclusive ? ">=" : ">", format_bound(min));
  if (has_max) return fmt::format("a finite number {} {}", max_inclusive ? "<=" : "<", format_bound(max));
  return "a finite number";
}

std::string IntRange::describe() const {
  constexpr auto lowest = std::numeric_limits<std::int64_t>::min();
  constexpr auto highest = std::numeric_limits<std::int64_t>::max();
  if (min != lowest && max != highest) return fmt::format("an integer in [{}, {}]", min, max);
  if (min != lowest) return fmt::format("an integer >= {}", min);
  if (max != highest) return fmt::format("an integer <= {}", max);
  return "an integer";
}

std::string describe_list_of(std::size_t n, const Range& each) {
  std::string element = each.describe();
  // "a finite number > 0" -> "finite numbers > 0"
  if (element.rfind("a finite number", 0) == 0) element = "finite numbers" + element.substr(15);
  return fmt::format("a list of {} {}", n, element);
}

std::string yaml_error_message(const std::string& file, const YAML::Mark& mark, const std::string& key_path,
                               const std::string& expected, const std::string& got) {
  std::string message = fmt::format("{}:{}:{}: {}: expected {}, got {}", file, one_based(mark.line),
                                    one_based(mark.column), key_path, expected, got);
  // one line whatever the file's strings hold
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::replace(message.begin(), message.end(), '\r', ' ');
  return message;
}

// ---- YamlValue

YamlValue::YamlValue(std::string file, YAML::Node node, std::string path)
    : file_(std::move(file)), node_(std::move(node)), path_(std::move(path)) {}

std::string YamlValue::describe_got() const {
  if (!node_.IsDefined() || node_.IsNull()) return "nothing (null)";
  if (node_.IsMap()) return "a map";
  if (node_.IsSequence()) return fmt::format("a list of {} item{}", node_.size(), node_.size() == 1 ? "" : "s");
  const std::string text = one_line(node_.Scalar());
  return is_quoted(node_) ? "\"" + text + "\"" : text;
}

void YamlValue::fail(const std::string& expected) const { fail(expected, describe_got()); }

void YamlValue::fail(const std::string& expected, const std::string& got) const {
  throw InputError(yaml_error_message(file_, node_.Mark(), display_path(), expected, got));
}

double YamlValue::number(const Range& range) const {
  if (!node_.IsScalar() || is_quoted(node_)) fail(range.describe());
  const auto x = parse_double(node_.Scalar());
  if (!x || !range.contains(*x)) fail(range.describe());
  return *x;
}

std::int64_t YamlValue::integer(const IntRange& range) const {
  if (!node_.IsScalar() || is_quoted(node_)) fail(range.describe());
  const auto x = parse_int(node_.Scalar());
  if (!x || *x < range.min || *x > range.max) fail(range.describe());
  return *x;
}

std::uint64_t YamlValue::unsigned_integer() const {
  const std::string what = "an integer in [0, 18446744073709551615]";
  if (!node_.IsScalar() || is_quoted(node_)) fail(what);
  const std::string& s = node_.Scalar();
  std::uint64_t x = 0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
  if (s.empty() || ec != std::errc() || end != s.data() + s.size()) fail(what);
  return x;
}

bool YamlValue::boolean() const {
  const std::string what = "true or false";
  if (!node_.IsScalar() || is_quoted(node_)) fail(what);
  const std::string& s = node_.Scalar();
  if (s == "true" || s == "True" || s == "TRUE") return true;
  if (s == "false" || s == "False" || s == "FALSE") return false;
  fail(what);
}

std::string YamlValue::string() const {
  if (!node_.IsScalar() || node_.Scalar().empty()) fail("a non-empty string");
  return node_.Scalar();
}

std::size_t YamlValue::choice(const std::vector<std::string>& words) const {
  const std::string what = "one of " + join(words, ", ");
  if (!node_.IsScalar()) fail(what);
  const auto it = std::find(words.begin(), words.end(), node_.Scalar());
  if (it == words.end()) fail(what);
  return static_cast<std::size_t>(it - words.begin());
}

std::vector<double> YamlValue::numbers(std::size_t n, const Range& each) const {
  if (!node_.IsSequence() || node_.size() != n) fail(describe_list_of(n, each));
  std::vector<double> out;
  for (std::size_t k = 0; k < n; ++k) {
    out.push_back(YamlValue(file_, node_[k], fmt::format("{}[{}]", display_path(), k)).number(each));
  }
  return out;
}

Eigen::Vector2d YamlValue::vec2(const Range& each) const {
  const auto v = numbers(2, each);
  return {v[0], v[1]};
}

Eigen::Vector3d YamlValue::vec3(const Range& each) const {
  const auto v = numbers(3, each);
  return {v[0], v[1], v[2]};
}

std::vector<YamlValue> YamlValue::list(std::size_t min_items) const {
  const std::string what =
      min_items > 0 ? fmt::format("a list of at least {} item{}", min_items, min_items == 1 ? "" : "s") : "a list";
  if (!node_.IsSequence() || node_.size() < min_items) fail(what);
  std::vector<YamlValue> out;
  for (std::size_t k = 0; k < node_.size(); ++k) {
    out.emplace_back(file_, node_[k], fmt::format("{}[{}]", display_path(), k));
  }
  return out;
}

YamlMap YamlValue::map(std::vector<std::string> allowed_keys) const { return YamlMap(*this, std::move(allowed_keys)); }

// ---- YamlMap

YamlMap::YamlMap(const YamlValue& self, std::vector<std::string> allowed_keys) : self_(self) {
  const std::string allowed = join(allowed_keys, ", ");
  if (!self_.node().IsMap()) self_.fail("a map with the keys " + allowed);
  std::set<std::string> seen;
  for (auto it = self_.node().begin(); it != self_.node().end(); ++it) {
    const YAML::Node key_node = it->first;
    if (!key_node.IsScalar()) {
      YamlValue(self_.file(), key_node, self_.display_path()).fail("a key (one of " + allowed + ")");
    }
    const std::string key = key_node.Scalar();
    const YamlValue key_value(self_.file(), key_node, child_path(key));
    if (std::find(allowed_keys.begin(), allowed_keys.end(), key) == allowed_keys.end()) {
      key_value.fail("one of the keys " + allowed, "unknown key '" + one_line(key) + "'");
    }
    if (!seen.insert(key).second) key_value.fail("each key once", "a second '" + one_line(key) + "'");
    entries_.emplace_back(key, it->second);
  }
}

std::string YamlMap::child_path(const std::string& key) const {
  return self_.path().empty() ? key : self_.path() + "." + key;
}

bool YamlMap::has(const std::string& key) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const auto& e) { return e.first == key; });
}

std::optional<YamlValue> YamlMap::get(const std::string& key) const {
  for (const auto& [k, node] : entries_) {
    if (k == key) return YamlValue(self_.file(), node, child_path(key));
  }
  return std::nullopt;
}

void YamlMap::fail_missing(const std::string& key, const std::string& expected) const {
  throw InputError(
      yaml_error_message(self_.file(), self_.node().Mark(), child_path(key), expected, "nothing (the key is missing)"));
}

YamlValue YamlMap::required(const std::string& key, const std::string& expected) const {
  auto v = get(key);
  if (!v) fail_missing(key, expected);
  return *v;
}

double YamlMap::number(const std::string& key, const Range& r) const { return required(key, r.describe()).number(r); }

double YamlMap::number_or(const std::string& key, const Range& r, double fallback) const {
  const auto v = get(key);
  return v ? v->number(r) : fallback;
}

std::int64_t YamlMap::integer(const std::string& key, const IntRange& r) const {
  return required(key, r.describe()).integer(r);
}

std::int64_t YamlMap::integer_or(const std::string& key, const IntRange& r, std::int64_t fallback) const {
  const auto v = get(key);
  return v ? v->integer(r) : fallback;
}

bool YamlMap::boolean_or(const std::string& key, bool fallback) const {
  const auto v = get(key);
  return v ? v->boolean() : fallback;
}

std::string YamlMap::string(const std::string& key) const { return required(key, "a non-empty string").string(); }

std::string YamlMap::string_or(const std::string& key, const std::string& fallback) const {
  const auto v = get(key);
  return v ? v->string() : fallback;
}

Eigen::Vector2d YamlMap::vec2(const std::string& key, const Range& each) const {
  return required(key, describe_list_of(2, each)).vec2(each);
}

Eigen::Vector3d YamlMap::vec3(const std::string& key, const Range& each) const {
  return required(key, describe_list_of(3, each)).vec3(each);
}

Eigen::Vector3d YamlMap::vec3_or(const std::string& key, const Range& each, const Eigen::Vector3d& fallback) const {
  const auto v = get(key);
  return v ? v->vec3(each) : fallback;
}

YamlValue parse_yaml(const std::string& text, const std::string& file) {
  // yaml-cpp's nodes take about 85 bytes per byte of text (input_file.h)
  require_memory(memory_estimate::product(text.size(), 90),
                 fmt::format("{}: parsing {} of YAML", file, format_bytes(text.size())));
  // the second-document check is on the text: yaml-cpp 0.7's LoadAll, which
  // would count documents, loops forever on some inputs (a fuzz finding,
  // tests/fuzz/regressions/yaml/), and Load ignores what follows the first
  check_single_document(text, file);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {  // syntax errors, and too deep nesting
    // an unterminated quote makes the parser fail further down: name the quote
    if (const auto quote = find_unclosed_quote(text, e.mark.line)) {
      throw InputError(yaml_error_message(
          file, *quote, "yaml", "a quoted string closed on the line where it opens",
          fmt::format("an unterminated quote (the parser then failed at line {}, column {}: {})",
                      one_based(e.mark.line), one_based(e.mark.column), e.msg)));
    }
    throw InputError(yaml_error_message(file, e.mark, "yaml", "valid YAML syntax", "a syntax error (" + e.msg + ")"));
  }
  check_quotes_closed(root, text, file);
  return YamlValue(file, root, "");
}

YamlValue read_yaml_file(const std::string& path, const InputKind& kind) {
  return parse_yaml(read_input_file(path, kind), path);
}

}  // namespace repose
