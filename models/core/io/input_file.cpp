#include "models/core/io/input_file.h"

#include <filesystem>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

void require_regular_file(const std::string& path, const char* kind) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw InputError(fmt::format("{}: no such file", path));
  if (fs::is_directory(status)) throw InputError(fmt::format("{}: is a directory, not a {} file", path, kind));
  if (!fs::is_regular_file(status)) throw InputError(fmt::format("{}: is not a regular file ({} expected)", path, kind));
}

}  // namespace repose
