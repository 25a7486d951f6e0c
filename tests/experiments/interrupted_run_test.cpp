// Safe outputs end to end: a real `repose run` killed (SIGKILL, no chance to
// clean up) while it is writing its run folder must leave no target folder
// (or, when replacing with --force, the old result untouched); a later run
// must succeed, write a complete folder, and remove the killed run's
// leftovers instead of trusting them. A run ended by SIGTERM or SIGINT,
// which can be caught, removes its temporary folder itself and still dies
// of the signal (exit status 128 + signal).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "models/core/io/npy_io.h"
#include "tests/support/run_repose.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

using test_support::read_all;
using test_support::start_repose;
using test_support::wait_exit_code;

struct TempDir : test_support::TempDir {
  TempDir() : test_support::TempDir("repose_interrupt") {}
};

// Big enough that writing the run folder takes a moment (a 1024 x 512 noise
// field, its .npy and its picture), small enough for a test: the run is
// killed as soon as its temporary folder holds a file. The `initial` solver:
// what is under test is the run folder, not a model.
const char* const kSlowScene = R"(name: interrupted
seed: 3
time: {step_s: 0.1, duration_s: 0.1}
ground:
  extent_m: [1.024, 0.512]
  cell_size_m: 0.001
  initial_height: {kind: noise, mean_m: 0.05, amplitude_m: 0.01, correlation_m: 0.004}
)";

// The hidden temporaries next to `target` (.NAME.tmp-PID-XXXXXX).
std::vector<fs::path> temporaries_of(const fs::path& target) {
  std::vector<fs::path> found;
  std::string prefix = ".";  // built in steps: GCC 12 warns falsely (-Wrestrict) on a + b + c here
  prefix += target.filename().string();
  prefix += ".tmp-";
  for (const auto& e : fs::directory_iterator(target.parent_path())) {
    if (e.path().filename().string().starts_with(prefix)) found.push_back(e.path());
  }
  return found;
}

// Starts a run and sends it `signal_number` once its temporary folder holds
// a file, i.e. in the middle of writing. Returns its exit code (128 + the
// signal when the signal ended it), or -1 when the run finished first.
int signal_run_midway(const std::vector<std::string>& args, const fs::path& cwd, const fs::path& target,
                      int signal_number) {
  const pid_t child = start_repose(args, cwd);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    for (const fs::path& t : temporaries_of(target)) {
      std::error_code ec;
      if (fs::is_directory(t, ec) && !fs::is_empty(t, ec)) {
        ::kill(child, signal_number);
        return wait_exit_code(child);
      }
    }
    int status = 0;
    if (::waitpid(child, &status, WNOHANG) == child) return -1;  // it finished (or failed) first
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ::kill(child, SIGKILL);
  wait_exit_code(child);
  return -1;
}

bool kill_run_midway(const std::vector<std::string>& args, const fs::path& cwd, const fs::path& target) {
  return signal_run_midway(args, cwd, target, SIGKILL) == 128 + SIGKILL;
}

// A child inherits ignored signals: a test started in the background by a
// non-interactive shell has SIGINT ignored, and so would the run (repose
// rightly keeps an inherited SIG_IGN). The test restores the default for
// the runs it starts.
struct DefaultSignalAction {
  explicit DefaultSignalAction(int s) : signal_number(s) { previous = std::signal(s, SIG_DFL); }
  ~DefaultSignalAction() { std::signal(signal_number, previous); }
  int signal_number;
  void (*previous)(int) = nullptr;
};

void expect_complete_run_folder(const fs::path& out) {
  ASSERT_TRUE(fs::is_directory(out));
  EXPECT_TRUE(fs::exists(out / "manifest.json"));
  const ArrayXXdR h = read_npy_2d((out / "height_initial.npy").string());
  EXPECT_EQ(h.rows(), 512);
  EXPECT_EQ(h.cols(), 1024);
  EXPECT_TRUE(h.allFinite());
}

TEST(InterruptedRun, KilledRunLeavesNoFolderAndALaterRunSucceeds) {
  TempDir cwd;
  std::ofstream(cwd.path / "scene.yaml") << kSlowScene;
  const fs::path out = cwd.path / "out";
  ASSERT_TRUE(kill_run_midway({"run", "scene.yaml", "--out", "out", "--solver", "initial"}, cwd.path, out))
      << "the run finished before it could be interrupted: make kSlowScene bigger";
  EXPECT_FALSE(fs::exists(out)) << "a killed run left a target folder";
  ASSERT_EQ(temporaries_of(out).size(), 1u) << "the killed run's temporary should still be there (SIGKILL)";
  const fs::path leftover = temporaries_of(out).front();

  EXPECT_EQ(wait_exit_code(start_repose({"run", "scene.yaml", "--out", "out", "--solver", "initial"}, cwd.path)), 0);
  expect_complete_run_folder(out);
  EXPECT_FALSE(fs::exists(leftover)) << "the later run did not clean up the killed run's temporary";
  EXPECT_TRUE(temporaries_of(out).empty());
}

TEST(InterruptedRun, KilledReplacementKeepsTheOldResult) {
  TempDir cwd;
  std::ofstream(cwd.path / "scene.yaml") << kSlowScene;
  const fs::path out = cwd.path / "out";
  ASSERT_EQ(wait_exit_code(start_repose({"run", "scene.yaml", "--out", "out", "--solver", "initial"}, cwd.path)), 0);
  const std::string old_manifest = read_all(out / "manifest.json");
  ASSERT_FALSE(old_manifest.empty());

  ASSERT_TRUE(kill_run_midway({"run", "scene.yaml", "--out", "out", "--solver", "initial", "--force"}, cwd.path, out))
      << "the run finished before it could be interrupted: make kSlowScene bigger";
  EXPECT_EQ(read_all(out / "manifest.json"), old_manifest) << "the old result was changed by a killed run";
  expect_complete_run_folder(out);

  EXPECT_EQ(wait_exit_code(start_repose({"run", "scene.yaml", "--out", "out", "--solver", "initial", "--force"}, cwd.path)), 0);
  expect_complete_run_folder(out);
  EXPECT_TRUE(temporaries_of(out).empty());
}

// SIGTERM and SIGINT can be caught: the run removes its temporary before it
// dies, and dies of the signal (the exit status says so); a later run works.
void expect_signal_removes_temporary(int signal_number, bool replacing) {
  const DefaultSignalAction restore(signal_number);
  TempDir cwd;
  std::ofstream(cwd.path / "scene.yaml") << kSlowScene;
  const fs::path out = cwd.path / "out";
  std::vector<std::string> args = {"run", "scene.yaml", "--out", "out", "--solver", "initial"};
  std::string old_manifest;
  if (replacing) {
    ASSERT_EQ(wait_exit_code(start_repose(args, cwd.path)), 0);
    old_manifest = read_all(out / "manifest.json");
    args.push_back("--force");
  }
  const int exit_code = signal_run_midway(args, cwd.path, out, signal_number);
  ASSERT_NE(exit_code, -1) << "the run finished before it could be interrupted: make kSlowScene bigger";
  EXPECT_EQ(exit_code, 128 + signal_number) << "the run did not die of signal " << signal_number;
  EXPECT_TRUE(temporaries_of(out).empty()) << "signal " << signal_number << " left the run's temporary folder";
  if (replacing) {
    EXPECT_EQ(read_all(out / "manifest.json"), old_manifest) << "the old result was changed by an interrupted run";
  } else {
    EXPECT_FALSE(fs::exists(out)) << "an interrupted run left a target folder";
  }
  EXPECT_EQ(wait_exit_code(start_repose({"run", "scene.yaml", "--out", "out", "--solver", "initial", "--force"},
                                        cwd.path)),
            0);
  expect_complete_run_folder(out);
}

TEST(InterruptedRun, SigtermRemovesTheTemporaryAndDiesOfTheSignal) {
  expect_signal_removes_temporary(SIGTERM, false);
}

TEST(InterruptedRun, SigintRemovesTheTemporaryAndDiesOfTheSignal) { expect_signal_removes_temporary(SIGINT, false); }

TEST(InterruptedRun, SigtermDuringAReplacementKeepsTheOldResultAndRemovesTheTemporary) {
  expect_signal_removes_temporary(SIGTERM, true);
}

}  // namespace
}  // namespace repose
