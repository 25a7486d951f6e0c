// libFuzzer target: parse_yaml on arbitrary text, with its document and
// quote checks (yaml_text_checks.h), and the lexical quote scan alone at
// every line of the input.
#include <cstdint>
#include <string>

#include "models/core/base/error.h"
#include "models/core/config/yaml_reader.h"
#include "models/core/config/yaml_text_checks.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)repose::parse_yaml(text, "fuzz.yaml");
  } catch (const repose::InputError&) {
  }
  (void)repose::find_unclosed_quote(text, 1 << 20);
  return 0;
}
