// The cases through the real program: a FIFO given as the
// calibration file waited forever for a writer, /dev/zero was read until
// memory ran out (4.2 GB, bad_alloc, exit 1). Both must fail at once with
// exit 2 and one line naming the file and the reason, and write nothing.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <string>

#include "tests/support/run_repose.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

struct TempDir : test_support::TempDir {
  TempDir() : test_support::TempDir("repose_calibration_input") {}
};

// Runs `repose calibrate FILE --out out`; a run that blocks is failed and
// unblocked (a writer opened and closed on the FIFO) instead of hanging.
test_support::ProgramResult calibrate(const std::string& file, const fs::path& cwd) {
  auto result = std::async(std::launch::async,
                           [&] { return test_support::run_repose({"calibrate", file, "--out", "out"}, cwd); });
  if (result.wait_for(std::chrono::seconds(60)) != std::future_status::ready) {
    ADD_FAILURE() << "repose calibrate " << file << " blocked";
    const int fd = ::open(file.c_str(), O_WRONLY | O_NONBLOCK);
    if (fd >= 0) ::close(fd);
  }
  return result.get();
}

void expect_refused(const test_support::ProgramResult& r, const fs::path& cwd, const std::string& file,
                    const std::string& reason) {
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  EXPECT_NE(r.err.find(file + ": " + reason), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(cwd)) << "wrote into the working folder";
}

TEST(CalibrationInputFile, FifoFailsAtOnce) {
  TempDir dir;
  TempDir cwd;
  const std::string fifo = (dir.path / "calibration.yaml").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  expect_refused(calibrate(fifo, cwd.path), cwd.path, fifo, "is a FIFO (named pipe), not a regular calibration file");
}

TEST(CalibrationInputFile, DevZeroFailsAtOnce) {
  TempDir cwd;
  expect_refused(calibrate("/dev/zero", cwd.path), cwd.path, "/dev/zero",
                 "is a character device, not a regular calibration file");
}

TEST(CalibrationInputFile, OversizeFileIsRefusedBeforeReading) {
  TempDir dir;
  TempDir cwd;
  const fs::path big = dir.path / "big.yaml";
  std::ofstream(big).close();
  fs::resize_file(big, 17u << 20);  // 17 MiB of zeros, sparse
  expect_refused(calibrate(big.string(), cwd.path), cwd.path, big.string(),
                 "is 17825792 bytes, more than a calibration file may have");
}

}  // namespace
}  // namespace repose
