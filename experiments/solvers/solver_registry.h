#pragma once
// repose's solvers: the list the command line, the experiment runner and
// calibration use. Adding a solver is one line in solver_registry.cpp.

#include "models/core/solver/solver_registry.h"

namespace repose {

// Every solver of repose, by name; the first is the default of `repose run`.
const SolverRegistry& solver_registry();

}  // namespace repose
