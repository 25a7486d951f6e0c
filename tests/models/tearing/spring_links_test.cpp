// The springs by vertex pair: every cell spring in exactly one link of its
// pair and rest length, a link's constant the sum of its intact cells'.
#include "models/tearing/spring_links.h"

#include <map>
#include <utility>

#include <gtest/gtest.h>

#include "models/tearing/sheet_forces.h"
#include "tests/models/tearing/tearing_fixtures.h"

namespace repose {
namespace {

using testing::fibre_sheet;
using testing::free_sheet_spec;

TEST(SpringLinks, EveryCellSpringIsInTheOneLinkOfItsPair) {
  const SheetModel model = fibre_sheet(free_sheet_spec(0.02, 7), 3);
  std::vector<double> constant;
  for (int k = 0; k < 6 * model.cell_count(); ++k) constant.push_back(1.0 + k);
  const std::vector<SpringLink> links = spring_links(model, constant);
  const int n = model.cells_x, m = model.cells_y;
  // edges (each once) and two diagonals a cell
  EXPECT_EQ(static_cast<int>(links.size()), n * (m + 1) + m * (n + 1) + 2 * n * m);
  std::map<std::pair<int, int>, int> link_of;
  for (std::size_t l = 0; l < links.size(); ++l) {
    const SpringLink& link = links[l];
    EXPECT_TRUE(link_of.emplace(std::minmax(link.a, link.b), static_cast<int>(l)).second) << "pair twice";
  }
  std::vector<int> seen(links.size(), 0);
  for (int c = 0; c < model.cell_count(); ++c) {
    const std::array<CellSpring, 6> springs = cell_springs(model, c);
    for (int k = 0; k < 6; ++k) {
      const CellSpring& s = springs[static_cast<std::size_t>(k)];
      const SpringLink& link = links[static_cast<std::size_t>(link_of.at(std::minmax(s.a, s.b)))];
      ++seen[static_cast<std::size_t>(link_of.at(std::minmax(s.a, s.b)))];
      EXPECT_EQ(link.rest_length_m, s.rest_length_m);
      const int slot = link.cell[0] == c ? 0 : 1;
      EXPECT_EQ(link.cell[static_cast<std::size_t>(slot)], c);
      EXPECT_EQ(link.constant[static_cast<std::size_t>(slot)], constant[static_cast<std::size_t>(6 * c + k)]);
      if (slot == 0) {
        EXPECT_EQ(link.first, 4 * (6 * c + k));
        EXPECT_EQ(link.a, s.a);
      }
    }
  }
  for (const int count : seen) EXPECT_TRUE(count == 1 || count == 2);
}

TEST(SpringLinks, ALinksConstantIsThatOfItsIntactCells) {
  const SheetModel model = fibre_sheet(free_sheet_spec(0.02, 4), 3);
  std::vector<double> constant(6 * static_cast<std::size_t>(model.cell_count()), 0.0);
  for (std::size_t k = 0; k < constant.size(); ++k) constant[k] = 1.0 + static_cast<double>(k);
  const std::vector<SpringLink> links = spring_links(model, constant);
  SheetState state = make_sheet_state(model);
  const SpringLink* shared = nullptr;
  for (const SpringLink& link : links) {
    if (link.cell[1] >= 0 && state.intact(link.cell[0]) && state.intact(link.cell[1])) shared = &link;
  }
  ASSERT_NE(shared, nullptr);
  EXPECT_EQ(shared->constant_in(state), shared->constant[0] + shared->constant[1]);
  state.torn_step[static_cast<std::size_t>(shared->cell[0])] = 1;
  EXPECT_EQ(shared->constant_in(state), shared->constant[1]);
  state.torn_step[static_cast<std::size_t>(shared->cell[1])] = 1;
  EXPECT_EQ(shared->constant_in(state), 0.0);
}

}  // namespace
}  // namespace repose
