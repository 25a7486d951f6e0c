#include "models/core/io/input_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <string>

#include "models/core/base/error.h"
#include "models/core/io/mesh_io.h"
#include "models/core/io/npy_io.h"
#include "models/core/io/png_io.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

class InputFileTest : public test_support::TempDirTest {};

using test_support::write_all;

constexpr InputKind kSmall{"test", 16};

// The one-line message `read` throws, or "" when it does not throw. A read
// that blocks (the FIFO bug) is unblocked by opening the FIFO's write end
// after a generous delay, so the test fails instead of hanging.
std::string error_of(const std::function<void()>& read, const std::string& fifo_to_unblock = "") {
  auto result = std::async(std::launch::async, [&read]() -> std::string {
    try {
      read();
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  });
  if (!fifo_to_unblock.empty() && result.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
    const int fd = ::open(fifo_to_unblock.c_str(), O_WRONLY | O_NONBLOCK);
    ADD_FAILURE() << "reading a FIFO blocked (waited for a writer)";
    if (fd >= 0) ::close(fd);
  }
  return result.get();
}

void expect_one_line_naming(const std::string& message, const std::string& path, const std::string& reason) {
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_NE(message.find(reason), std::string::npos) << message << "\nexpected: " << reason;
  EXPECT_EQ(std::count(message.begin(), message.end(), '\n'), 0) << message;
}

TEST_F(InputFileTest, ReadsARegularFileWhole) {
  write_all(path("a.txt"), "hello\nworld\n");
  EXPECT_EQ(read_input_file(path("a.txt"), kSmall), "hello\nworld\n");
}

TEST_F(InputFileTest, FifoFailsAtOnceForEveryReader) {
  const std::string fifo = path("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::vector<std::function<void()>> readers = {
      [&] { (void)read_input_file(fifo, input_kind::kCalibration); },
      [&] { InputStream in(fifo, input_kind::kLiggghtsDump); },
      [&] { (void)read_npy_2d(fifo); },
      [&] { (void)read_png16(fifo); },
      [&] { (void)read_mesh(fifo + ".obj"); },
  };
  ASSERT_EQ(::mkfifo((fifo + ".obj").c_str(), 0600), 0);
  for (std::size_t k = 0; k < readers.size(); ++k) {
    const std::string message = error_of(readers[k], k == 4 ? fifo + ".obj" : fifo);
    expect_one_line_naming(message, "pipe", "is a FIFO (named pipe), not a regular");
  }
}

TEST_F(InputFileTest, DevZeroFailsAtOnceAsACharacterDevice) {
  // before the check, /dev/zero was read until memory ran out
  const std::string message = error_of([] { (void)read_input_file("/dev/zero", input_kind::kCalibration); });
  expect_one_line_naming(message, "/dev/zero", "is a character device, not a regular calibration file");
  expect_one_line_naming(error_of([] { (void)read_npy_2d("/dev/zero"); }), "/dev/zero", "character device");
  expect_one_line_naming(error_of([] { (void)read_png16("/dev/zero"); }), "/dev/zero", "character device");
}

TEST_F(InputFileTest, DirectoryIsRefusedByName) {
  fs::create_directory(path("folder"));
  expect_one_line_naming(error_of([&] { (void)read_input_file(path("folder"), input_kind::kScene); }), "folder",
                         "is a directory, not a scene file");
}

TEST_F(InputFileTest, OversizeFileIsRefusedBeforeReading) {
  write_all(path("big.yaml"), std::string(17, 'x'));
  expect_one_line_naming(error_of([&] { (void)read_input_file(path("big.yaml"), kSmall); }), "big.yaml",
                         "is 17 bytes, more than a test file may have (16 bytes)");
  write_all(path("fits.yaml"), std::string(16, 'x'));
  EXPECT_EQ(read_input_file(path("fits.yaml"), kSmall).size(), 16u);
}

TEST_F(InputFileTest, NeverReadsPastTheSizeFoundAtOpenEvenWhenTheFileGrows) {
  write_all(path("growing.txt"), "0123456789");
  InputFile f = InputFile::open(path("growing.txt"), kSmall);
  EXPECT_EQ(f.size(), 10u);
  std::ofstream(path("growing.txt"), std::ios::app) << std::string(1000, 'y');
  const std::string text = f.read_rest();
  EXPECT_EQ(text, "0123456789");
  char more = 0;
  EXPECT_EQ(f.read(&more, 1), 0u);
}

TEST_F(InputFileTest, StreamEndsAtTheSizeFoundAtOpen) {
  write_all(path("lines.txt"), "a\nb\n");
  InputStream in(path("lines.txt"), kSmall);
  std::ofstream(path("lines.txt"), std::ios::app) << "c\nd\n";
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  EXPECT_EQ(lines, (std::vector<std::string>{"a", "b"}));
}

// What root cannot read either: a path through a file (not a directory), a
// missing file. (chmod 000 is no test as root, who reads any file.)
TEST_F(InputFileTest, UnreadablePathsNameTheReason) {
  write_all(path("plain"), "x");
  expect_one_line_naming(error_of([&] { (void)read_input_file(path("plain") + "/scene.yaml", kSmall); }),
                         "plain/scene.yaml", "a part of the path is not a directory");
  expect_one_line_naming(error_of([&] { (void)read_input_file(path("missing.yaml"), kSmall); }), "missing.yaml",
                         "no such file");
}

TEST_F(InputFileTest, PermissionDeniedWhenNotRoot) {
  write_all(path("locked"), "x");
  fs::permissions(path("locked"), fs::perms::none);
  const std::string message = error_of([&] { (void)read_input_file(path("locked"), kSmall); });
  if (::geteuid() == 0) {
    EXPECT_EQ(message, "") << "root reads a chmod 000 file";
  } else {
    expect_one_line_naming(message, "locked", "cannot be read: permission denied");
  }
}

TEST_F(InputFileTest, RequireRegularFileUsesTheKindsBound) {
  write_all(path("scene.yaml"), std::string(100, ' '));
  EXPECT_NO_THROW(require_regular_file(path("scene.yaml"), "scene"));
  EXPECT_THROW(require_regular_file(path("scene.yaml"), kSmall), InputError);
  EXPECT_THROW(require_regular_file("/dev/zero", "scene"), InputError);
}

}  // namespace
}  // namespace repose
