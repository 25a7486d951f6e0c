#pragma once
// Errors that reach the user. InputError is bad input (a file, a key, a
// command-line value): the program exits 2 and prints what() as one line.
// Anything else that escapes is an internal failure (exit 1).

#include <stdexcept>
#include <string>

namespace repose {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Internal invariants: checked in every build type (never compiled out).
[[noreturn]] void invariant_failed(const char* expr, const char* file, int line);

}  // namespace repose

#define REPOSE_DEMAND(cond) \
  ((cond) ? (void)0 : ::repose::invariant_failed(#cond, __FILE__, __LINE__))
