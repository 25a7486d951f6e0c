#pragma once
// The subcommands of `repose`, one file each. Each add_* registers its
// subcommand on the app; the work runs in the subcommand's callback, and
// errors propagate to main() (InputError: exit 2, anything else: exit 1).

#include <CLI/CLI.hpp>

namespace repose::cli {

void add_check_command(CLI::App& app);
void add_render_command(CLI::App& app);
void add_run_command(CLI::App& app, int argc, char** argv);
void add_calibrate_command(CLI::App& app, int argc, char** argv);
void add_experiment_command(CLI::App& app, int argc, char** argv);

}  // namespace repose::cli
