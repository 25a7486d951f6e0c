#include "models/core/base/memory_budget.h"

#include <sys/resource.h>
#include <unistd.h>

#include <atomic>
#include <charconv>
#include <cstdlib>
#include <fstream>
#include <limits>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {
namespace {

constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();
constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;
constexpr const char* kEnvironment = "REPOSE_MEMORY_BUDGET_MB";

// 0: no override.
std::atomic<std::uint64_t> g_override_bytes{0};

std::uint64_t physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return kMax;
  return memory_estimate::product(static_cast<std::uint64_t>(pages), static_cast<std::uint64_t>(page_size));
}

// cgroup v2's limit of this process's group ("max" or absent: none).
std::uint64_t cgroup_limit_bytes() {
  std::ifstream in("/sys/fs/cgroup/memory.max");
  std::string text;
  if (!(in >> text)) return kMax;
  std::uint64_t v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  return ec == std::errc() && end == text.data() + text.size() && v > 0 ? v : kMax;
}

std::uint64_t address_space_limit_bytes() {
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return kMax;
  return static_cast<std::uint64_t>(limit.rlim_cur);
}

struct Budget {
  std::uint64_t bytes;
  std::string source;
};

Budget default_budget() {
  const std::uint64_t physical = physical_memory_bytes();
  const std::uint64_t cgroup = cgroup_limit_bytes();
  const std::uint64_t address_space = address_space_limit_bytes();
  if (address_space < physical && address_space <= cgroup) {
    return {address_space / 2, fmt::format("half of the address-space limit of {} (ulimit -v)", format_bytes(address_space))};
  }
  if (cgroup < physical) return {cgroup / 2, fmt::format("half of this control group's {}", format_bytes(cgroup))};
  return {physical / 2, fmt::format("half of this machine's {}", format_bytes(physical))};
}

Budget current_budget() {
  if (const std::uint64_t bytes = g_override_bytes.load()) return {bytes, "set by the program"};
  if (const char* text = std::getenv(kEnvironment)) {
    const std::string_view v(text);
    std::uint64_t mb = 0;
    const auto [end, ec] = std::from_chars(v.data(), v.data() + v.size(), mb);
    if (v.empty() || ec != std::errc() || end != v.data() + v.size() || mb == 0) {
      throw InputError(fmt::format("{}: expected a positive whole number of megabytes, got '{}'", kEnvironment, v));
    }
    return {memory_estimate::product(mb, kMiB), fmt::format("{}={}", kEnvironment, v)};
  }
  return default_budget();
}

}  // namespace

namespace memory_estimate {

std::uint64_t product(std::uint64_t a, std::uint64_t b) {
  std::uint64_t r = 0;
  return __builtin_mul_overflow(a, b, &r) ? kMax : r;
}

std::uint64_t sum(std::uint64_t a, std::uint64_t b) { return a > kMax - b ? kMax : a + b; }

std::uint64_t grid_bytes(std::uint64_t nx, std::uint64_t ny, std::uint64_t fields, std::uint64_t bytes_per_value) {
  return product(product(nx, ny), product(fields, bytes_per_value));
}

std::uint64_t image_bytes(std::uint64_t width, std::uint64_t height, std::uint64_t bytes_per_pixel) {
  return product(product(width, height), bytes_per_pixel);
}

std::uint64_t triangle_mesh_bytes(std::uint64_t triangles) {
  // three corners of 3 doubles, three int indices, and the welding map's
  // node per corner (key, value and tree links: about 64 bytes)
  constexpr std::uint64_t kPerTriangle = 3 * 3 * sizeof(double) + 3 * sizeof(int) + 3 * 64;
  return product(triangles, kPerTriangle);
}

std::uint64_t items_bytes(std::uint64_t count, std::uint64_t bytes_each) { return product(count, bytes_each); }

}  // namespace memory_estimate

std::string format_bytes(std::uint64_t bytes) {
  if (bytes == kMax) return "more than 16 EB";
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB", "EB"};
  double v = static_cast<double>(bytes);
  int u = 0;
  while (v >= 1024.0 && u < 6) {
    v /= 1024.0;
    ++u;
  }
  return u == 0 ? fmt::format("{} bytes", bytes) : fmt::format("{:.1f} {}", v, units[u]);
}

std::uint64_t memory_budget_bytes() { return current_budget().bytes; }

std::string memory_budget_source() { return current_budget().source; }

void set_memory_budget_bytes(std::optional<std::uint64_t> bytes) {
  g_override_bytes.store(bytes ? std::max<std::uint64_t>(*bytes, 1) : 0);
}

void require_memory(std::uint64_t estimated_bytes, std::string_view what) {
  const Budget budget = current_budget();
  if (estimated_bytes <= budget.bytes) return;
  throw InputError(fmt::format(
      "{} needs about {} of memory, more than the memory budget of {} ({}); reduce the input or raise {}", what,
      format_bytes(estimated_bytes), format_bytes(budget.bytes), budget.source, kEnvironment));
}

}  // namespace repose
