#include "models/core/run/repository_path.h"

#include <filesystem>

namespace repose {

namespace fs = std::filesystem;

std::string repository_root() {
#ifdef REPOSE_SOURCE_DIR
  return REPOSE_SOURCE_DIR;
#else
  return fs::current_path().string();
#endif
}

std::string repository_relative(const std::string& path) {
  if (path.empty()) return path;
  std::error_code ec;
  const fs::path absolute = fs::weakly_canonical(fs::absolute(path), ec);
  const fs::path root = fs::weakly_canonical(repository_root(), ec);
  if (ec) return path;
  const fs::path relative = absolute.lexically_relative(root);
  if (relative.empty() || *relative.begin() == "..") return path;
  return relative.generic_string();
}

}  // namespace repose
