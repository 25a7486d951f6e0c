// The `repose` program over a solver registry (commands.h: run_cli).
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <string>

#include "experiments/cli/commands.h"
#include "models/core/run/build_info.h"
#include "models/core/base/error.h"

namespace {

constexpr int kExitBadInput = 2;
constexpr int kExitInternal = 1;

// Messages are printed on one line whatever they contain.
std::string one_line(std::string text) {
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  while (!text.empty() && text.back() == ' ') text.pop_back();
  return text;
}

std::string version_text() {
  std::string text = fmt::format("repose {}\n{}", REPOSE_VERSION, repose::describe_build(repose::build_info()));
  while (!text.empty() && text.back() == '\n') text.pop_back();  // CLI11 adds the last newline
  return text;
}

}  // namespace

namespace repose::cli {

int run_cli(int argc, char** argv, const SolverRegistry& registry) {
  CLI::App app{"repose: heuristic granular models validated against DEM references"};
  app.set_version_flag("--version", version_text, "Print the version, the git commit and the library versions");
  app.require_subcommand(1);
  add_check_command(app, registry);
  add_render_command(app, registry);
  add_run_command(app, argc, argv, registry);
  add_calibrate_command(app, argc, argv, registry);
  add_experiment_command(app, argc, argv, registry);
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "repose: %s (see repose --help)\n", one_line(e.what()).c_str());
    return kExitBadInput;
  } catch (const repose::InputError& e) {
    // InputError messages start with the file (and line:column) they are about.
    std::fprintf(stderr, "%s\n", one_line(e.what()).c_str());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "repose: internal error: %s\n", one_line(e.what()).c_str());
    return kExitInternal;
  }
  return 0;
}

}  // namespace repose::cli
