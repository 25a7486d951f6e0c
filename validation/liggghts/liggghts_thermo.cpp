#include "validation/liggghts/liggghts_thermo.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/io/input_file.h"

namespace repose {

int ThermoTable::column(const std::string& name) const {
  for (std::size_t k = 0; k < columns.size(); ++k) {
    if (columns[k] == name) return static_cast<int>(k);
  }
  return -1;
}

namespace {

std::vector<std::string> words_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> w;
  for (std::string s; in >> s;) w.push_back(s);
  return w;
}

// The row of numbers, or empty when the line is not all numbers of the right count.
std::vector<double> numeric_row(const std::vector<std::string>& w, std::size_t count) {
  std::vector<double> row;
  if (w.size() != count) return row;
  for (const std::string& s : w) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (end == s.c_str() || *end != '\0') return {};
    row.push_back(v);
  }
  return row;
}

}  // namespace

ThermoTable read_thermo_table(const std::string& log_path) {
  InputStream in(log_path, input_kind::kLiggghtsLog);
  ThermoTable table;
  bool in_block = false;
  for (std::string line; std::getline(in, line);) {
    const auto w = words_of(line);
    if (!w.empty() && w[0] == "Step") {
      if (w != table.columns) {  // a new thermo style: start over
        table.columns = w;
        table.rows.clear();
      }
      in_block = true;
      continue;
    }
    if (!in_block) continue;
    std::vector<double> row = numeric_row(w, table.columns.size());
    if (row.empty()) {
      in_block = false;
      continue;
    }
    if (!table.rows.empty() && table.rows.back()[0] >= row[0]) continue;  // repeated first line of a block
    table.rows.push_back(std::move(row));
  }
  if (table.rows.empty()) throw InputError(fmt::format("{}: no thermo lines", log_path));
  return table;
}

}  // namespace repose
