#pragma once
// Runs the `liggghts` program on a script in a run directory:
//   liggghts -in SCRIPT -log log.liggghts -screen screen.txt
// (stdout and stderr go to stdout.txt). Serial on purpose: on this kind of
// machine two ranks gave no speed-up and serial runs are bit-identical, so
// independent runs side by side are the better use of cores.
// Progress comes from the thermo lines of the log; failure is detected from
// the exit status, signals, ERROR lines, lost atoms, REPOSE_FAILURE markers,
// a missing REPOSE_COMPLETE marker and non-finite positions in the dumps.

#include <stdexcept>
#include <string>

#include "models/core/base/progress.h"

namespace repose {

// A reference run that failed: what() is one line naming the run directory,
// the log file and the reason (the ERROR line quoted where there is one).
class LiggghtsRunError : public std::runtime_error {
 public:
  LiggghtsRunError(std::string run_dir, std::string log_path, std::string reason);
  const std::string& run_dir() const { return run_dir_; }
  const std::string& log_path() const { return log_path_; }
  const std::string& reason() const { return reason_; }

 private:
  std::string run_dir_, log_path_, reason_;
};

struct LiggghtsRunOptions {
  // The program: an absolute path, or a name looked up on PATH. Empty: the
  // CMake-found path when the build defines REPOSE_LIGGGHTS_EXECUTABLE, else "liggghts".
  std::string executable;
  double wall_clock_limit_s = 0.0;  // kill the run (whole process group) after this; 0: no limit
  int nice_increment = 10;          // the run's niceness is the caller's plus this, at most 19 (shared machines)
  long total_steps = 0;             // steps the script runs in all (for progress); 0: no fraction
  bool expect_complete_marker = true;  // a run that exits 0 without printing REPOSE_COMPLETE failed
  std::string dump_directory;       // relative to the run directory: every file there is checked for
                                    // non-finite positions after the run; empty: none checked
  ProgressFn progress;              // called with step / total_steps while it runs
};

struct LiggghtsRunSummary {
  double wall_time_s = 0.0;
  double cpu_time_s = 0.0; // user + system time of the program (on a shared machine the fairer cost)
  long last_step = 0;      // the last thermo step seen
  long atom_count = 0;     // atoms on the last thermo line
  std::string version;     // the log's first line, e.g. "LIGGGHTS (Version LIGGGHTS-PUBLIC 3.8.0, ...)"
};

// The program path the options resolve to (found on PATH when a bare name).
// Throws InputError when it cannot be found.
std::string resolve_liggghts_executable(const LiggghtsRunOptions& options);

// The version line the program prints first (runs it once on an empty input
// in a temporary directory; remembered per executable).
std::string liggghts_version(const std::string& executable);

// Runs `script_name` (relative to run_dir, which must exist). Throws
// LiggghtsRunError on any failure listed above.
LiggghtsRunSummary run_liggghts(const std::string& run_dir, const std::string& script_name,
                                const LiggghtsRunOptions& options);

}  // namespace repose
