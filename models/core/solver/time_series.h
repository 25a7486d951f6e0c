#pragma once
// A quantity over a run (the mass a bucket holds, step by step): samples
// (time, value) in time order, with a unit. Solvers put theirs in
// Run::series; calibration compares them at given times (a `series`
// observable) with a reference's.

#include <string>
#include <vector>

namespace repose {

struct TimeSeries {
  std::string unit;            // as Measure::unit: "kg", "m^3", ...
  std::vector<double> time_s;  // non-decreasing
  std::vector<double> value;   // one per time

  // Linear between the samples around t, the first value before the first
  // sample and the last after the last. InputError when empty or ragged.
  double at(double t) const;
};

}  // namespace repose
