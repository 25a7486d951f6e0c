#include "models/core/run/interrupt_cleanup.h"

#include <fcntl.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <climits>
#include <csignal>
#include <cstring>
#include <mutex>

#include "models/core/base/error.h"

namespace repose {
namespace {

constexpr int kSlots = 32;
constexpr int kSignals[] = {SIGTERM, SIGINT, SIGHUP};
// Deeper trees are left to the next run's sweep (a run folder is a few levels deep).
constexpr int kMaxDepth = 24;

enum SlotState : int { kFree = 0, kWriting = 1, kReady = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[PATH_MAX] = {0};
};

Slot g_slots[kSlots];
// Process groups of child programs (a LIGGGHTS run) to end with this
// process: each runs in its own group, which a Ctrl-C at the terminal does
// not reach, and would run on for hours.
std::atomic<pid_t> g_groups[kSlots];
// The process that registered the paths: a child forked before exec (which
// inherits the handler) must not remove its parent's folders.
std::atomic<pid_t> g_owner{0};

// The layout of a record getdents64 returns (linux_dirent64).
struct DirentRecord {
  std::uint64_t inode;
  std::int64_t offset;
  unsigned short length;
  unsigned char type;
  char name[1];
};

bool is_dot_or_dot_dot(const char* name) {
  return name[0] == '.' && (name[1] == '\0' || (name[1] == '.' && name[2] == '\0'));
}

// Removes `name` under the directory `dir_fd`, recursively, with system
// calls only. Best effort: what cannot be removed stays for the next sweep.
void remove_tree_at(int dir_fd, const char* name, int depth) {
  if (::unlinkat(dir_fd, name, 0) == 0 || (errno != EISDIR && errno != EPERM)) return;
  if (depth > kMaxDepth) return;
  const int fd = ::openat(dir_fd, name, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  // entries may be missed while their directory shrinks: read it again until empty
  for (int pass = 0; pass < 8; ++pass) {
    alignas(8) char buffer[2048];
    ::lseek(fd, 0, SEEK_SET);
    for (;;) {
      const long n = ::syscall(SYS_getdents64, fd, buffer, sizeof buffer);
      if (n <= 0) break;
      for (long at = 0; at < n;) {
        const auto* record = reinterpret_cast<const DirentRecord*>(buffer + at);
        at += record->length;
        if (!is_dot_or_dot_dot(record->name)) remove_tree_at(fd, record->name, depth + 1);
      }
    }
    if (::unlinkat(dir_fd, name, AT_REMOVEDIR) == 0 || errno != ENOTEMPTY) break;
  }
  ::close(fd);
}

extern "C" void remove_temporaries_and_die(int signal_number) {
  const int saved_errno = errno;
  if (g_owner.load() == ::getpid()) {
    for (std::atomic<pid_t>& group : g_groups) {
      const pid_t g = group.load(std::memory_order_acquire);
      if (g > 0) ::kill(-g, SIGTERM);
    }
    for (Slot& slot : g_slots) {
      if (slot.state.load(std::memory_order_acquire) == kReady) remove_tree_at(AT_FDCWD, slot.path, 0);
    }
  }
  // die of the same signal: default action, raised again; it is delivered
  // when this handler returns and unblocks it
  struct sigaction default_action {};
  default_action.sa_handler = SIG_DFL;
  sigemptyset(&default_action.sa_mask);
  ::sigaction(signal_number, &default_action, nullptr);
  ::raise(signal_number);
  errno = saved_errno;
}

void install_handlers() {
  for (const int s : kSignals) {
    struct sigaction previous {};
    if (::sigaction(s, nullptr, &previous) != 0) continue;
    if (previous.sa_handler == SIG_IGN) continue;  // inherited as ignored: stay so (nohup, background jobs)
    struct sigaction action {};
    action.sa_handler = remove_temporaries_and_die;
    sigemptyset(&action.sa_mask);
    for (const int other : kSignals) sigaddset(&action.sa_mask, other);  // one cleanup at a time
    ::sigaction(s, &action, nullptr);
  }
}

void own_handlers() {
  static std::once_flag installed;
  g_owner.store(::getpid());
  std::call_once(installed, install_handlers);
}

}  // namespace

int remove_on_interrupt(const std::filesystem::path& path) {
  own_handlers();
  const std::string absolute = std::filesystem::absolute(path).lexically_normal().string();
  if (absolute.size() >= PATH_MAX) return -1;
  for (int k = 0; k < kSlots; ++k) {
    int expected = kFree;
    if (!g_slots[k].state.compare_exchange_strong(expected, kWriting)) continue;
    std::memcpy(g_slots[k].path, absolute.c_str(), absolute.size() + 1);
    g_slots[k].state.store(kReady, std::memory_order_release);
    return k;
  }
  return -1;
}

void forget_on_interrupt(int slot) {
  if (slot < 0) return;
  REPOSE_DEMAND(slot < kSlots);
  g_slots[slot].state.store(kFree, std::memory_order_release);
}

int end_group_on_interrupt(pid_t process_group) {
  REPOSE_DEMAND(process_group > 0);
  own_handlers();
  for (int k = 0; k < kSlots; ++k) {
    pid_t expected = 0;
    if (g_groups[k].compare_exchange_strong(expected, process_group, std::memory_order_acq_rel)) return k;
  }
  return -1;
}

void forget_group_on_interrupt(int slot) {
  if (slot < 0) return;
  REPOSE_DEMAND(slot < kSlots);
  g_groups[slot].store(0, std::memory_order_release);
}

}  // namespace repose
