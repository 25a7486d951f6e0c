#pragma once
// A GoogleTest fixture for tests that run the real `liggghts` program: skips
// the test when LIGGGHTS is not installed, and gives it a fresh folder dir_.

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>

#include "models/core/base/error.h"
#include "validation/liggghts/liggghts_runner.h"

namespace repose::test_support {

class LiggghtsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    try {
      resolve_liggghts_executable({});
    } catch (const InputError&) {
      GTEST_SKIP() << "liggghts is not installed";
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
