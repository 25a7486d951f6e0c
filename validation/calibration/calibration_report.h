#pragma once
// The files of a calibration's run folder, from the fit and the ladder:
//   calibration.json     every number (parameters with value and standard error
//                        or "undetermined", correlation matrix, costs, per-scene
//                        RMSE before and after, iterations, termination, wall
//                        time, the starts, the ladder)
//   parameters.yaml      the calibrated parameters by full name (solver.parameter)
//                        in their units, standard errors and provenance in comments
//   data/*.npy, *.csv    maps and transects the figures are drawn from
//   report.md            what a person reads first
// Values are written in each parameter's unit (degrees for *_deg).

#include <optional>
#include <string>
#include <vector>

#include "validation/calibration/calibration_fit.h"
#include "validation/calibration/calibration_ladder.h"
#include "validation/calibration/calibration_problem.h"

namespace repose {

struct CalibrationOutputs {
  const CalibrationProblem& problem;
  const CalibrationFit& fit;
  const std::optional<Ladder>& ladder;
  std::string command_line;  // for the provenance
  std::string git_commit;
};

// `path(name)` gives where to write the file `name` of the run folder.
// Returns the names written.
std::vector<std::string> write_calibration_json(const CalibrationOutputs& o, const std::function<std::string(const std::string&)>& path);
std::vector<std::string> write_calibrated_parameters(const CalibrationOutputs& o, const std::function<std::string(const std::string&)>& path);
std::vector<std::string> write_calibration_figure_data(const CalibrationOutputs& o, const std::function<std::string(const std::string&)>& path);
// figures: the image names made (linked from the report); figure_note: why some are missing.
void write_calibration_report(const CalibrationOutputs& o, const std::vector<std::string>& figures,
                              const std::string& figure_note, const std::string& path);

// The text of parameters.yaml.
std::string calibrated_parameters_yaml(const CalibrationOutputs& o);

}  // namespace repose
