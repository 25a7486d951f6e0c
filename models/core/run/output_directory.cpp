#include "models/core/run/output_directory.h"

#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <random>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <sys/stat.h>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/run/interrupt_cleanup.h"

namespace repose {
namespace fs = std::filesystem;
namespace {

// "runs/a/" and "runs/a" name the same folder; the name must not be empty.
fs::path normalised_target(const std::string& target) {
  fs::path path = fs::path(target).lexically_normal();
  if (path.has_filename() == false && path.has_parent_path()) path = path.parent_path();
  if (path.empty() || path.filename() == "." || path.filename() == "..") {
    throw InputError(fmt::format("{}: not a usable output folder name", target));
  }
  return path;
}

fs::path parent_of(const fs::path& target) {
  return target.has_parent_path() ? target.parent_path() : fs::path(".");
}

// `parent/.NAME.KIND-PID-XXXXXX` with a random suffix.
fs::path sibling_name(const fs::path& target, std::string_view kind) {
  static const char kDigits[] = "abcdefghijklmnopqrstuvwxyz0123456789";
  std::random_device random;
  std::string suffix(6, 'x');
  for (char& c : suffix) c = kDigits[random() % (sizeof kDigits - 1)];
  return parent_of(target) / fmt::format(".{}.{}-{}-{}", target.filename().string(), kind, ::getpid(), suffix);
}

// Creates a fresh sibling with `create` (false on EEXIST, to try another name).
// mkdir/open with modes 0777/0666 let the umask decide, as for any other output.
fs::path make_sibling(const fs::path& target, std::string_view kind, bool (*create)(const fs::path&)) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const fs::path path = sibling_name(target, kind);
    if (create(path)) return path;
    if (errno != EEXIST) break;
  }
  throw InputError(fmt::format("{}: cannot create a temporary beside it: {}", target.string(), std::strerror(errno)));
}

bool create_directory(const fs::path& path) { return ::mkdir(path.c_str(), 0777) == 0; }

bool create_file(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) return false;
  ::close(fd);
  return true;
}

bool process_is_gone(long pid) { return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH; }

// Removes `.NAME.tmp-PID-*` and `.NAME.old-PID-*` (folders or files) left by
// processes that no longer run.
void remove_stale_siblings(const fs::path& target) {
  std::error_code ec;
  for (const auto& kind : {"tmp", "old"}) {
    const std::string prefix = fmt::format(".{}.{}-", target.filename().string(), kind);
    for (const auto& entry : fs::directory_iterator(parent_of(target), ec)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind(prefix, 0) != 0) continue;
      char* end = nullptr;
      const long pid = std::strtol(name.c_str() + prefix.size(), &end, 10);
      if (end == name.c_str() + prefix.size() || *end != '-' || pid <= 0) continue;
      if (process_is_gone(pid)) fs::remove_all(entry.path(), ec);
    }
  }
}

void check_target_may_be_written(const fs::path& target, bool force) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(target, ec);
  if (!fs::exists(status)) return;
  if (!fs::is_directory(status)) {
    throw InputError(fmt::format("{}: exists and is not a directory; choose another --out", target.string()));
  }
  if (!force && !fs::is_empty(target, ec)) {
    throw InputError(fmt::format("{}: output folder is not empty; pass --force to replace it", target.string()));
  }
}

void rename_or_throw(const fs::path& from, const fs::path& to) {
  std::error_code ec;
  fs::rename(from, to, ec);
  if (ec) {
    throw std::runtime_error(fmt::format("cannot rename {} to {}: {}", from.string(), to.string(), ec.message()));
  }
}

}  // namespace

OutputDirectory OutputDirectory::open(const std::string& target_text, bool force) {
  const fs::path target = normalised_target(target_text);
  check_target_may_be_written(target, force);
  std::error_code ec;
  fs::create_directories(parent_of(target), ec);
  if (ec) {
    throw InputError(fmt::format("{}: cannot create its parent folder: {}", target.string(), ec.message()));
  }
  remove_stale_siblings(target);
  return OutputDirectory(target, make_sibling(target, "tmp", create_directory), force);
}

OutputDirectory::OutputDirectory(fs::path target, fs::path temporary, bool force)
    : target_(std::move(target)),
      temporary_(std::move(temporary)),
      force_(force),
      interrupt_slot_(remove_on_interrupt(temporary_)) {}

OutputDirectory::OutputDirectory(OutputDirectory&& other) noexcept
    : target_(std::move(other.target_)),
      temporary_(std::move(other.temporary_)),
      force_(other.force_),
      committed_(other.committed_),
      interrupt_slot_(std::exchange(other.interrupt_slot_, -1)) {
  other.temporary_.clear();
}

OutputDirectory::~OutputDirectory() {
  if (temporary_.empty()) return;
  std::error_code ec;  // best effort: a destructor must not throw
  fs::remove_all(temporary_, ec);
  forget_on_interrupt(interrupt_slot_);
}

std::string OutputDirectory::path(std::string_view name) const {
  REPOSE_DEMAND(!temporary_.empty());
  const fs::path relative = fs::path(name).lexically_normal();
  REPOSE_DEMAND(relative.is_relative() && !relative.empty());
  REPOSE_DEMAND(*relative.begin() != "..");
  const fs::path full = temporary_ / relative;
  if (relative.has_parent_path()) fs::create_directories(full.parent_path());
  return full.string();
}

void OutputDirectory::commit() {
  REPOSE_DEMAND(!committed_ && !temporary_.empty());
  std::error_code ec;
  if (fs::exists(fs::symlink_status(target_, ec))) {
    // Checked again: the target may have changed since open().
    check_target_may_be_written(target_, force_);
    const fs::path aside = make_sibling(target_, "old", create_directory);
    rename_or_throw(target_, aside);  // onto the empty `aside` directory (POSIX rename)
    try {
      rename_or_throw(temporary_, target_);
    } catch (...) {
      fs::rename(aside, target_, ec);  // put the old result back
      throw;
    }
    fs::remove_all(aside, ec);
  } else {
    rename_or_throw(temporary_, target_);
  }
  temporary_.clear();
  forget_on_interrupt(std::exchange(interrupt_slot_, -1));
  committed_ = true;
}

void write_file_atomically(const std::string& path, const std::function<void(const std::string&)>& write) {
  const fs::path target(path);
  if (fs::is_directory(target)) throw InputError(fmt::format("{}: is a directory, expected a file name", path));
  remove_stale_siblings(target);
  const std::string temporary = make_sibling(target, "tmp", create_file).string();
  const int slot = remove_on_interrupt(temporary);
  try {
    write(temporary);
    rename_or_throw(temporary, target);
  } catch (...) {
    std::error_code ec;
    fs::remove(temporary, ec);
    forget_on_interrupt(slot);
    throw;
  }
  forget_on_interrupt(slot);
}

}  // namespace repose
