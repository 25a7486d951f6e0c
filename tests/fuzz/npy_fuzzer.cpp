// libFuzzer target: read_npy_2d on arbitrary .npy bytes, with and without an
// expected shape, and the header-only probe.
#include "models/core/io/npy_io.h"
#include "models/core/base/error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = repose::fuzz::write_input(data, size, ".npy");
  try {
    (void)repose::read_npy_2d(path);
  } catch (const repose::InputError&) {
  }
  try {
    (void)repose::read_npy_shape(path);
  } catch (const repose::InputError&) {
  }
  try {
    (void)repose::read_npy_2d(path, 4, 4);
  } catch (const repose::InputError&) {
  }
  return 0;
}
