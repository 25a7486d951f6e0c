#pragma once
// The report of experiments/tearing/tearing_paper_fit.cpp: report.md (the
// fitted values with standard errors; each measure against its published
// value, beside the sheet's seed-to-seed spread and the unfitted sheet's
// error; the tear-ratio check per seed) and fit.csv (the same numbers, one
// per row).

#include <map>
#include <string>
#include <vector>

#include "experiments/tearing/paper_fit_spec.h"
#include "experiments/tearing/tear_ratio.h"
#include "validation/calibration/calibration_uncertainty.h"

namespace repose {

// Measures by direction ("md", "cd") and name, means over seeds.
using DirectionMeasures = std::map<std::string, std::map<std::string, double>>;

struct PaperFitResults {
  std::vector<double> fitted;
  CalibrationUncertainty uncertainty;
  double final_cost = 0.0;
  SeedMeasures tensile;             // at the fitted values, per seed
  DirectionMeasures unfitted;       // tensile means at the file's initial values
  SeedMeasures tear;                // empty when the spec has no tear scene; "md" along the grain, "cd" across
  double cpu_s = 0.0;
};

void write_paper_fit_report(const PaperFitSpec& spec, const PaperFitResults& results, const std::string& out_dir);

}  // namespace repose
