#pragma once
// A small streaming JSON writer for manifests and summaries: values are
// written as they come, pretty-printed with a 2-space indent. Misuse (a value
// where an object needs a key, a key in an array, closing the wrong
// container, two top-level values) is an internal error (REPOSE_DEMAND).
//
//   JsonWriter json(out);
//   json.begin_object();
//   json.key("seed").integer(42);
//   json.key("sizes").begin_array().number(0.5).number(1.0).end_array();
//   json.end_object();

#include <cstdint>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace repose {

class JsonWriter {
 public:
  explicit JsonWriter(std::ostream& out) : out_(out) {}

  JsonWriter& begin_object();
  JsonWriter& end_object();
  JsonWriter& begin_array();
  JsonWriter& end_array();
  // The key of the next member; only inside an object, before each value.
  JsonWriter& key(std::string_view name);

  // Strings are UTF-8: valid sequences pass through, invalid bytes become U+FFFD.
  JsonWriter& string(std::string_view text);
  JsonWriter& boolean(bool b);
  JsonWriter& null();
  JsonWriter& integer(std::int64_t i);
  JsonWriter& unsigned_integer(std::uint64_t u);
  // Shortest text that reads back to the same double; NaN and infinities as null.
  JsonWriter& number(double x);

  // True once one complete top-level value has been written.
  bool complete() const { return stack_.empty() && wrote_top_level_; }

 private:
  enum class Container { kObject, kArray };
  struct Frame {
    Container container;
    int count = 0;
    bool key_pending = false;  // objects: a key was written, its value is due
  };

  void before_value();
  void open(Container container, char bracket);
  void close(Container container, char bracket);
  void newline_and_indent(std::size_t depth);

  std::ostream& out_;
  std::vector<Frame> stack_;
  bool wrote_top_level_ = false;
};

// The JSON string literal of text, quotes included (see JsonWriter::string).
std::string json_quoted(std::string_view text);

}  // namespace repose
