#include "models/core/base/error.h"

#include <fmt/format.h>

namespace repose {

void invariant_failed(const char* expr, const char* file, int line) {
  throw std::logic_error(fmt::format("internal invariant failed: {} ({}:{})", expr, file, line));
}

}  // namespace repose
