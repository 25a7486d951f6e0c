#pragma once
// A GoogleTest fixture for tests that run the real `liggghts` program: fails
// the test when LIGGGHTS is not installed (scripts/install-deps.sh installs
// it, so a missing program is a broken set-up, not a reason to pass), unless
// REPOSE_ALLOW_MISSING_LIGGGHTS=1 says it is expected to be missing, then
// skips; gives the test a fresh folder dir_.

#include <gtest/gtest.h>
#include <stdlib.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "models/core/base/error.h"
#include "validation/liggghts/liggghts_runner.h"

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
    char pattern[] = "/tmp/repose-liggghts-test-XXXXXX";
    dir_ = ::mkdtemp(pattern);
  }
  void TearDown() override {
    if (!dir_.empty()) std::filesystem::remove_all(dir_);
  }
  std::filesystem::path dir_;
};

}  // namespace repose::test_support
