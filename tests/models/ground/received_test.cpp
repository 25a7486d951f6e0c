// Received (models/ground/received.h): the flat map of the material one
// displacement put on each cell must behave as a map, keyed by cell, with
// the amounts summed exactly as std::map sums them, iterated in the order
// cells were first met.
#include "models/ground/received.h"

#include <cstdint>
#include <map>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace repose {
namespace {

TEST(Received, SumsLikeAMapThroughGrowthAndFindsOnlyWhatWasInserted) {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<std::int64_t> cell(0, 512 * 512 - 1);
  std::uniform_real_distribution<double> amount(0.0, 1e-3);
  Received received;
  std::map<std::int64_t, double> expected;
  std::vector<std::int64_t> first_seen;
  for (int k = 0; k < 20000; ++k) {  // many growths; cells repeat
    const std::int64_t c = cell(rng) % 6000;
    const double a = amount(rng);
    if (!expected.contains(c)) first_seen.push_back(c);
    received[c] += a;
    expected[c] += a;
  }
  ASSERT_EQ(received.size(), expected.size());
  for (const auto& [c, a] : expected) {
    const double* found = received.find(c);
    ASSERT_NE(found, nullptr) << c;
    EXPECT_EQ(*found, a) << c;  // the same additions in the same order: the same double
  }
  EXPECT_EQ(received.find(6000), nullptr);
  EXPECT_EQ(received.find(-1 + 512 * 512), nullptr);
  std::size_t k = 0;
  for (const auto& [c, a] : received) EXPECT_EQ(c, first_seen[k++]);
}

TEST(Received, AnEmptyMapFindsNothingAndIteratesOverNothing) {
  const Received received;
  EXPECT_EQ(received.find(0), nullptr);
  EXPECT_EQ(received.size(), 0u);
  EXPECT_EQ(received.begin(), received.end());
}

}  // namespace
}  // namespace repose
