// libFuzzer target: read_png16 on arbitrary .png bytes.
#include "models/core/io/png_io.h"
#include "models/core/base/error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = repose::fuzz::write_input(data, size, ".png");
  try {
    (void)repose::read_png16(path);
  } catch (const repose::InputError&) {
  }
  return 0;
}
