// The counting sorts of a drag along a grid axis give the comparison sort's
// order (the one the committed results were made with).
#include "models/ground/rear_to_front_order.h"

#include <gtest/gtest.h>

#include <random>

namespace repose {
namespace {

// A random contact region over an ni x nj footprint at (i0, j0): about half
// the cells in contact, each at a random distance to the border in [1, 6].
ContactRegion random_region(int i0, int j0, int ni, int nj, std::mt19937_64* rng) {
  ContactRegion r;
  r.fp = Footprint{i0, j0, ni, nj};
  r.dist.assign(static_cast<std::size_t>(ni) * nj, 0);
  std::bernoulli_distribution in_contact(0.5);
  std::uniform_int_distribution<int> dist(1, 6);
  for (int l = 0; l < ni * nj; ++l) {
    if (!in_contact(*rng)) continue;
    r.dist[static_cast<std::size_t>(l)] = dist(*rng);
    r.cells.push_back(l);
  }
  return r;
}

DragDirection direction(double dx, double dy) {
  DragDirection d;
  d.active = true;
  d.dx = dx, d.dy = dy;
  return d;
}

TEST(RearToFrontOrder, AlongEveryAxisTheCountingSortsGiveTheSortedOrder) {
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const ContactRegion r = random_region(3 + trial, 7, 5 + trial, 3 + 2 * trial, &rng);
    for (const auto& [dx, dy] : {std::pair{1.0, 0.0}, {-1.0, 0.0}, {0.0, 1.0}, {0.0, -1.0}, {0.3, 0.0}}) {
      const DragDirection d = direction(dx, dy);
      const std::vector<int> order = rear_to_front_order(d, r);
      ASSERT_EQ(order.size(), r.cells.size());
      EXPECT_EQ(order, rear_to_front_order_by_sort(d, r)) << "trial " << trial << " dx " << dx << " dy " << dy;
    }
  }
}

// Off the axes the comparison sort decides: along the drag first.
TEST(RearToFrontOrder, ADiagonalDragGoesByPositionAlongIt) {
  std::mt19937_64 rng(3);
  const ContactRegion r = random_region(0, 0, 9, 9, &rng);
  const DragDirection d = direction(std::sqrt(0.5), std::sqrt(0.5));
  const std::vector<int> order = rear_to_front_order(d, r);
  ASSERT_EQ(order.size(), r.cells.size());
  for (std::size_t k = 1; k < order.size(); ++k) {
    EXPECT_LE(r.gi(order[k - 1]) + r.gj(order[k - 1]), r.gi(order[k]) + r.gj(order[k]));
  }
}

}  // namespace
}  // namespace repose
