// libFuzzer target: read_mesh on arbitrary .stl bytes.
#include "models/core/io/mesh_io.h"
#include "models/core/base/error.h"
#include "tests/fuzz/fuzz_input_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string& path = repose::fuzz::write_input(data, size, ".stl");
  try {
    (void)repose::read_mesh(path);
  } catch (const repose::InputError&) {
  }
  return 0;
}
