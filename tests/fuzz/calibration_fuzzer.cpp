// libFuzzer target: the calibration-file loader on arbitrary YAML text.
#include <cstdint>
#include <string>

#include "models/core/base/error.h"
#include "validation/calibration/calibration_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    // scene paths resolve against a folder that holds none: the loader must say so, not crash
    (void)repose::load_calibration_from_string(text, "/dev/shm/repose-fuzz-calibration/calibration.yaml");
  } catch (const repose::InputError&) {
  }
  return 0;
}
