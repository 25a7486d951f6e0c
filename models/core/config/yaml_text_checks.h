#pragma once
// Checks on the YAML source text that yaml-cpp does not make, so that a
// mistake is reported where it is, not as a missing key further down.
//
// - One document per file: YAML::Load reads the first document and ignores
//   the rest, even a second document that is a syntax error. A `---` after
//   content, or content after `...`, is refused at its line.
// - Quotes close on the line they open: yaml-cpp accepts a double quote left
//   open until the end of the file (the rest of the file becomes one string
//   and the next error is "missing key"), and a quote that pairs with one on
//   a later line swallows the lines between. A quoted scalar spanning lines
//   is refused at its opening quote; a config file has no need of one (use
//   a block scalar, `|` or `>`, for long text).
//
// Every refusal is the reader's one-line "FILE:LINE:COL: yaml: expected ...,
// got ..." (yaml_error_message).

#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

namespace repose {

// Throws InputError at the second document's marker when `text` holds more
// than one YAML document.
void check_single_document(const std::string& text, const std::string& file);

// After a successful parse of `text` into `root`: throws InputError at the
// opening quote of the first quoted scalar (key or value) that is not closed
// on the line where it opens.
void check_quotes_closed(const YAML::Node& root, const std::string& text, const std::string& file);

// For a syntax error at line `error_line` (0-based): the first quote before
// it that opens a scalar and is not closed on its own line, a likely cause.
// A lexical scan (comments and block scalars skipped), used only to explain
// an error the parser already found.
std::optional<YAML::Mark> find_unclosed_quote(const std::string& text, int error_line);

}  // namespace repose
