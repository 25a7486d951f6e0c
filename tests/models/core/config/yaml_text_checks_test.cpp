#include "models/core/config/yaml_text_checks.h"

#include <gtest/gtest.h>

#include <string>

#include "models/core/base/error.h"
#include "models/core/config/yaml_reader.h"

namespace repose {
namespace {

// parse_yaml's one-line error, or "" when the text is accepted.
std::string error_of(const std::string& text) {
  try {
    (void)parse_yaml(text, "s.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

void expect_error(const std::string& text, const std::string& location, const std::string& fragment) {
  const std::string message = error_of(text);
  EXPECT_EQ(message.rfind(location, 0), 0u) << message << "\nexpected at: " << location << "\nfor:\n" << text;
  EXPECT_NE(message.find(fragment), std::string::npos) << message << "\nexpected: " << fragment;
}

TEST(SingleDocument, ASecondDocumentIsRefusedAtItsMarker) {
  expect_error("name: a\nseed: 1\n---\nname: b\n", "s.yaml:3:1: yaml:", "a second document starting here");
  // the case: the second document is a syntax error that YAML::Load never saw
  expect_error("name: a\n---\nobjects: [1, 2\n", "s.yaml:2:1: yaml:", "a single YAML document per file");
  // an empty second document is a second document too
  expect_error("name: a\n---\n", "s.yaml:2:1:", "a second document");
  expect_error("name: a\n...\nname: b\n", "s.yaml:3:1:", "more content after the document's end");
}

TEST(SingleDocument, OneDocumentWithMarkersCommentsAndDirectivesIsAccepted) {
  EXPECT_EQ(error_of("---\nname: a\n"), "");
  EXPECT_EQ(error_of("# comment\n%YAML 1.2\n---\nname: a\n...\n# trailing comment\n"), "");
  EXPECT_EQ(error_of("--- {name: a}\n"), "");
  EXPECT_EQ(error_of(""), "");
  // '---' inside a value is text, not a marker
  EXPECT_EQ(error_of("name: a---b\nnote: '--- quoted'\nblock: |\n  ---\n  text\n"), "");
}

TEST(QuotesClosed, UnterminatedQuoteAtTheEndIsReportedAtTheQuote) {
  // yaml-cpp accepted this: the rest of the file became the name, and the
  // loader then reported "time: missing"
  expect_error("name: \"abc\ntime: {step_s: 0.1}\nground: 3\n", "s.yaml:1:7: name:", "never closed");
}

TEST(QuotesClosed, UnterminatedQuoteThatPairsLaterIsReportedAtTheQuote) {
  // the parser fails on line 3 ("end of map not found"); the cause is on line 1
  expect_error("name: \"abc\ntime: {step_s: 0.1}\nground: \"x\"\n", "s.yaml:1:7: yaml:",
               "an unterminated quote (the parser then failed at line 3");
  expect_error("seed: 1\nname: 'abc\ntime: 1\nx: 'y'\n", "s.yaml:2:7:", "unterminated quote");
  // a quote that closes two lines down without a parse error
  expect_error("a: 'x\n  y'\nb: 1\n", "s.yaml:1:4: a:", "a quote closed only on line 2");
}

TEST(QuotesClosed, QuotesInsideValuesAndEscapesAreFine) {
  EXPECT_EQ(error_of("name: \"a \\\" b\"\nx: 'it''s'\ny: it's plain\nz: [\"a\", 'b']\n"), "");
  EXPECT_EQ(error_of("# it's a comment\nname: a  # don't\n\"quoted key\": 1\n"), "");
  EXPECT_EQ(error_of("text: |\n  it's \"open\n  still text\nnext: 1\n"), "");
}

TEST(FindUnclosedQuote, SkipsCommentsPlainApostrophesAndBlockScalars) {
  EXPECT_FALSE(find_unclosed_quote("a: it's\n# 'x\nb: |\n  \"open\nc: 1\n", 10).has_value());
  const auto mark = find_unclosed_quote("a: 1\nb: [\"x\", \"y]\n", 5);
  ASSERT_TRUE(mark.has_value());
  EXPECT_EQ(mark->line, 1);
  EXPECT_EQ(mark->column, 9);
}

}  // namespace
}  // namespace repose
