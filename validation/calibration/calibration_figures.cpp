#include "validation/calibration/calibration_figures.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "models/core/run/repository_path.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

std::string quoted(const std::string& s) {
  std::string out = "'";
  for (const char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

}  // namespace

std::string calibration_figures_script() {
  return (fs::path(repository_root()) / "experiments" / "plots" / "calibration_figures.py").string();
}

CalibrationFigures make_calibration_figures(const std::string& run_dir) {
  CalibrationFigures figures;
  const std::string python = "/usr/bin/python3";
  const std::string script = calibration_figures_script();
  if (!fs::exists(python) || !fs::exists(script)) {
    figures.note = fmt::format("Figures not made: {} not found.", fs::exists(python) ? script : python);
    return figures;
  }
  const std::string log = (fs::path(run_dir) / "figures.log").string();
  const std::string command = fmt::format("MPLBACKEND=Agg {} {} {} > {} 2>&1", python, quoted(script), quoted(run_dir), quoted(log));
  const int status = std::system(command.c_str());
  if (status != 0) {
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    std::string last = text.str();
    if (last.size() > 400) last = "..." + last.substr(last.size() - 400);
    figures.note = fmt::format("Figures not made: the plot script failed (status {}): {}", status, last);
  }
  for (const auto& entry : fs::directory_iterator(run_dir)) {
    if (entry.path().extension() == ".png") figures.names.push_back(entry.path().filename().string());
  }
  std::sort(figures.names.begin(), figures.names.end());
  return figures;
}

}  // namespace repose
