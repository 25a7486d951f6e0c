#pragma once
// Runs the real `repose` program (REPOSE_BINARY, defined by tests/CMakeLists.txt)
// as a subprocess in a given folder. stdout and stderr are captured in files
// outside that folder, so the folder shows exactly what the program wrote.

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/temp_dir.h"

namespace repose::test_support {

struct ProgramResult {
  int exit_code = -1;  // 128 + signal when killed
  std::string out;
  std::string err;
};

// Starts REPOSE_BINARY with args in cwd, stdout and stderr to the given files
// ("/dev/null" to drop them). Returns the child's pid.
inline pid_t start_repose(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                          const std::string& out_path = "/dev/null", const std::string& err_path = "/dev/null") {
  const pid_t child = ::fork();
  if (child < 0) throw std::runtime_error("fork failed");
  if (child == 0) {
    const int out = ::open(out_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open(err_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out < 0 || err < 0 || ::dup2(out, 1) < 0 || ::dup2(err, 2) < 0 || ::chdir(cwd.c_str()) != 0) ::_exit(126);
    std::vector<char*> argv;
    argv.push_back(const_cast<char*>(REPOSE_BINARY));
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(REPOSE_BINARY, argv.data());
    ::_exit(127);
  }
  return child;
}

inline int wait_exit_code(pid_t child) {
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

inline ProgramResult run_repose(const std::vector<std::string>& args, const std::filesystem::path& cwd) {
  TempDir capture("repose_capture");
  const std::string out_path = (capture.path / "out").string();
  const std::string err_path = (capture.path / "err").string();
  ProgramResult result;
  result.exit_code = wait_exit_code(start_repose(args, cwd, out_path, err_path));
  result.out = read_all(out_path);
  result.err = read_all(err_path);
  return result;
}

}  // namespace repose::test_support
