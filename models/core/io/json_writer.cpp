#include "models/core/io/json_writer.h"

#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {
namespace {

// Length of the valid UTF-8 sequence starting at s[i], or 0 if it is not one
// (overlong forms, surrogates and code points above U+10FFFF are invalid).
std::size_t utf8_sequence_length(std::string_view s, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
  const unsigned char b0 = byte(i);
  std::size_t length = 0;
  unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
  if (b0 >= 0xC2 && b0 <= 0xDF) {
    length = 2;
  } else if (b0 >= 0xE0 && b0 <= 0xEF) {
    length = 3;
    if (b0 == 0xE0) lo = 0xA0;  // no overlong forms
    if (b0 == 0xED) hi = 0x9F;  // no surrogates
  } else if (b0 >= 0xF0 && b0 <= 0xF4) {
    length = 4;
    if (b0 == 0xF0) lo = 0x90;  // no overlong forms
    if (b0 == 0xF4) hi = 0x8F;  // nothing above U+10FFFF
  } else {
    return 0;
  }
  if (i + length > s.size()) return 0;
  if (byte(i + 1) < lo || byte(i + 1) > hi) return 0;
  for (std::size_t k = 2; k < length; ++k) {
    if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
  }
  return length;
}

}  // namespace

std::string json_quoted(std::string_view text) {
  std::string out;
  out.reserve(text.size() + 2);
  out.push_back('"');
  for (std::size_t i = 0; i < text.size();) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x80) {
      const std::size_t length = utf8_sequence_length(text, i);
      if (length == 0) {
        out += "\\ufffd";
        ++i;
      } else {
        out.append(text.substr(i, length));
        i += length;
      }
      continue;
    }
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\b': out += "\\b"; break;
      case '\f': out += "\\f"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        if (c < 0x20) {
          out += fmt::format("\\u{:04x}", c);
        } else {
          out.push_back(static_cast<char>(c));
        }
    }
    ++i;
  }
  out.push_back('"');
  return out;
}

void JsonWriter::newline_and_indent(std::size_t depth) {
  out_ << '\n' << std::string(2 * depth, ' ');
}

// Separators and indentation before any value; checks that a value may come here.
void JsonWriter::before_value() {
  if (stack_.empty()) {
    REPOSE_DEMAND(!wrote_top_level_);
    wrote_top_level_ = true;
    return;
  }
  Frame& frame = stack_.back();
  if (frame.container == Container::kObject) {
    REPOSE_DEMAND(frame.key_pending);
    frame.key_pending = false;
  } else {
    if (frame.count > 0) out_ << ',';
    newline_and_indent(stack_.size());
  }
  ++frame.count;
}

JsonWriter& JsonWriter::key(std::string_view name) {
  REPOSE_DEMAND(!stack_.empty());
  Frame& frame = stack_.back();
  REPOSE_DEMAND(frame.container == Container::kObject);
  REPOSE_DEMAND(!frame.key_pending);
  if (frame.count > 0) out_ << ',';
  newline_and_indent(stack_.size());
  out_ << json_quoted(name) << ": ";
  frame.key_pending = true;
  return *this;
}

void JsonWriter::open(Container container, char bracket) {
  before_value();
  out_ << bracket;
  stack_.push_back(Frame{container});
}

void JsonWriter::close(Container container, char bracket) {
  REPOSE_DEMAND(!stack_.empty());
  const Frame frame = stack_.back();
  REPOSE_DEMAND(frame.container == container);
  REPOSE_DEMAND(!frame.key_pending);
  stack_.pop_back();
  if (frame.count > 0) newline_and_indent(stack_.size());
  out_ << bracket;
  if (stack_.empty()) out_ << '\n';
}

JsonWriter& JsonWriter::begin_object() {
  open(Container::kObject, '{');
  return *this;
}
JsonWriter& JsonWriter::end_object() {
  close(Container::kObject, '}');
  return *this;
}
JsonWriter& JsonWriter::begin_array() {
  open(Container::kArray, '[');
  return *this;
}
JsonWriter& JsonWriter::end_array() {
  close(Container::kArray, ']');
  return *this;
}

JsonWriter& JsonWriter::string(std::string_view text) {
  before_value();
  out_ << json_quoted(text);
  return *this;
}

JsonWriter& JsonWriter::boolean(bool b) {
  before_value();
  out_ << (b ? "true" : "false");
  return *this;
}

JsonWriter& JsonWriter::null() {
  before_value();
  out_ << "null";
  return *this;
}

JsonWriter& JsonWriter::integer(std::int64_t i) {
  before_value();
  out_ << fmt::format("{}", i);
  return *this;
}

JsonWriter& JsonWriter::unsigned_integer(std::uint64_t u) {
  before_value();
  out_ << fmt::format("{}", u);
  return *this;
}

JsonWriter& JsonWriter::number(double x) {
  if (!std::isfinite(x)) return null();
  before_value();
  // fmt's "{}" is the shortest round-trip form (0.1, 1e+20, 2); ".0" is added to
  // integral values so readers keep them as floating point (and -0.0 keeps its sign).
  std::string text = fmt::format("{}", x);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  out_ << text;
  return *this;
}

}  // namespace repose
