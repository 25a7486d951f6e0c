#pragma once
// Progress of long work, reported to whoever runs it (the command line prints
// a line; tests pass nothing). fraction is in [0, 1].

#include <functional>
#include <string_view>

namespace repose {

using ProgressFn = std::function<void(double fraction, std::string_view what)>;

inline void report(const ProgressFn& progress, double fraction, std::string_view what) {
  if (progress) progress(fraction, what);
}

}  // namespace repose
