// The runner against stand-in programs (shell scripts taking the same
// arguments as liggghts: -in SCRIPT -log LOG -screen SCREEN), so that every
// failure it must detect can be produced on purpose, without LIGGGHTS.

#include "validation/liggghts/liggghts_runner.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

class LiggghtsRunner : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(dir_ / "in.test") << "# nothing\n"; }

  // A stand-in program whose body runs with $LOG set to the log path.
  LiggghtsRunOptions fake(const std::string& body) {
    const fs::path program = dir_ / "fake_liggghts";
    std::ofstream(program) << "#!/bin/sh\nLOG=$4\necho 'LIGGGHTS (Version fake)' > \"$LOG\"\n" << body << "\n";
    fs::permissions(program, fs::perms::owner_all);
    LiggghtsRunOptions o;
    o.executable = program.string();
    o.nice_increment = 0;
    return o;
  }

  std::string reason_of(const LiggghtsRunOptions& o) {
    try {
      run_liggghts(dir_.string(), "in.test", o);
    } catch (const LiggghtsRunError& e) {
      EXPECT_NE(std::string(e.what()).find(dir_.string()), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("log.liggghts"), std::string::npos) << e.what();
      return e.reason();
    }
    return {};
  }

  test_support::TempDir temp_;
  const fs::path dir_ = temp_.path;
};

const char* kThermo =
    "printf 'Step Atoms KinEng\\n0 10 1.0\\n500 10 0.5\\n\\nStep Atoms KinEng\\n500 10 0.5\\n1000 10 0.1\\nLoop time\\n' >> \"$LOG\"";

TEST_F(LiggghtsRunner, ReadsProgressFromThermoLines) {
  LiggghtsRunOptions o = fake(std::string(kThermo) + "\necho REPOSE_COMPLETE >> \"$LOG\"");
  std::vector<double> fractions;
  o.total_steps = 1000;
  o.progress = [&](double f, std::string_view) { fractions.push_back(f); };
  const LiggghtsRunSummary s = run_liggghts(dir_.string(), "in.test", o);
  EXPECT_EQ(s.last_step, 1000);
  EXPECT_EQ(s.atom_count, 10);
  EXPECT_EQ(s.version, "LIGGGHTS (Version fake)");
  ASSERT_FALSE(fractions.empty());
  EXPECT_DOUBLE_EQ(fractions.back(), 1.0);
  for (std::size_t k = 1; k < fractions.size(); ++k) EXPECT_GE(fractions[k], fractions[k - 1]);
}

TEST_F(LiggghtsRunner, DetectsEachKindOfFailure) {
  EXPECT_NE(reason_of(fake("echo REPOSE_COMPLETE >> \"$LOG\"; exit 3")).find("exit status 3"), std::string::npos);
  EXPECT_NE(reason_of(fake("kill -SEGV $$")).find("signal 11"), std::string::npos);
  EXPECT_NE(reason_of(fake("echo 'ERROR: Lost atoms: original 10 current 9 (thermo.cpp:389)' >> \"$LOG\"; exit 1"))
                .find("\"ERROR: Lost atoms: original 10 current 9"),
            std::string::npos);
  EXPECT_NE(reason_of(fake("echo 'ERROR: Illegal fix command' > screen.txt; exit 1")).find("Illegal fix command"),
            std::string::npos);
  EXPECT_NE(reason_of(fake("echo 'REPOSE_FAILURE: the bed did not settle' >> \"$LOG\"")).find("did not settle"),
            std::string::npos);
  const std::string unfinished = reason_of(fake(kThermo));
  EXPECT_NE(unfinished.find("REPOSE_COMPLETE missing"), std::string::npos) << unfinished;
  // non-finite positions in a dump
  LiggghtsRunOptions o = fake(
      "mkdir -p dumps; printf 'ITEM: TIMESTEP\\n0\\nITEM: NUMBER OF ATOMS\\n1\\nITEM: BOX BOUNDS ff ff ff\\n0 1\\n0 1\\n0 1\\n"
      "ITEM: ATOMS id type x y z radius\\n1 1 0.5 nan 0.5 0.01\\n' > dumps/dump.0.txt\necho REPOSE_COMPLETE >> \"$LOG\"");
  o.dump_directory = "dumps";
  const std::string bad_dump = reason_of(o);
  EXPECT_NE(bad_dump.find("non-finite"), std::string::npos) << bad_dump;
}

TEST_F(LiggghtsRunner, WallClockLimitKillsTheRun) {
  LiggghtsRunOptions o = fake(std::string(kThermo) + "\nsleep 30\necho REPOSE_COMPLETE >> \"$LOG\"");
  o.wall_clock_limit_s = 0.5;
  const auto start = std::chrono::steady_clock::now();
  const std::string reason = reason_of(o);
  const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_NE(reason.find("wall-clock limit"), std::string::npos) << reason;
  EXPECT_LT(waited, 20.0);  // killed, not waited out (the program would sleep 30 s)
}

TEST_F(LiggghtsRunner, MissingProgramOrScriptIsAnInputError) {
  LiggghtsRunOptions o;
  o.executable = "repose-no-such-program";
  EXPECT_THROW(resolve_liggghts_executable(o), InputError);
  EXPECT_THROW(run_liggghts(dir_.string(), "missing.in", fake("true")), InputError);
}

// The run is niced relative to its caller: a caller already at a low
// priority (nice -n 19 repose ...) must not see its run raised to 10.
TEST_F(LiggghtsRunner, NicesTheRunRelativeToItsCaller) {
  errno = 0;
  const int caller = ::nice(5);  // this test's own process: each test runs in its own (gtest_discover_tests)
  ASSERT_EQ(errno, 0);
  LiggghtsRunOptions o = fake("nice > niceness; echo REPOSE_COMPLETE >> \"$LOG\"");
  o.nice_increment = 3;
  run_liggghts(dir_.string(), "in.test", o);
  int run = -100;
  std::ifstream(dir_ / "niceness") >> run;
  EXPECT_EQ(run, std::min(19, caller + 3));
}

// True once `pid` has ended (gone, or a zombie waiting for its new parent).
bool ended(pid_t pid) {
  if (::kill(pid, 0) != 0) return true;
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string pid_field, name, state;
  stat >> pid_field >> name >> state;
  return state == "Z" || state == "X";
}

// The run has its own process group, which a Ctrl-C at the terminal does
// not reach: repose ended by SIGTERM (or SIGINT) must end the run too.
TEST_F(LiggghtsRunner, AnInterruptedRunEndsItsProgramToo) {
  const fs::path pid_file = dir_ / "program.pid";
  const LiggghtsRunOptions o = fake("echo $$ > program.pid.tmp; mv program.pid.tmp program.pid; exec sleep 60");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {  // stands in for repose: runs the program until a signal ends it
    try {
      run_liggghts(dir_.string(), "in.test", o);
    } catch (...) {
    }
    ::_exit(0);
  }
  pid_t program = 0;
  for (int k = 0; k < 100 && program == 0; ++k) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    std::ifstream(pid_file) >> program;
  }
  ASSERT_GT(program, 0) << "the stand-in program never started";
  ::kill(child, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM);
  bool program_ended = false;
  for (int k = 0; k < 60 && !program_ended; ++k) {
    program_ended = ended(program);
    if (!program_ended) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  if (!program_ended) ::kill(program, SIGKILL);  // leave nothing behind
  EXPECT_TRUE(program_ended);
}

}  // namespace
}  // namespace repose
