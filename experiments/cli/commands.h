#pragma once
// The subcommands of `repose`, one file each. Each add_* registers its
// subcommand on the app; the work runs in the subcommand's callback, and
// errors propagate to main() (InputError: exit 2, anything else: exit 1).

#include <CLI/CLI.hpp>

#include "models/core/solver/solver_registry.h"

namespace repose::cli {

// The commands use `registry` (which must outlive the app) for the solvers
// and scene sections they know.
void add_check_command(CLI::App& app, const SolverRegistry& registry);
void add_render_command(CLI::App& app, const SolverRegistry& registry);
void add_run_command(CLI::App& app, int argc, char** argv, const SolverRegistry& registry);
void add_calibrate_command(CLI::App& app, int argc, char** argv, const SolverRegistry& registry);
void add_experiment_command(CLI::App& app, int argc, char** argv, const SolverRegistry& registry);

// The whole `repose` program over a registry: parses argv, runs the command
// and returns the exit code (0 success, 2 bad input, 1 internal failure),
// printing every error as one line on stderr.
int run_cli(int argc, char** argv, const SolverRegistry& registry);

}  // namespace repose::cli
