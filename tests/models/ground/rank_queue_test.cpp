// RankQueue (models/ground/rank_queue.h): pops what was pushed, smallest
// first, each rank once however often it was pushed, also when ranks are
// pushed while popping (always beyond the last popped one, as the heap
// routing does) and across word boundaries.
#include "models/ground/rank_queue.h"

#include <random>
#include <set>
#include <vector>

#include <gtest/gtest.h>

namespace repose {
namespace {

TEST(RankQueue, PopsLikeASortedSetWhilePushingBeyondTheTop) {
  std::mt19937_64 rng(3);
  RankQueue queue;
  std::set<int> expected;
  std::uniform_int_distribution<int> start(0, 5000);
  for (int k = 0; k < 300; ++k) {  // unordered, with repeats
    const int r = start(rng);
    queue.push(r);
    expected.insert(r);
  }
  std::vector<int> popped;
  while (!queue.empty()) {
    const int r = queue.top();
    ASSERT_FALSE(expected.empty());
    EXPECT_EQ(r, *expected.begin());
    expected.erase(expected.begin());
    queue.pop();
    popped.push_back(r);
    std::uniform_int_distribution<int> ahead(r + 1, r + 200);
    for (int n = 0; n < 2 && popped.size() < 2000; ++n) {  // onward cells: beyond r, sometimes twice
      const int a = ahead(rng);
      queue.push(a);
      expected.insert(a);
    }
  }
  EXPECT_TRUE(expected.empty());
  for (std::size_t k = 1; k < popped.size(); ++k) EXPECT_LT(popped[k - 1], popped[k]);
  EXPECT_EQ(queue.top(), -1);
}

TEST(RankQueue, StartsOverBelowTheCursorOnceEmpty) {
  RankQueue queue;
  for (const int r : {130, 64, 63, 0}) queue.push(r);
  std::vector<int> popped;
  for (; !queue.empty(); queue.pop()) popped.push_back(queue.top());
  EXPECT_EQ(popped, (std::vector<int>{0, 63, 64, 130}));
  queue.push(5);  // smaller than the last popped: the next shed_outwards call
  EXPECT_EQ(queue.top(), 5);
}

}  // namespace
}  // namespace repose
