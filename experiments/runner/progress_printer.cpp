#include "experiments/runner/progress_printer.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace repose::cli {

ProgressPrinter::ProgressPrinter(std::FILE* stream, ProgressPrinterOptions options)
    : stream_(stream),
      options_(options),
      tty_(::isatty(::fileno(stream)) != 0),
      start_(Clock::now()),
      last_print_(start_) {}

ProgressFn ProgressPrinter::callback() {
  return [this](double fraction, std::string_view what) { report(fraction, what); };
}

void ProgressPrinter::report(double fraction, std::string_view what) {
  fraction = std::clamp(fraction, 0.0, 1.0);
  const double since_last_s = std::chrono::duration<double>(Clock::now() - last_print_).count();
  const bool new_task = what != last_what_;
  const bool done = fraction >= 1.0;
  if (tty_) {
    if (new_task || done || since_last_s >= options_.tty_refresh_s) print(fraction, what, done);
    return;
  }
  const bool next_step = std::floor(fraction / options_.step_fraction) >
                         std::floor(std::max(last_fraction_, 0.0) / options_.step_fraction);
  if (new_task || done || next_step || since_last_s >= options_.min_interval_s) print(fraction, what, done);
}

void ProgressPrinter::print(double fraction, std::string_view what, bool final) {
  const double elapsed_s = std::chrono::duration<double>(Clock::now() - start_).count();
  const std::string line = fmt::format("repose: {} {:3.0f}% ({:.1f} s)", what, 100.0 * fraction, elapsed_s);
  if (tty_) {
    if (line_open_ && what != last_what_) std::fputc('\n', stream_);
    std::fprintf(stream_, "\r%s\x1b[K%s", line.c_str(), final ? "\n" : "");
    line_open_ = !final;
  } else {
    std::fprintf(stream_, "%s\n", line.c_str());
  }
  std::fflush(stream_);
  last_print_ = Clock::now();
  last_fraction_ = (what != last_what_) ? fraction : std::max(fraction, last_fraction_);
  last_what_ = std::string(what);
}

}  // namespace repose::cli
