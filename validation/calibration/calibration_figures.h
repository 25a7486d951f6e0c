#pragma once
// The figures of a calibration run folder, drawn by
// experiments/plots/calibration_figures.py with matplotlib (/usr/bin/python3,
// MPLBACKEND=Agg) from calibration.json and data/: per scene the reference,
// heuristic and difference maps (maps_SCENE.png) and the transect profiles
// (transects_SCENE.png); the cost against iteration of every start
// (cost.png); the speed/accuracy ladder (ladder.png).

#include <string>
#include <vector>

namespace repose {

struct CalibrationFigures {
  std::vector<std::string> names;  // PNG files made, relative to the run folder
  std::string note;                // empty, or why figures are missing (python's error)
};

// run_dir holds calibration.json and data/ already.
CalibrationFigures make_calibration_figures(const std::string& run_dir);

// The script's path in the source tree.
std::string calibration_figures_script();

}  // namespace repose
