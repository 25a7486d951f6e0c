#pragma once
// What this program was built from and with, for `repose --version` and run
// manifests: the git commit of the source tree, the compiler, the build type
// and the versions of the libraries compiled in.

#include <string>
#include <vector>

namespace repose {

struct LibraryVersion {
  std::string name;
  std::string version;  // "unknown" when the build does not say
};

struct BuildInfo {
  std::string git_commit;   // 40 hex digits, or "unknown" outside a checkout
  bool git_dirty = false;   // tracked files outside data/ differ from git_commit
  std::string compiler;     // e.g. "GCC 12.2.0"
  std::string build_type;   // CMake's build type when passed, else from NDEBUG/__OPTIMIZE__
  std::vector<LibraryVersion> libraries;
};

struct BuildInfoOptions {
  // Create a 1x1 OSMesa context to read Mesa's GL_VERSION (a few ms).
  bool query_opengl = true;
};

// Collects the build information. The commit is REPOSE_GIT_COMMIT when the
// build defines it, else `git rev-parse HEAD` in the source tree at run time.
BuildInfo build_info(const BuildInfoOptions& options = {});

// Several lines, "name version", for --version.
std::string describe_build(const BuildInfo& info);

}  // namespace repose
