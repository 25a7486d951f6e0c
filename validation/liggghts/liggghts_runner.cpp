#include "validation/liggghts/liggghts_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <sstream>
#include <thread>
#include <vector>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/run/interrupt_cleanup.h"
#include "validation/liggghts/liggghts_dump.h"
#include "validation/liggghts/liggghts_script.h"

namespace repose {

namespace fs = std::filesystem;

LiggghtsRunError::LiggghtsRunError(std::string run_dir, std::string log_path, std::string reason)
    : std::runtime_error(fmt::format("LIGGGHTS run in {} failed (log: {}): {}", run_dir, log_path, reason)),
      run_dir_(std::move(run_dir)),
      log_path_(std::move(log_path)),
      reason_(std::move(reason)) {}

namespace {

constexpr const char* kLogFile = "log.liggghts";
constexpr const char* kScreenFile = "screen.txt";
constexpr const char* kStdoutFile = "stdout.txt";

bool is_executable_file(const fs::path& p) {
  std::error_code ec;
  return fs::is_regular_file(p, ec) && ::access(p.c_str(), X_OK) == 0;
}

std::vector<std::string> read_lines(const fs::path& path) {
  std::vector<std::string> lines;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Thermo progress read incrementally from the growing log file: a data line
// is one whose first token is an integer, following a header starting "Step".
class ThermoFollower {
 public:
  explicit ThermoFollower(fs::path log) : log_(std::move(log)) {}

  void poll() {
    std::ifstream in(log_, std::ios::binary);
    if (!in) return;
    in.seekg(static_cast<std::streamoff>(offset_));
    std::string chunk((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::size_t end = chunk.rfind('\n');
    if (end == std::string::npos) return;
    offset_ += end + 1;
    std::istringstream lines(chunk.substr(0, end + 1));
    for (std::string line; std::getline(lines, line);) consume(line);
  }

  long last_step = 0;
  long atom_count = 0;

 private:
  void consume(const std::string& line) {
    std::istringstream words(line);
    std::string first;
    if (!(words >> first)) {
      in_thermo_ = false;
      return;
    }
    if (first == "Step") {
      in_thermo_ = true;
      std::string col;
      atoms_column_ = -1;
      for (int k = 1; words >> col; ++k) {
        if (col == "Atoms") atoms_column_ = k;
      }
      return;
    }
    if (!in_thermo_) return;
    char* end = nullptr;
    const long step = std::strtol(first.c_str(), &end, 10);
    if (end == first.c_str() || *end != '\0') {
      in_thermo_ = false;
      return;
    }
    last_step = step;
    std::string col;
    for (int k = 1; words >> col; ++k) {
      if (k == atoms_column_) atom_count = std::strtol(col.c_str(), nullptr, 10);
    }
  }

  fs::path log_;
  std::size_t offset_ = 0;
  bool in_thermo_ = false;
  int atoms_column_ = -1;
};

// The first line that reports an error, quoted, or empty.
std::string first_error_line(const fs::path& path) {
  for (const std::string& line : read_lines(path)) {
    if (line.rfind("ERROR", 0) == 0 || line.find("Lost atoms") != std::string::npos ||
        line.rfind(kFailureMarker, 0) == 0) {
      return line;
    }
  }
  return {};
}

bool has_line_starting(const fs::path& path, const std::string& prefix) {
  for (const std::string& line : read_lines(path)) {
    if (line.rfind(prefix, 0) == 0) return true;
  }
  return false;
}

std::string first_line(const fs::path& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

struct ChildExit {
  bool killed_by_limit = false;
  int status = 0;
  double cpu_time_s = 0.0;
};

double cpu_seconds(const struct rusage& u) {
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// fork + exec with the working directory, priority and output files set in
// the child (only async-signal-safe calls between fork and exec).
pid_t spawn(const std::string& executable, const std::vector<std::string>& args, const std::string& dir,
            int nice_increment) {
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(executable.c_str()));
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error(fmt::format("cannot start {}: fork failed: {}", executable, std::strerror(errno)));
  if (pid == 0) {
    ::setpgid(0, 0);  // own process group, so a limit kills everything it started
    if (::chdir(dir.c_str()) != 0) ::_exit(126);
    // Lowered relative to the caller's priority: setpriority sets an absolute
    // value, which for a caller already niced above it (and run as root)
    // raised the run's priority back to nice_increment.
    if (nice_increment > 0) {
      errno = 0;
      const int current = ::getpriority(PRIO_PROCESS, 0);
      if (errno == 0) ::setpriority(PRIO_PROCESS, 0, std::min(19, current + nice_increment));
    }
    const int out = ::open(kStdoutFile, O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int in = ::open("/dev/null", O_RDONLY);
    if (out >= 0) {
      ::dup2(out, STDOUT_FILENO);
      ::dup2(out, STDERR_FILENO);
    }
    if (in >= 0) ::dup2(in, STDIN_FILENO);
    ::execv(executable.c_str(), argv.data());
    ::_exit(127);
  }
  ::setpgid(pid, pid);  // also from the parent, so the group exists before any kill
  return pid;
}

// Registered while the run lives: SIGINT, SIGTERM or SIGHUP to repose ends
// the run's process group too (interrupt_cleanup.h).
class GroupEndedOnInterrupt {
 public:
  explicit GroupEndedOnInterrupt(pid_t group) : slot_(end_group_on_interrupt(group)) {}
  ~GroupEndedOnInterrupt() { forget_group_on_interrupt(slot_); }
  GroupEndedOnInterrupt(const GroupEndedOnInterrupt&) = delete;
  GroupEndedOnInterrupt& operator=(const GroupEndedOnInterrupt&) = delete;

 private:
  int slot_;
};

void kill_group(pid_t pid) {
  ::kill(-pid, SIGTERM);
  for (int k = 0; k < 20; ++k) {
    int status = 0;
    if (::waitpid(pid, &status, WNOHANG) == pid) {
      ::kill(-pid, SIGKILL);  // stragglers of the group
      return;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ::kill(-pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
}

std::string describe_status(int status) {
  if (WIFEXITED(status)) return fmt::format("exit status {}", WEXITSTATUS(status));
  if (WIFSIGNALED(status)) return fmt::format("killed by signal {} ({})", WTERMSIG(status), strsignal(WTERMSIG(status)));
  return "unknown termination";
}

void check_dumps(const fs::path& dir, const std::string& run_dir, const std::string& log) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (!entry.is_regular_file()) continue;
    try {
      (void)read_dump_file(entry.path().string());  // refuses NaN/inf positions, truncation
    } catch (const InputError& e) {
      throw LiggghtsRunError(run_dir, log, fmt::format("bad dump: {}", e.what()));
    }
  }
}

}  // namespace

std::string resolve_liggghts_executable(const LiggghtsRunOptions& options) {
  std::string name = options.executable;
#ifdef REPOSE_LIGGGHTS_EXECUTABLE
  if (name.empty()) name = REPOSE_LIGGGHTS_EXECUTABLE;
#endif
  if (name.empty()) name = "liggghts";
  if (name.find('/') != std::string::npos) {
    if (!is_executable_file(name)) throw InputError(fmt::format("liggghts: {}: not an executable file", name));
    return name;
  }
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string d; std::getline(dirs, d, ':');) {
    const fs::path candidate = fs::path(d.empty() ? "." : d) / name;
    if (is_executable_file(candidate)) return candidate.string();
  }
  throw InputError(fmt::format("liggghts: '{}' not found on PATH; install the liggghts package "
                               "(scripts/install-deps.sh) or give its path",
                               name));
}

std::string liggghts_version(const std::string& executable) {
  static std::mutex mutex;
  static std::map<std::string, std::string> known;
  std::lock_guard lock(mutex);
  if (auto it = known.find(executable); it != known.end()) return it->second;
  char pattern[] = "/tmp/repose-liggghts-version-XXXXXX";
  const char* dir = ::mkdtemp(pattern);
  if (!dir) throw std::runtime_error(fmt::format("cannot create a temporary directory: {}", std::strerror(errno)));
  std::ofstream(fs::path(dir) / "empty.in") << "\n";
  const pid_t pid = spawn(executable, {"-in", "empty.in", "-log", "none", "-screen", kScreenFile}, dir, 0);
  int status = 0;
  ::waitpid(pid, &status, 0);
  const std::string version = first_line(fs::path(dir) / kScreenFile);
  fs::remove_all(dir);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0 || version.rfind("LIGGGHTS", 0) != 0) {
    throw std::runtime_error(fmt::format("{} did not print its version ({})", executable, describe_status(status)));
  }
  known[executable] = version;
  return version;
}

LiggghtsRunSummary run_liggghts(const std::string& run_dir, const std::string& script_name,
                                const LiggghtsRunOptions& options) {
  const std::string executable = resolve_liggghts_executable(options);
  const fs::path dir(run_dir);
  const fs::path log = dir / kLogFile;
  if (!fs::is_regular_file(dir / script_name)) {
    throw InputError(fmt::format("{}: no such script", (dir / script_name).string()));
  }
  // outputs of an earlier run in the same directory must not be read as this run's
  for (const char* file : {kLogFile, kScreenFile, kStdoutFile}) fs::remove(dir / file);

  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = spawn(executable, {"-in", script_name, "-log", kLogFile, "-screen", kScreenFile}, run_dir,
                          options.nice_increment);
  const GroupEndedOnInterrupt interrupt_guard(pid);  // a Ctrl-C ends the run with repose
  ThermoFollower thermo(log);
  ChildExit exit;
  for (;;) {
    struct rusage usage {};
    const pid_t done = ::wait4(pid, &exit.status, WNOHANG, &usage);
    if (done == pid) exit.cpu_time_s = cpu_seconds(usage);
    thermo.poll();
    if (options.total_steps > 0) {
      report(options.progress, std::min(1.0, static_cast<double>(thermo.last_step) / options.total_steps),
             "liggghts");
    }
    if (done == pid) break;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (options.wall_clock_limit_s > 0 && elapsed > options.wall_clock_limit_s) {
      kill_group(pid);
      exit.killed_by_limit = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  thermo.poll();

  LiggghtsRunSummary summary;
  summary.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  summary.cpu_time_s = exit.cpu_time_s;
  summary.last_step = thermo.last_step;
  summary.atom_count = thermo.atom_count;
  summary.version = first_line(log);

  const std::string log_name = log.string();
  if (exit.killed_by_limit) {
    throw LiggghtsRunError(run_dir, log_name,
                           fmt::format("killed after the wall-clock limit of {} s (at step {})",
                                       options.wall_clock_limit_s, thermo.last_step));
  }
  for (const char* file : {kLogFile, kScreenFile, kStdoutFile}) {
    const std::string error = first_error_line(dir / file);
    if (!error.empty()) throw LiggghtsRunError(run_dir, log_name, fmt::format("\"{}\"", error));
  }
  if (!WIFEXITED(exit.status) || WEXITSTATUS(exit.status) != 0) {
    std::string reason = describe_status(exit.status);
    if (WIFEXITED(exit.status) && WEXITSTATUS(exit.status) == 127) reason += fmt::format(" (cannot execute {})", executable);
    throw LiggghtsRunError(run_dir, log_name, reason);
  }
  if (options.expect_complete_marker && !has_line_starting(log, kCompleteMarker)) {
    throw LiggghtsRunError(run_dir, log_name, fmt::format("the script did not reach its end ({} missing)", kCompleteMarker));
  }
  if (!options.dump_directory.empty()) check_dumps(dir / options.dump_directory, run_dir, log_name);
  report(options.progress, 1.0, "liggghts");
  return summary;
}

}  // namespace repose
