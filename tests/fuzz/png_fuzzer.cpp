// libFuzzer target: read_png16 on arbitrary .png bytes, with and without an
// expected size, and the header-only probe. The fuzzer's memory limit
// (-rss_limit_mb) sits below the default budget, so the budget is lowered
// to keep a declared-huge image a refusal rather than a finding.
#include "models/core/io/png_io.h"
#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  repose::set_memory_budget_bytes(std::uint64_t{256} << 20);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = repose::fuzz::write_input(data, size, ".png");
  try {
    (void)repose::read_png16(path);
  } catch (const repose::InputError&) {
  }
  try {
    (void)repose::read_png_size(path);
  } catch (const repose::InputError&) {
  }
  try {
    (void)repose::read_png16(path, 4, 4);
  } catch (const repose::InputError&) {
  }
  return 0;
}
