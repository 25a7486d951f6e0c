#pragma once
// How much memory a run may use, and estimates of what it will need, so
// that an input that would need too much is refused before anything is
// allocated, with the estimate and the budget in the message, instead of
// ending in std::bad_alloc or the OOM killer after minutes.
//
// The budget, in order of precedence:
//   1. set_memory_budget_bytes(bytes)   (tests, embedding programs)
//   2. REPOSE_MEMORY_BUDGET_MB=N        (environment, N > 0 megabytes of 2^20 bytes)
//   3. half of the memory this process can have: the smallest of physical
//      memory (sysconf), the cgroup v2 limit (/sys/fs/cgroup/memory.max) and
//      the address-space limit (RLIMIT_AS, ulimit -v)
//
// Usage (scene loader, solvers, readers): estimate, then demand, then allocate.
//
//   const std::uint64_t need = memory_estimate::grid_bytes(nx, ny, 6);  // 6 double fields
//   require_memory(need, "the ground grid of 8192 x 8192 cells");
//   // -> InputError "the ground grid of 8192 x 8192 cells needs about 3.2 GB of
//   //    memory, more than the memory budget of 2.0 GB (REPOSE_MEMORY_BUDGET_MB=2048)"
//
// Estimates add up with saturating arithmetic: an absurd count gives
// UINT64_MAX (always refused), never an overflowed small number. They count
// the large arrays only (what grows with the input), not the program itself.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace repose {

// Bytes needed by the large arrays of common shapes; saturating.
namespace memory_estimate {
// a * b, or UINT64_MAX when it overflows.
std::uint64_t product(std::uint64_t a, std::uint64_t b);
// a + b, or UINT64_MAX when it overflows.
std::uint64_t sum(std::uint64_t a, std::uint64_t b);
// `fields` arrays of nx x ny values of bytes_per_value each (a height field
// and its scratch copies: doubles by default).
std::uint64_t grid_bytes(std::uint64_t nx, std::uint64_t ny, std::uint64_t fields,
                         std::uint64_t bytes_per_value = sizeof(double));
// An image of width x height pixels of bytes_per_pixel (RGB8: 3, depth float: 4).
std::uint64_t image_bytes(std::uint64_t width, std::uint64_t height, std::uint64_t bytes_per_pixel);
// An indexed triangle mesh read from a file: per triangle three double
// vertices (as read, before welding) and three int indices.
std::uint64_t triangle_mesh_bytes(std::uint64_t triangles);
// `count` items (particles, objects, rows) of bytes_each.
std::uint64_t items_bytes(std::uint64_t count, std::uint64_t bytes_each);
}  // namespace memory_estimate

// "512 kB", "3.4 GB" (powers of 1024, one decimal).
std::string format_bytes(std::uint64_t bytes);

// The budget in bytes, as described above. Throws InputError naming
// REPOSE_MEMORY_BUDGET_MB when it is set to anything but a positive integer.
std::uint64_t memory_budget_bytes();
// Where the budget comes from, for messages: "REPOSE_MEMORY_BUDGET_MB=2048",
// "half of this machine's 23.4 GB", "set by the program".
std::string memory_budget_source();
// Overrides the environment and the default (nullopt: back to them).
void set_memory_budget_bytes(std::optional<std::uint64_t> bytes);

// Throws InputError "WHAT needs about X of memory, more than the memory
// budget of Y (SOURCE); ..." when estimated_bytes > memory_budget_bytes().
void require_memory(std::uint64_t estimated_bytes, std::string_view what);

}  // namespace repose
