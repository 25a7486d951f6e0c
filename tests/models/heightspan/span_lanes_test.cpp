#include "models/heightspan/span_lanes.h"

#include <gtest/gtest.h>

namespace repose {
namespace {

// 5 x 4 cells; spans (from 0 to 1 m) in row 0 at i = 0..2, none in row 1,
// row 2 at i = 1..4, row 3 at i = 3.
SpanMap l_shaped_map() {
  const Grid grid{5, 4, 0.01, 0.0, 0.0};
  std::vector<SpanHit> hits;
  auto span = [&](int i, int j) {
    const std::int64_t c = static_cast<std::int64_t>(j) * grid.nx + i;
    hits.push_back({c, 0.0, +1});
    hits.push_back({c, 1.0, -1});
  };
  for (int i = 0; i <= 2; ++i) span(i, 0);
  for (int i = 1; i <= 4; ++i) span(i, 2);
  span(3, 3);
  return spans_from_hits(hits, grid);
}

std::vector<std::array<int, 3>> as_triples(const std::vector<LaneFront>& fronts) {
  std::vector<std::array<int, 3>> out;
  for (const LaneFront& f : fronts) out.push_back({f.lane, f.i, f.j});
  return out;
}

using Triples = std::vector<std::array<int, 3>>;

TEST(SpanLanes, AlongXEachRowWithASpanGivesItsFrontmostCellInRowOrder) {
  const SpanMap map = l_shaped_map();
  EXPECT_TRUE(along_x({-1, 0}));
  // dragged towards +x (the step against it is -x): the highest i with a span; row 1 has none
  EXPECT_EQ(as_triples(lane_fronts(map, {-1, 0})), (Triples{{0, 2, 0}, {2, 4, 2}, {3, 3, 3}}));
  // towards -x: the lowest i
  EXPECT_EQ(as_triples(lane_fronts(map, {1, 0})), (Triples{{0, 0, 0}, {2, 1, 2}, {3, 3, 3}}));
}

TEST(SpanLanes, AlongYEachColumnIsALane) {
  const SpanMap map = l_shaped_map();
  EXPECT_FALSE(along_x({0, -1}));
  EXPECT_EQ(as_triples(lane_fronts(map, {0, -1})),  // towards +y: the highest j
            (Triples{{0, 0, 0}, {1, 1, 2}, {2, 2, 2}, {3, 3, 3}, {4, 4, 2}}));
  EXPECT_EQ(as_triples(lane_fronts(map, {0, 1})),  // towards -y: the lowest j
            (Triples{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}, {3, 3, 2}, {4, 4, 2}}));
}

TEST(SpanLanes, AMapWithNoSpanHasNoLanes) {
  const SpanMap empty = spans_from_hits({}, Grid{3, 3, 0.01, 0.0, 0.0});
  EXPECT_TRUE(lane_fronts(empty, {-1, 0}).empty());
}

}  // namespace
}  // namespace repose
