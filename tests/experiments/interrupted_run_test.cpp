// Safe outputs end to end: a real `repose run` killed (SIGKILL, no chance to
// clean up) while it is writing its run folder must leave no target folder
// (or, when replacing with --force, the old result untouched); a later run
// must succeed, write a complete folder, and remove the killed run's
// leftovers instead of trusting them.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
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

// Starts a run and SIGKILLs it once its temporary folder holds a file, i.e.
// in the middle of writing. False when the run finished first.
bool kill_run_midway(const std::vector<std::string>& args, const fs::path& cwd, const fs::path& target) {
  const pid_t child = start_repose(args, cwd);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (std::chrono::steady_clock::now() < deadline) {
    for (const fs::path& t : temporaries_of(target)) {
      std::error_code ec;
      if (fs::is_directory(t, ec) && !fs::is_empty(t, ec)) {
        ::kill(child, SIGKILL);
        return wait_exit_code(child) == 128 + SIGKILL;
      }
    }
    int status = 0;
    if (::waitpid(child, &status, WNOHANG) == child) return false;  // it finished (or failed) first
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  ::kill(child, SIGKILL);
  wait_exit_code(child);
  return false;
}

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

}  // namespace
}  // namespace repose
