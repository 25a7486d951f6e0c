#include "models/core/config/yaml_reader.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <string>

#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

class YamlReader : public test_support::TempDirTest {};

// yaml-cpp takes about 85 bytes per byte of text: parsing is refused when
// that exceeds the memory budget, before yaml-cpp allocates it.
TEST_F(YamlReader, ParsingBeyondTheMemoryBudgetIsRefusedWithTheEstimate) {
  std::string text = "objects:\n";
  while (text.size() < 20000) text += "  - {name: s, radius_m: 0.01}\n";
  set_memory_budget_bytes(std::uint64_t{1} << 20);
  try {
    (void)parse_yaml(text, "big.yaml");
    ADD_FAILURE() << "parsed beyond the budget";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("big.yaml: parsing 19.5 kB of YAML needs about 1.7 MB of memory"),
              std::string::npos)
        << e.what();
  }
  set_memory_budget_bytes(std::nullopt);
  EXPECT_EQ(parse_yaml(text, "big.yaml").node()["objects"].size(), 667u);
}

TEST_F(YamlReader, ReadYamlFileGoesThroughTheInputFileChecks) {
  test_support::write_all(path("s.yaml"), "a: 1\n");
  EXPECT_EQ(read_yaml_file(path("s.yaml"), input_kind::kScene).node()["a"].as<int>(), 1);
  ASSERT_EQ(::mkfifo(path("pipe.yaml").c_str(), 0600), 0);
  try {
    (void)read_yaml_file(path("pipe.yaml"), input_kind::kScene);
    ADD_FAILURE() << "a FIFO was read";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("pipe.yaml: is a FIFO (named pipe), not a regular scene file"),
              std::string::npos)
        << e.what();
  }
}

// A fuzz finding: yaml-cpp's LoadAll loops forever (allocating) on these
// 26 bytes, which Load reads as one document. parse_yaml must return.
TEST_F(YamlReader, InputThatMakesLoadAllLoopForeverIsParsedOnce) {
  const std::string text("\x2c\x20\x68\x61\x3a\x20\x22\x78\x20\x5c\x22\x20\x79\xff\xff\x5f\xf0\x00\x0c\xb6\xa5\x0a"
                         "\x70\x65\x6e\x0a",
                         26);
  try {
    (void)parse_yaml(text, "fuzz.yaml");
  } catch (const InputError&) {
  }
  SUCCEED();
}

}  // namespace
}  // namespace repose
