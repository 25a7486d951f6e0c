#include "models/core/io/json_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace repose {
namespace {

namespace fs = std::filesystem;

const char* const kPython = "/usr/bin/python3";

std::string read_all(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A fresh, empty temporary directory, removed at the end of the test.
struct TempDir {
  fs::path path;
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "repose_json_XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path = pattern;
  }
  ~TempDir() { fs::remove_all(path); }
};

TEST(JsonWriter, WritesNestedPrettyPrintedDocument) {
  std::ostringstream out;
  JsonWriter json(out);
  json.begin_object();
  json.key("a").integer(1);
  json.key("b").begin_array().boolean(true).null().end_array();
  json.key("c").begin_object().end_object();
  json.key("d").begin_array().end_array();
  json.end_object();
  EXPECT_TRUE(json.complete());
  EXPECT_EQ(out.str(),
            "{\n"
            "  \"a\": 1,\n"
            "  \"b\": [\n"
            "    true,\n"
            "    null\n"
            "  ],\n"
            "  \"c\": {},\n"
            "  \"d\": []\n"
            "}\n");
}

TEST(JsonWriter, EscapesQuotesBackslashesAndControlCharacters) {
  EXPECT_EQ(json_quoted("a\"b\\c"), "\"a\\\"b\\\\c\"");
  EXPECT_EQ(json_quoted("\n\r\t\b\f"), "\"\\n\\r\\t\\b\\f\"");
  EXPECT_EQ(json_quoted(std::string("\x01\x1f", 2)), "\"\\u0001\\u001f\"");
  EXPECT_EQ(json_quoted(std::string("x\0y", 3)), "\"x\\u0000y\"");
  EXPECT_EQ(json_quoted("/"), "\"/\"");
}

TEST(JsonWriter, PassesValidUtf8AndReplacesInvalidBytes) {
  const std::string snow = "\xe9\x9b\xaa";  // U+96EA
  EXPECT_EQ(json_quoted(snow), "\"" + snow + "\"");
  const std::string emoji = "\xf0\x9f\x8c\x8b";  // U+1F30B, four bytes
  EXPECT_EQ(json_quoted(emoji), "\"" + emoji + "\"");
  EXPECT_EQ(json_quoted("\xff"), "\"\\ufffd\"");
  EXPECT_EQ(json_quoted("\xe9\x9b"), "\"\\ufffd\\ufffd\"");   // truncated sequence
  EXPECT_EQ(json_quoted("\xc0\xaf"), "\"\\ufffd\\ufffd\"");   // overlong '/'
  EXPECT_EQ(json_quoted("\xed\xa0\x80"), "\"\\ufffd\\ufffd\\ufffd\"");  // surrogate
}

TEST(JsonWriter, NonFiniteNumbersAreNull) {
  std::ostringstream out;
  JsonWriter json(out);
  json.begin_array()
      .number(std::numeric_limits<double>::quiet_NaN())
      .number(std::numeric_limits<double>::infinity())
      .number(-std::numeric_limits<double>::infinity())
      .end_array();
  EXPECT_EQ(out.str(), "[\n  null,\n  null,\n  null\n]\n");
}

TEST(JsonWriter, IntegralDoublesKeepAFractionPart) {
  std::ostringstream out;
  JsonWriter json(out);
  json.begin_array().number(2.0).number(-0.0).number(0.25).number(1e20).integer(2).end_array();
  EXPECT_EQ(out.str(), "[\n  2.0,\n  -0.0,\n  0.25,\n  1e+20,\n  2\n]\n");
}

TEST(JsonWriter, MisuseIsAnInternalError) {
  std::ostringstream out;
  {
    JsonWriter json(out);
    json.begin_object();
    EXPECT_THROW(json.integer(1), std::logic_error);  // value without a key
  }
  {
    JsonWriter json(out);
    json.begin_array();
    EXPECT_THROW(json.key("k"), std::logic_error);  // key in an array
    EXPECT_THROW(json.end_object(), std::logic_error);  // wrong container
  }
  {
    JsonWriter json(out);
    json.begin_object().key("k");
    EXPECT_THROW(json.key("again"), std::logic_error);  // two keys in a row
    EXPECT_THROW(json.end_object(), std::logic_error);  // key without its value
  }
  {
    JsonWriter json(out);
    json.integer(1);
    EXPECT_TRUE(json.complete());
    EXPECT_THROW(json.integer(2), std::logic_error);  // two top-level values
    EXPECT_THROW(json.end_array(), std::logic_error);  // nothing open
  }
}

// Python's json module parses what we wrote; it prints every number back
// (repr is round-trip exact) and writes every string to its own file, so
// both can be compared with what went in.
TEST(JsonWriter, OutputParsesInPythonWithEveryValueIntact) {
  if (!fs::exists(kPython)) GTEST_SKIP() << "no " << kPython;
  const std::vector<double> numbers = {0.0,    -0.0,   0.1,     1.0 / 3.0, 1e300, -2.5e-310,
                                       1e20,   123456789.123456789, std::ldexp(1.0, -1074),
                                       std::numeric_limits<double>::max(), -7.0};
  const std::vector<std::string> strings = {
      "plain", "quote\" backslash\\ slash/", std::string("nul\0inside", 10), "\x01\x02\x1f\x7f",
      "tab\tnewline\nreturn\r", "\xe9\x9b\xaa \xf0\x9f\x8c\x8b", ""};

  TempDir dir;
  {
    std::ofstream file(dir.path / "doc.json", std::ios::binary);
    JsonWriter json(file);
    json.begin_object();
    json.key("numbers").begin_array();
    for (double x : numbers) json.number(x);
    json.end_array();
    json.key("strings").begin_array();
    for (const auto& s : strings) json.string(s);
    json.end_array();
    json.key("big").integer(std::numeric_limits<std::int64_t>::min());
    json.key("huge").unsigned_integer(std::numeric_limits<std::uint64_t>::max());
    json.key("nested").begin_object().key("deeper").begin_array().begin_object().end_object().end_array().end_object();
    json.end_object();
  }
  const fs::path script = dir.path / "check.py";
  std::ofstream(script) << "import json, sys\n"
                           "d = json.load(open(sys.argv[1] + '/doc.json', encoding='utf-8'))\n"
                           "out = open(sys.argv[1] + '/numbers.txt', 'w')\n"
                           "for x in d['numbers']: out.write(repr(x) + '\\n')\n"
                           "out.write(str(d['big']) + '\\n' + str(d['huge']) + '\\n')\n"
                           "for i, s in enumerate(d['strings']):\n"
                           "  open(sys.argv[1] + '/s%d.txt' % i, 'wb').write(s.encode('utf-8'))\n"
                           "assert d['nested'] == {'deeper': [{}]}\n";
  const std::string command = std::string(kPython) + " " + script.string() + " " + dir.path.string();
  ASSERT_EQ(std::system(command.c_str()), 0) << read_all(dir.path / "doc.json");

  std::istringstream lines(read_all(dir.path / "numbers.txt"));
  for (double x : numbers) {
    std::string line;
    ASSERT_TRUE(std::getline(lines, line));
    const double back = std::strtod(line.c_str(), nullptr);
    EXPECT_EQ(back, x) << line;
    EXPECT_EQ(std::signbit(back), std::signbit(x)) << line;
  }
  std::string big, huge;
  std::getline(lines, big);
  std::getline(lines, huge);
  EXPECT_EQ(big, std::to_string(std::numeric_limits<std::int64_t>::min()));
  EXPECT_EQ(huge, std::to_string(std::numeric_limits<std::uint64_t>::max()));
  for (std::size_t i = 0; i < strings.size(); ++i) {
    EXPECT_EQ(read_all(dir.path / ("s" + std::to_string(i) + ".txt")), strings[i]) << i;
  }
}

}  // namespace
}  // namespace repose
