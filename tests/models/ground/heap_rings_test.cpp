// The heap routing's rings (heap_rings.h): ring 0 the footprint's covered
// cells, ring k the open cells first reached from ring k - 1 through open
// cells, each cell's ring as a plain breadth-first search over every cell's
// on_open_ground() finds it, however far they grow, with other objects'
// undersides and pockets in the way.
#include "models/ground/heap_rings.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "models/ground/contact_region.h"
#include "models/ground/ground_params.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

// A random underside over `fp`: each cell covered (at 1 cm) or not (+inf).
Underside random_underside(const Footprint& fp, double covered_fraction, std::mt19937* rng) {
  Underside u;
  u.footprint = fp;
  u.z_m = ArrayXXdR::Constant(fp.nj, fp.ni, std::numeric_limits<double>::infinity());
  std::bernoulli_distribution covered(covered_fraction);
  for (int j = 0; j < fp.nj; ++j) {
    for (int i = 0; i < fp.ni; ++i) {
      if (covered(*rng)) u.z_m(j, i) = 0.01;
    }
  }
  return u;
}

// Each grid cell's ring by a plain breadth-first search (-1: never reached).
std::vector<int> plain_rings(const ExcessRouting& in) {
  const Grid& g = in.model.grid;
  std::vector<int> ring(g.cell_count(), -1);
  std::vector<std::array<int, 2>> front;
  const Footprint& fp = in.region.fp;
  for (int j = fp.j0; j < fp.j0 + fp.nj; ++j) {
    for (int i = fp.i0; i < fp.i0 + fp.ni; ++i) {
      if (!in.on_open_ground(i, j)) ring[static_cast<std::size_t>(in.model.cell(i, j))] = 0, front.push_back({i, j});
    }
  }
  for (int k = 1; !front.empty(); ++k) {
    std::vector<std::array<int, 2>> next;
    for (const auto& [i, j] : front) {
      for (const auto& o : kNeighbours) {
        const int ni = i + o[0], nj = j + o[1];
        if (!g.contains(ni, nj) || ring[static_cast<std::size_t>(in.model.cell(ni, nj))] != -1) continue;
        if (!in.on_open_ground(ni, nj)) continue;
        ring[static_cast<std::size_t>(in.model.cell(ni, nj))] = k;
        next.push_back({ni, nj});
      }
    }
    front = std::move(next);
  }
  return ring;
}

TEST(HeapRings, RingsAreThoseAPlainSearchOverEveryCellFinds) {
  const GroundModel model = make_plain_ground_model(centred_grid(60, 50, 0.01), sand());
  const GroundParams params = default_params(model);
  const DragDirection dir;
  for (unsigned seed = 1; seed <= 6; ++seed) {
    std::mt19937 rng(seed);
    ContactRegion region;
    region.fp = Footprint{20, 15, 10, 8};
    region.dist.assign(static_cast<std::size_t>(region.fp.ni * region.fp.nj), 0);
    Ceiling ceiling;
    ceiling.undersides.push_back(random_underside(region.fp, 0.8, &rng));
    // other objects' undersides away from the contact, the rings reach past and around them
    ceiling.undersides.push_back(random_underside(Footprint{40, 5, 12, 30}, 0.6, &rng));
    ceiling.undersides.push_back(random_underside(Footprint{2, 35, 9, 9}, 0.5, &rng));
    ExcessRouting in{model, params, ceiling, dir, region, 0.1};
    // pockets: the footprint and a ring around it, a few of its uncovered cells marked
    in.window = Footprint{19, 14, 12, 10};
    in.pocket.assign(static_cast<std::size_t>(in.window.ni * in.window.nj), 0);
    std::bernoulli_distribution pocket(0.2);
    for (int j = in.window.j0; j < in.window.j0 + in.window.nj; ++j) {
      for (int i = in.window.i0; i < in.window.i0 + in.window.ni; ++i) {
        const std::size_t at = static_cast<std::size_t>((j - in.window.j0) * in.window.ni + (i - in.window.i0));
        in.pocket[at] = std::isinf(ceiling.at(i, j)) && pocket(rng);
      }
    }
    const std::vector<int> expected = plain_rings(in);
    Rings rings(in);
    for (int k = 1; !rings.at(k).empty(); ++k) {
    }
    int reached = 0;
    for (int j = 0; j < model.grid.ny; ++j) {
      for (int i = 0; i < model.grid.nx; ++i) {
        const int want = expected[static_cast<std::size_t>(model.cell(i, j))];
        ASSERT_EQ(rings.of(i, j), want) << "seed " << seed << " cell " << i << ", " << j;
        reached += want >= 0;
      }
    }
    EXPECT_GT(reached, model.grid.nx * model.grid.ny / 2);  // the rings spread over most of the grid
  }
}

}  // namespace
}  // namespace repose
