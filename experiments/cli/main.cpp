// repose: the command-line program. Exit codes: 0 success, 2 bad input, 1 internal failure.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <exception>

#include "models/core/error.h"

int main(int argc, char** argv) {
  CLI::App app{"repose: heuristic granular models validated against DEM references"};
  app.set_version_flag("--version", std::string("repose ") + REPOSE_VERSION);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  return 0;
}
