#pragma once
// A calibration parameter resolved against the solver's declaration: its
// unit, and its initial value, bounds and step in SI units. The file's
// bounds default to the solver's interval and must lie within it; the step
// defaults to 5 % of the bounds' width and is at most half of it.

#include "models/core/solver/solver.h"
#include "validation/calibration/calibration_spec.h"

namespace repose {

// Fills unit, si_per_unit, initial, lower, upper and step of `param` from
// its file values and `info`. InputError at param.location for bounds or an
// initial value outside the solver's interval.
void resolve_parameter(ParameterSpec& param, const ParameterInfo& info);

}  // namespace repose
