// libFuzzer target: the LIGGGHTS dump reader on arbitrary text.
#include "models/core/base/error.h"
#include "tests/fuzz/fuzz_input_file.h"
#include "validation/liggghts/liggghts_dump.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = repose::fuzz::write_input(data, size, ".dump.txt");
  try {
    (void)repose::read_dump_file(path);
  } catch (const repose::InputError&) {
  }
  return 0;
}
