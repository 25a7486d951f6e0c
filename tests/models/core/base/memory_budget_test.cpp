#include "models/core/base/memory_budget.h"

#include <gtest/gtest.h>
#include <stdlib.h>
#include <unistd.h>

#include <cstdint>
#include <limits>
#include <string>

#include "models/core/base/error.h"

namespace repose {
namespace {

constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;
constexpr std::uint64_t kMax = std::numeric_limits<std::uint64_t>::max();

// Each test starts from the environment's budget and leaves it so.
class MemoryBudget : public ::testing::Test {
 protected:
  void SetUp() override {
    ::unsetenv("REPOSE_MEMORY_BUDGET_MB");
    set_memory_budget_bytes(std::nullopt);
  }
  void TearDown() override { SetUp(); }
};

std::string error_of(std::uint64_t bytes, const std::string& what) {
  try {
    require_memory(bytes, what);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST_F(MemoryBudget, EstimatesCountEveryByteAndSaturateInsteadOfOverflowing) {
  EXPECT_EQ(memory_estimate::grid_bytes(8192, 8192, 6), 8192ull * 8192 * 6 * 8);
  EXPECT_EQ(memory_estimate::grid_bytes(100, 50, 1, 4), 100ull * 50 * 4);
  EXPECT_EQ(memory_estimate::image_bytes(16384, 16384, 2), 16384ull * 16384 * 2);
  EXPECT_EQ(memory_estimate::items_bytes(50000, 1000), 50000000u);
  EXPECT_GE(memory_estimate::triangle_mesh_bytes(1000), 1000u * (9 * 8 + 3 * 4));
  // 2^40 x 2^40 cells overflow 64 bits: the estimate is "too much", never small
  EXPECT_EQ(memory_estimate::grid_bytes(1ull << 40, 1ull << 40, 1), kMax);
  EXPECT_EQ(memory_estimate::product(1ull << 63, 2), kMax);
  EXPECT_EQ(memory_estimate::sum(kMax - 1, 2), kMax);
  EXPECT_EQ(memory_estimate::sum(3, 4), 7u);
}

TEST_F(MemoryBudget, RefusesAboveTheBudgetWithEstimateAndBudgetInOneLine) {
  set_memory_budget_bytes(100 * kMiB);
  EXPECT_EQ(memory_budget_bytes(), 100 * kMiB);
  EXPECT_EQ(error_of(100 * kMiB, "exactly the budget"), "");
  const std::string message = error_of(memory_estimate::grid_bytes(8192, 8192, 1), "the ground grid");
  EXPECT_NE(message.find("the ground grid needs about 512.0 MB of memory"), std::string::npos) << message;
  EXPECT_NE(message.find("memory budget of 100.0 MB (set by the program)"), std::string::npos) << message;
  EXPECT_NE(message.find("REPOSE_MEMORY_BUDGET_MB"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos);
  EXPECT_NE(error_of(kMax, "an absurd grid").find("more than 16 EB"), std::string::npos);
}

TEST_F(MemoryBudget, EnvironmentSetsTheBudgetInMegabytes) {
  ::setenv("REPOSE_MEMORY_BUDGET_MB", "64", 1);
  EXPECT_EQ(memory_budget_bytes(), 64 * kMiB);
  EXPECT_EQ(memory_budget_source(), "REPOSE_MEMORY_BUDGET_MB=64");
  EXPECT_NE(error_of(65 * kMiB, "x").find("REPOSE_MEMORY_BUDGET_MB=64"), std::string::npos);
  // the program's setting wins over the environment
  set_memory_budget_bytes(kMiB);
  EXPECT_EQ(memory_budget_bytes(), kMiB);
}

TEST_F(MemoryBudget, MalformedEnvironmentValueIsAnInputErrorNamingIt) {
  for (const char* bad : {"abc", "0", "-5", "12MB", "", "1e3"}) {
    ::setenv("REPOSE_MEMORY_BUDGET_MB", bad, 1);
    try {
      (void)memory_budget_bytes();
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("REPOSE_MEMORY_BUDGET_MB: expected a positive whole number"),
                std::string::npos)
          << e.what();
    }
  }
}

TEST_F(MemoryBudget, DefaultIsHalfOfWhatThisProcessMayHave) {
  const std::uint64_t physical =
      static_cast<std::uint64_t>(::sysconf(_SC_PHYS_PAGES)) * static_cast<std::uint64_t>(::sysconf(_SC_PAGE_SIZE));
  EXPECT_GT(memory_budget_bytes(), 0u);
  EXPECT_LE(memory_budget_bytes(), physical / 2);
  EXPECT_NE(memory_budget_source().find("half of"), std::string::npos) << memory_budget_source();
}

TEST(FormatBytes, UsesPowersOf1024) {
  EXPECT_EQ(format_bytes(512), "512 bytes");
  EXPECT_EQ(format_bytes(1536), "1.5 kB");
  EXPECT_EQ(format_bytes(3ull << 30), "3.0 GB");
}

}  // namespace
}  // namespace repose
