#include "models/heightspan/side_cut.h"

#include <set>

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"

namespace repose {
namespace {

using testing::standing_bucket;
using testing::StandingBucket;

// The bucket of standing_bucket over ground cells 12 .. 27 in x and y, its floor 5 mm deep in a 6 cm bed.
StandingBucket sunk_bucket() { return standing_bucket(0.1, 0.06); }

// The lowest span bottom of the bucket's map: its flat floor's underside.
double floor_bottom_m(const SpanMap& map) {
  double lowest = 1.0;
  for (std::int64_t c = 0; c + 1 < static_cast<std::int64_t>(map.first.size()); ++c) {
    if (map.count(c) > 0) lowest = std::min(lowest, map.begin(c)[0].bottom_m);
  }
  return lowest;
}

struct Cut {
  int i, j;
  double fraction;  // of the ground above the floor's underside
};

// Cuts with `motion_m` and checks that exactly `cells` changed, by their fractions, that
// the wedge holds what they lost, and that the ledger still balances.
void expect_cut(const Eigen::Vector3d& motion_m, const std::vector<Cut>& cells, std::array<int, 2> back) {
  StandingBucket b = sunk_bucket();
  const SpanMap& map = b.state.held[0].map;
  const double level_m = floor_bottom_m(map), area_m2 = 0.005 * 0.005;
  ASSERT_LT(level_m, 0.06 - 0.004);
  const double before_m3 = accounted_m3(b.state);
  DragWedge& wedge = b.state.held[0].wedge;
  const double cut_m3 = cut_beside(b.model.ground, map, 0.0075, motion_m, &wedge, &b.state.ground);
  double expected_m3 = 0.0;
  std::set<std::pair<int, int>> cut_cells;
  for (const Cut& c : cells) {
    const double dz = c.fraction * (0.06 - level_m);
    EXPECT_NEAR(b.state.ground.height.at(c.i, c.j), 0.06 - dz, 1e-15) << c.i << ", " << c.j;
    expected_m3 += dz * area_m2;
    cut_cells.insert({c.i, c.j});
  }
  for (int j = 0; j < 40; ++j) {
    for (int i = 0; i < 40; ++i) {
      if (cut_cells.count({i, j}) == 0) {
        EXPECT_EQ(b.state.ground.height.at(i, j), 0.06) << i << ", " << j;
      }
    }
  }
  EXPECT_NEAR(cut_m3, expected_m3, 1e-18);
  EXPECT_NEAR(wedge.volume_m3, cut_m3, 1e-18);
  EXPECT_EQ(wedge.back, back);
  EXPECT_NEAR(accounted_m3(b.state), before_m3, 1e-17);
}

TEST(SideCut, CutsBesideBothSideWallsInTheLipsColumnDownToTheFloorIntoTheWedge) {
  // 7.5 mm: the first cell beside each wall whole, the next by half; the lip's column is 27
  expect_cut({0.001, 0.0, 0.0}, {{27, 11, 1.0}, {27, 10, 0.5}, {27, 28, 1.0}, {27, 29, 0.5}}, {-1, 0});
}

TEST(SideCut, FollowsTheDragsMainAxisAndDirection) {
  // towards -y (with a smaller x motion): the lip's row is 12, the walls are columns 12 and 27
  expect_cut({0.0003, -0.001, 0.0}, {{11, 12, 1.0}, {10, 12, 0.5}, {28, 12, 1.0}, {29, 12, 0.5}}, {0, 1});
  // towards -x: the lip's column is 12
  expect_cut({-0.001, 0.0, 0.0}, {{12, 11, 1.0}, {12, 10, 0.5}, {12, 28, 1.0}, {12, 29, 0.5}}, {1, 0});
}

TEST(SideCut, CutsNothingWhenPressingOrSwitchedOffOrAboveTheGround) {
  StandingBucket b = sunk_bucket();
  const SpanMap& map = b.state.held[0].map;
  DragWedge& wedge = b.state.held[0].wedge;
  GroundState& g = b.state.ground;
  EXPECT_EQ(cut_beside(b.model.ground, map, 0.0075, {0.0, 0.0, -0.001}, &wedge, &g), 0.0);  // pressing
  EXPECT_EQ(cut_beside(b.model.ground, map, 0.0, {0.001, 0.0, 0.0}, &wedge, &g), 0.0);     // off
  for (int j = 0; j < 40; ++j) {
    for (int i = 0; i < 40; ++i) g.height.at(i, j) = std::min(g.height.at(i, j), floor_bottom_m(map));
  }
  EXPECT_EQ(cut_beside(b.model.ground, map, 0.0075, {0.001, 0.0, 0.0}, &wedge, &g), 0.0);  // nothing above the floor
  EXPECT_EQ(wedge.volume_m3, 0.0);
}

TEST(SideCut, StopsAtTheGridsEdge) {
  // 10 cm: 20 cells beside each wall, of which 12 lie on the grid on each side
  StandingBucket b = sunk_bucket();
  const double cut_m3 = cut_beside(b.model.ground, b.state.held[0].map, 0.1, {0.001, 0.0, 0.0},
                                   &b.state.held[0].wedge, &b.state.ground);
  EXPECT_NEAR(cut_m3, 24 * (0.06 - floor_bottom_m(b.state.held[0].map)) * 0.005 * 0.005, 1e-18);
  EXPECT_TRUE(b.state.ground.height.all_finite());
}

}  // namespace
}  // namespace repose
