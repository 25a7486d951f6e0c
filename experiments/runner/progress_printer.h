#pragma once
// Progress of long work on stderr. On a terminal the line is rewritten in
// place; otherwise (CI logs, files) a new line is printed per 10 % step or
// at most every few seconds, so logs stay short and readable.

#include <chrono>
#include <cstdio>
#include <string>

#include "models/core/base/progress.h"

namespace repose::cli {

struct ProgressPrinterOptions {
  double step_fraction = 0.1;     // a line each time this much more is done
  double min_interval_s = 5.0;    // ... or when this long passed since the last line
  double tty_refresh_s = 0.1;     // terminal: rewrite the line at most this often
};

class ProgressPrinter {
 public:
  explicit ProgressPrinter(std::FILE* stream = stderr, ProgressPrinterOptions options = {});
  // A callback for models and solvers; it refers to this printer.
  ProgressFn callback();
  void report(double fraction, std::string_view what);

 private:
  using Clock = std::chrono::steady_clock;
  void print(double fraction, std::string_view what, bool final);

  std::FILE* stream_;
  ProgressPrinterOptions options_;
  bool tty_;
  Clock::time_point start_;
  Clock::time_point last_print_;
  double last_fraction_ = -1.0;
  std::string last_what_;
  bool line_open_ = false;  // terminal: a line without its newline yet
};

}  // namespace repose::cli
