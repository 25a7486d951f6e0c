#pragma once
// Paths as files that may be committed record them: relative to the
// repository when they lie inside it (data/ manifests must not hold the
// absolute paths of the machine that made them), unchanged otherwise.

#include <string>

namespace repose {

// The repository root this build came from (REPOSE_SOURCE_DIR).
std::string repository_root();
// `path` relative to repository_root() when inside it, else as given.
std::string repository_relative(const std::string& path);

}  // namespace repose
