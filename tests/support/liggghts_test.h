#pragma once
// A GoogleTest fixture for tests that run the real `liggghts` program: fails
// the test when LIGGGHTS is not installed (scripts/install-deps.sh installs
// it, so a missing program is a broken set-up, not a reason to pass), unless
// REPOSE_ALLOW_MISSING_LIGGGHTS=1 says it is expected to be missing, then
// skips; gives the test a fresh folder dir_.

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "models/core/base/error.h"
#include "validation/liggghts/liggghts_runner.h"
#include "tests/support/temp_dir.h"

namespace repose::test_support {

class LiggghtsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      resolve_liggghts_executable({});
    } catch (const InputError& e) {
      const char* allow = std::getenv("REPOSE_ALLOW_MISSING_LIGGGHTS");
      if (allow != nullptr && std::string(allow) == "1") GTEST_SKIP() << "liggghts is not installed (allowed)";
      FAIL() << "liggghts is expected (scripts/install-deps.sh) but missing: " << e.what();
    }
  }
  TempDir temp_;
  const std::filesystem::path dir_ = temp_.path;
};

}  // namespace repose::test_support
