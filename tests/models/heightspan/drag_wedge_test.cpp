#include "models/heightspan/drag_wedge.h"

#include <gtest/gtest.h>

#include "heightspan_fixtures.h"
#include "models/heightspan/ground_contact.h"

namespace repose {
namespace {

using testing::standing_bucket;
using testing::StandingBucket;

TEST(DragWedge, KeepsItsFractionOfWhatADragCompressesAndTheLedgerStillBalances) {
  StandingBucket b = standing_bucket(0.1);
  GroundState& g = b.state.ground;
  g.ledger.compressed_m3 = 1e-6;
  const double before = accounted_m3(b.state);
  DragWedge& w = b.state.held[0].wedge;
  EXPECT_DOUBLE_EQ(keep_in_wedge(b.model.ground, 1e-6, {0.4, 0.0}, {0.001, 0.0, 0.0}, &w, &g), 4e-7);
  EXPECT_DOUBLE_EQ(w.volume_m3, 4e-7);
  EXPECT_DOUBLE_EQ(g.ledger.compressed_m3, 6e-7);
  EXPECT_EQ(w.back, (std::array<int, 2>{-1, 0}));
  EXPECT_NEAR(accounted_m3(b.state), before, 1e-18);
  // pressing (moving down) is not a drag: its compression stays compressed
  EXPECT_EQ(keep_in_wedge(b.model.ground, 1e-6, {0.4, 0.0}, {0.001, 0.0, -0.001}, &w, &g), 0.0);
  // nor with the option off
  EXPECT_EQ(keep_in_wedge(b.model.ground, 1e-6, {0.0, 0.0}, {0.001, 0.0, 0.0}, &w, &g), 0.0);
  // a drag along -y remembers its direction
  keep_in_wedge(b.model.ground, 1e-6, {1.0, 0.0}, {0.0002, -0.001, 0.0}, &w, &g);
  EXPECT_EQ(w.back, (std::array<int, 2>{0, 1}));
  EXPECT_DOUBLE_EQ(w.volume_m3, 1.4e-6);
}

TEST(DragWedge, KeepsWhatAPressCompressesUntilADragDrivesItOrTheObjectLiftsOff) {
  StandingBucket b = standing_bucket(0.1);
  GroundState& g = b.state.ground;
  g.ledger.compressed_m3 = 2e-6;
  const double before = accounted_m3(b.state);
  DragWedge& w = b.state.held[0].wedge;
  const SpanMap& map = b.state.held[0].map;
  const Eigen::Vector3d down(0.0, 0.0, -0.001), drag(0.001, 0.0, 0.0), up(0.0, 0.0, 0.001);
  // a drag's compression is not the press fraction's, and the option off keeps nothing
  DragWedge dragged;  // a drag sets its wedge's direction: a wedge of its own
  EXPECT_EQ(keep_in_wedge(b.model.ground, 1e-6, {0.0, 0.5}, drag, &dragged, &g), 0.0);
  EXPECT_EQ(keep_in_wedge(b.model.ground, 1e-6, {0.0, 0.0}, down, &w, &g), 0.0);
  EXPECT_DOUBLE_EQ(keep_in_wedge(b.model.ground, 1e-6, {0.0, 0.5}, down, &w, &g), 5e-7);
  EXPECT_DOUBLE_EQ(g.ledger.compressed_m3, 1.5e-6);
  EXPECT_EQ(w.back, (std::array<int, 2>{0, 0}));  // no way to lay it along yet
  // pressing on or standing: it waits in the wedge
  EXPECT_EQ(lay_wedge(b.model.ground, map, down, &w, &g), 0.0);
  EXPECT_EQ(lay_wedge(b.model.ground, map, Eigen::Vector3d::Zero(), &w, &g), 0.0);
  EXPECT_DOUBLE_EQ(w.volume_m3, 5e-7);
  EXPECT_NEAR(accounted_m3(b.state), before, 1e-18);
  // lifted off without a drag: it stays compressed after all
  EXPECT_EQ(lay_wedge(b.model.ground, map, up, &w, &g), 0.0);
  EXPECT_EQ(w.volume_m3, 0.0);
  EXPECT_DOUBLE_EQ(g.ledger.compressed_m3, 2e-6);
  // pressed, then dragged towards +x (a drag that keeps none of its own compression still drives it) and
  // lifted: laid just ahead of the drag
  const double ground_before = g.height.volume_m3();
  keep_in_wedge(b.model.ground, 1e-6, {0.0, 1.0}, down, &w, &g);
  EXPECT_EQ(keep_in_wedge(b.model.ground, 6e-7, {0.0, 1.0}, drag, &w, &g), 0.0);
  EXPECT_EQ(w.back, (std::array<int, 2>{-1, 0}));
  EXPECT_EQ(lay_wedge(b.model.ground, map, drag, &w, &g), 0.0);
  EXPECT_DOUBLE_EQ(lay_wedge(b.model.ground, map, up, &w, &g), 1e-6);
  EXPECT_NEAR(g.height.volume_m3() - ground_before, 1e-6, 1e-18);
  EXPECT_GT(g.height.at(28, 20), 0.01);  // column 28: just ahead of the spans along +x
  EXPECT_NEAR(accounted_m3(b.state), before, 1e-18);
}

TEST(DragWedge, KeepsWhatTheLipPushedAheadAndRemembersTheWay) {
  DragWedge w;
  keep_pushed_ahead(2e-6, {-1, 0}, &w);
  EXPECT_EQ(w.volume_m3, 2e-6);
  EXPECT_EQ(w.back, (std::array<int, 2>{-1, 0}));
  keep_pushed_ahead(1e-6, {0, 1}, &w);  // turned towards -y: the latest way counts
  EXPECT_DOUBLE_EQ(w.volume_m3, 3e-6);
  EXPECT_EQ(w.back, (std::array<int, 2>{0, 1}));
}

TEST(DragWedge, LaysItInEqualSharesJustAheadOfEveryLaneOfTheObjectOnceItStopsDragging) {
  StandingBucket b = standing_bucket(0.1);  // spans over ground cells 12 .. 27 in x and y
  GroundState& g = b.state.ground;
  DragWedge& w = b.state.held[0].wedge;
  w = DragWedge{1.6e-5, {-1, 0}};  // driven towards +x
  const SpanMap& map = b.state.held[0].map;
  const double before = accounted_m3(b.state), ground_before = g.height.volume_m3();
  // still dragging: it stays in front of the object
  EXPECT_EQ(lay_wedge(b.model.ground, map, {0.001, 0.0, 0.0}, &w, &g), 0.0);
  EXPECT_EQ(w.volume_m3, 1.6e-5);
  // lifted: laid on ground column 28, rows 12 .. 27, 1e-6 m^3 each
  EXPECT_DOUBLE_EQ(lay_wedge(b.model.ground, map, {0.0, 0.0, 0.001}, &w, &g), 1.6e-5);
  EXPECT_EQ(w.volume_m3, 0.0);
  EXPECT_NEAR(g.height.volume_m3() - ground_before, 1.6e-5, 1e-18);
  EXPECT_NEAR(accounted_m3(b.state), before, 1e-18);
  const double share_m = 1e-6 / (0.005 * 0.005);
  for (int j = 0; j < 40; ++j) {
    for (int i = 0; i < 40; ++i) {
      const bool laid = i == 28 && j >= 12 && j <= 27;
      EXPECT_NEAR(g.height.at(i, j), 0.01 + (laid ? share_m : 0.0), 1e-15) << i << ", " << j;
    }
  }
  EXPECT_TRUE(g.erosion.contains(b.model.ground.cell(28, 12)));
}

TEST(DragWedge, WhatFindsNoCellAheadOnTheGridLeavesIt) {
  StandingBucket b = standing_bucket(0.1);
  GroundState& g = b.state.ground;
  DragWedge& w = b.state.held[0].wedge;
  w = DragWedge{1.6e-5, {0, 1}};  // driven towards -y: the cells ahead are row 11
  EXPECT_DOUBLE_EQ(lay_wedge(b.model.ground, b.state.held[0].map, Eigen::Vector3d::Zero(), &w, &g), 1.6e-5);
  EXPECT_GT(g.height.at(20, 11), 0.01);
  StandingBucket edge = standing_bucket(0.18);  // reaches past the grid's +x edge (0.2 m)
  GroundState& e = edge.state.ground;
  DragWedge& we = edge.state.held[0].wedge;
  we = DragWedge{1.6e-5, {-1, 0}};
  const double before = accounted_m3(edge.state);
  EXPECT_EQ(lay_wedge(edge.model.ground, edge.state.held[0].map, Eigen::Vector3d::Zero(), &we, &e), 0.0);
  EXPECT_DOUBLE_EQ(e.ledger.left_grid_m3, 1.6e-5);
  EXPECT_NEAR(accounted_m3(edge.state), before, 1e-18);
}

TEST(DragWedge, SendsItsShareOfWhatADragKeptOverTheLipInEqualSharesOntoEveryLanesFront) {
  StandingBucket b = standing_bucket(0.1);  // spans over ground cells 12 .. 27 in x and y
  SpanMap& map = b.state.held[0].map;
  DragWedge& w = b.state.held[0].wedge;
  w = DragWedge{2e-5, {-1, 0}};  // 1.6e-5 of it kept this substep, driven towards +x
  const double before = accounted_m3(b.state), on_spans = map.material_m3();
  EXPECT_DOUBLE_EQ(feed_over_lip(b.model.ground.grid, 1.6e-5, 0.25, &w, &map), 4e-6);
  EXPECT_DOUBLE_EQ(w.volume_m3, 1.6e-5);
  EXPECT_NEAR(map.material_m3() - on_spans, 4e-6, 1e-18);
  EXPECT_NEAR(accounted_m3(b.state), before, 1e-18);
  // 2.5e-7 m^3 onto the lowest span of each of the 16 lanes' front cell (ground column 27)
  const CellOffset off = ground_offset(map.grid, b.model.ground.grid);
  const double share_m = 2.5e-7 / (0.005 * 0.005);
  for (int j = 0; j < map.grid.ny; ++j) {
    for (int i = 0; i < map.grid.nx; ++i) {
      const std::int64_t c = map.cell(i, j);
      if (map.count(c) == 0) continue;
      const bool front = i + off.di == 27;
      EXPECT_NEAR(map.begin(c)[0].material_m, front ? share_m : 0.0, 1e-15) << i << ", " << j;
    }
  }
  // nothing with the option off or nothing kept
  EXPECT_EQ(feed_over_lip(b.model.ground.grid, 1.6e-5, 0.0, &w, &map), 0.0);
  EXPECT_EQ(feed_over_lip(b.model.ground.grid, 0.0, 0.5, &w, &map), 0.0);
  EXPECT_DOUBLE_EQ(w.volume_m3, 1.6e-5);
}

}  // namespace
}  // namespace repose
