#pragma once
// A fresh folder under the system temp directory, named after the running
// test and process, removed (with whatever a test left in it, even without
// write permission) when it goes out of scope. Every test's temporary files
// go in one: `ctest -j` runs tests of one program at once, and the normal and
// sanitized builds' suites may run side by side, so no fixed name is safe.

#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

namespace repose::test_support {

// "<Suite>_<Test>_<pid>" of the running GoogleTest test ("no_test_<pid>"
// outside one), usable in a file name: characters other than letters, digits,
// '-' and '_' become '_' (a parameterized test's name holds '/'), and the test's
// part is cut to 120 characters (the folder's random suffix keeps it unique).
inline std::string current_test_file_name() {
  const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = test == nullptr ? "no_test" : std::string(test->test_suite_name()) + "_" + test->name();
  for (char& c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '-') c = '_';
  }
  if (name.size() > 120) name.resize(120);
  return name + "_" + std::to_string(::getpid());
}

// <temp>/<prefix>_<Suite>_<Test>_<pid>_XXXXXX, made by mkdtemp: no other test,
// process or TempDir has it.
struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const std::string& prefix = "repose") {
    const std::string name = prefix + "_" + current_test_file_name() + "_XXXXXX";
    std::string pattern = (std::filesystem::temp_directory_path() / name).string();
    if (::mkdtemp(pattern.data()) == nullptr) {
      throw std::runtime_error("cannot make a temporary folder " + pattern + ": " + std::strerror(errno));
    }
    path = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    std::filesystem::permissions(path, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
    std::filesystem::remove_all(path, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
};

inline std::string read_all(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

inline void write_all(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// A GoogleTest fixture with a fresh folder per test: path("x.npy") names a file in it.
class TempDirTest : public ::testing::Test {
 protected:
  std::string path(const std::string& name) const { return (dir_.path / name).string(); }
  TempDir dir_;
};

}  // namespace repose::test_support
