// repose: the command-line program over repose's solvers. Exit codes: 0
// success, 2 bad input (InputError or a command-line error), 1 internal
// failure. Every error is one line on stderr.
#include "experiments/cli/commands.h"
#include "experiments/solvers/solver_registry.h"

int main(int argc, char** argv) { return repose::cli::run_cli(argc, argv, repose::solver_registry()); }
