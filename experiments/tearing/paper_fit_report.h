#pragma once
// The report of experiments/tearing/tearing_paper_fit.cpp: report.md (the
// fitted values with standard errors, each measure against its published
// value, the tear-ratio check) and fit.csv (the same numbers, one per row).

#include <map>
#include <string>
#include <vector>

#include "experiments/tearing/paper_fit_spec.h"
#include "validation/calibration/calibration_uncertainty.h"

namespace repose {

// Measures by direction ("md", "cd") and name, means over seeds.
using DirectionMeasures = std::map<std::string, std::map<std::string, double>>;

// tear: empty when the spec has no tear scene; its "md" is the tear along the
// grain, "cd" across it.
void write_paper_fit_report(const PaperFitSpec& spec, const std::vector<double>& fitted,
                            const CalibrationUncertainty& uncertainty, double final_cost,
                            const DirectionMeasures& tensile, const DirectionMeasures& tear, double cpu_s,
                            const std::string& out_dir);

}  // namespace repose
