#include "models/core/config/yaml_text_checks.h"

#include <cctype>
#include <string_view>
#include <vector>

#include "models/core/base/error.h"
#include "models/core/config/yaml_reader.h"

namespace repose {
namespace {

// The offsets where each line of `text` starts.
std::vector<std::size_t> line_starts(const std::string& text) {
  std::vector<std::size_t> starts{0};
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] == '\n') starts.push_back(k + 1);
  }
  return starts;
}

std::string_view line_at(const std::string& text, const std::vector<std::size_t>& starts, std::size_t k) {
  const std::size_t end = k + 1 < starts.size() ? starts[k + 1] - 1 : text.size();
  std::string_view line(text.data() + starts[k], end - starts[k]);
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  return line;
}

YAML::Mark mark_at(std::size_t line, std::size_t column) {
  YAML::Mark m;
  m.line = static_cast<int>(line);
  m.column = static_cast<int>(column);
  m.pos = 0;
  return m;
}

// `---` or `...` at column 0, alone or followed by a space.
bool is_marker(std::string_view line, std::string_view marker) {
  return line.substr(0, 3) == marker && (line.size() == 3 || line[3] == ' ' || line[3] == '\t');
}

bool is_blank_or_comment(std::string_view line) {
  const std::size_t first = line.find_first_not_of(" \t");
  return first == std::string_view::npos || line[first] == '#';
}

struct QuoteEnd {
  std::size_t close = std::string::npos;  // offset of the closing quote, npos when never closed
  bool same_line = false;
};

// Where the quoted scalar opening at text[open] ends, by YAML's escapes:
// backslash in double quotes, a doubled quote in single quotes.
QuoteEnd find_closing_quote(std::string_view text, std::size_t open) {
  const char quote = text[open];
  QuoteEnd end;
  end.same_line = true;
  for (std::size_t k = open + 1; k < text.size(); ++k) {
    const char c = text[k];
    if (c == '\n') end.same_line = false;
    if (quote == '"' && c == '\\') {
      if (k + 1 < text.size() && text[k + 1] == '\n') end.same_line = false;
      ++k;
      continue;
    }
    if (c != quote) continue;
    if (quote == '\'' && k + 1 < text.size() && text[k + 1] == '\'') {
      ++k;
      continue;
    }
    end.close = k;
    return end;
  }
  end.same_line = false;
  return end;
}

[[noreturn]] void fail_unclosed(const std::string& file, const YAML::Mark& at, const std::string& key_path,
                                const QuoteEnd& end, const std::vector<std::size_t>& starts) {
  std::string got = "a quote that is never closed (unterminated quote)";
  if (end.close != std::string::npos) {
    std::size_t close_line = 0;
    while (close_line + 1 < starts.size() && starts[close_line + 1] <= end.close) ++close_line;
    got = "a quote closed only on line " + std::to_string(close_line + 1) + " (unterminated quote?)";
  }
  throw InputError(yaml_error_message(file, at, key_path, "a quoted string closed on the line where it opens", got));
}

struct QuoteChecker {
  const std::string& text;
  const std::string& file;
  std::vector<std::size_t> starts;

  void scalar(const YAML::Node& node, const std::string& key_path) const {
    const YAML::Mark m = node.Mark();
    if (m.line < 0 || m.column < 0 || static_cast<std::size_t>(m.line) >= starts.size()) return;
    const std::size_t offset = starts[static_cast<std::size_t>(m.line)] + static_cast<std::size_t>(m.column);
    if (offset >= text.size() || (text[offset] != '"' && text[offset] != '\'')) return;
    const QuoteEnd end = find_closing_quote(text, offset);
    if (!end.same_line) fail_unclosed(file, m, key_path, end, starts);
  }

  void visit(const YAML::Node& node, const std::string& key_path) const {
    if (node.IsScalar()) {
      scalar(node, key_path);
    } else if (node.IsSequence()) {
      for (std::size_t k = 0; k < node.size(); ++k) visit(node[k], key_path + "[" + std::to_string(k) + "]");
    } else if (node.IsMap()) {
      for (const auto& entry : node) {
        const std::string key = entry.first.IsScalar() ? entry.first.Scalar() : "?";
        const std::string child = key_path.empty() ? key : key_path + "." + key;
        scalar(entry.first, child);
        visit(entry.second, child);
      }
    }
  }
};

// True when a quote at line[p] opens a scalar: at the start of the line's
// content, or after a flow indicator, or after `: `, `- `, `? `.
bool opens_scalar(std::string_view line, std::size_t p) {
  std::size_t k = p;
  while (k > 0 && (line[k - 1] == ' ' || line[k - 1] == '\t')) --k;
  if (k == 0) return true;
  const char before = line[k - 1];
  if (before == '[' || before == '{' || before == ',') return true;
  return (before == ':' || before == '-' || before == '?') && k < p;
}

// The indentation of a line that ends a key or item with a block scalar
// indicator (`|`, `>-`, `|2+`, ...), else npos.
std::size_t block_scalar_indent(std::string_view line) {
  std::size_t end = line.find(" #");
  std::string_view content = line.substr(0, end);
  while (!content.empty() && (content.back() == ' ' || content.back() == '\t')) content.remove_suffix(1);
  std::size_t k = content.size();
  while (k > 0 && (std::isdigit(static_cast<unsigned char>(content[k - 1])) || content[k - 1] == '+' ||
                   content[k - 1] == '-')) {
    --k;
  }
  if (k == 0 || (content[k - 1] != '|' && content[k - 1] != '>')) return std::string_view::npos;
  if (k >= 2 && content[k - 2] != ' ') return std::string_view::npos;
  return line.find_first_not_of(' ');
}

}  // namespace

void check_single_document(const std::string& text, const std::string& file) {
  const std::vector<std::size_t> starts = line_starts(text);
  bool content = false;
  bool ended = false;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const std::string_view line = line_at(text, starts, k);
    if (is_marker(line, "---")) {
      if (content || ended) {
        throw InputError(yaml_error_message(file, mark_at(k, 0), "yaml", "a single YAML document per file",
                                            "a second document starting here ('---')"));
      }
      content = !is_blank_or_comment(line.substr(3));
    } else if (is_marker(line, "...")) {
      ended = true;
    } else if (!is_blank_or_comment(line) && !(line.front() == '%' && !content)) {
      if (ended) {
        throw InputError(yaml_error_message(file, mark_at(k, 0), "yaml", "a single YAML document per file",
                                            "more content after the document's end ('...')"));
      }
      content = true;
    }
  }
}

void check_quotes_closed(const YAML::Node& root, const std::string& text, const std::string& file) {
  const QuoteChecker checker{text, file, line_starts(text)};
  checker.visit(root, "");
}

std::optional<YAML::Mark> find_unclosed_quote(const std::string& text, int error_line) {
  const std::vector<std::size_t> starts = line_starts(text);
  std::size_t block_indent = std::string_view::npos;
  for (std::size_t k = 0; k < starts.size() && static_cast<int>(k) <= error_line; ++k) {
    const std::string_view line = line_at(text, starts, k);
    const std::size_t indent = line.find_first_not_of(' ');
    if (block_indent != std::string_view::npos) {
      if (indent == std::string_view::npos || indent > block_indent) continue;  // inside a block scalar
      block_indent = std::string_view::npos;
    }
    for (std::size_t p = 0; p < line.size(); ++p) {
      const char c = line[p];
      if (c == '#' && (p == 0 || line[p - 1] == ' ' || line[p - 1] == '\t')) break;  // a comment
      if ((c != '"' && c != '\'') || !opens_scalar(line, p)) continue;
      const QuoteEnd end = find_closing_quote(line, p);
      if (end.close == std::string::npos) return mark_at(k, p);
      p = end.close;
    }
    block_indent = block_scalar_indent(line);
  }
  return std::nullopt;
}

}  // namespace repose
