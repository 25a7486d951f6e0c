#include "models/heightspan/span_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "heightspan_fixtures.h"

namespace repose {
namespace {

Grid grid(int n, double h, double origin) { return Grid{n, n, h, origin, origin}; }

double solid_volume_m3(const SpanMap& map) {
  double v = 0.0;
  for (const Span& s : map.spans) v += s.top_m - s.bottom_m;
  return v * map.grid.cell_area_m2();
}

TEST(SpanMap, BoxGivesOneSpanPerCoveredCell) {
  // a 2 x 2 x 1 cm box centred at (0, 0, 0.05) on 1 mm cells: 20 x 20 cells, no edge on a centre
  const TriangleMesh box = transformed(make_box({0.01, 0.01, 0.005}), Pose{{0, 0, 0.05}, Eigen::Quaterniond::Identity()});
  const SpanMap map = peel_spans(box, grid(40, 0.001, -0.02));
  int covered = 0;
  for (std::int64_t c = 0; c < 1600; ++c) {
    ASSERT_LE(map.count(c), 1);
    if (map.count(c) == 0) continue;
    ++covered;
    EXPECT_NEAR(map.begin(c)[0].bottom_m, 0.045, 1e-12);
    EXPECT_NEAR(map.begin(c)[0].top_m, 0.055, 1e-12);
  }
  EXPECT_EQ(covered, 400);
}

TEST(SpanMap, CentresOnSharedEdgesAreCountedOnce) {
  // box edges and its triangles' diagonals pass through cell centres: every
  // column must still close (one span, right height), never two or a half
  const TriangleMesh box = make_box({0.0105, 0.0105, 0.01});
  const SpanMap map = peel_spans(box, grid(42, 0.001, -0.021));
  for (std::int64_t c = 0; c < 42 * 42; ++c) {
    ASSERT_LE(map.count(c), 1) << c;
    if (map.count(c) == 1) {
      EXPECT_NEAR(map.begin(c)[0].top_m - map.begin(c)[0].bottom_m, 0.02, 1e-12) << c;
    }
  }
}

TEST(SpanMap, StackedBodiesGiveOrderedSpansAndOverlapsMerge) {
  const TriangleMesh low = make_box({0.01, 0.01, 0.005});
  const TriangleMesh high = transformed(make_box({0.01, 0.01, 0.005}), Pose{{0, 0, 0.03}, Eigen::Quaterniond::Identity()});
  const TriangleMesh overlapping = transformed(make_box({0.005, 0.005, 0.005}), Pose{{0, 0, 0.004}, Eigen::Quaterniond::Identity()});
  const SpanMap map = peel_spans(merged(merged(low, high), overlapping), grid(10, 0.004, -0.02));
  const std::int64_t centre = 5 * 10 + 5;
  ASSERT_EQ(map.count(centre), 2);
  EXPECT_NEAR(map.begin(centre)[0].bottom_m, -0.005, 1e-12);
  EXPECT_NEAR(map.begin(centre)[0].top_m, 0.009, 1e-12);  // the overlapping box reaches higher
  EXPECT_NEAR(map.begin(centre)[1].bottom_m, 0.025, 1e-12);
  EXPECT_NEAR(map.begin(centre)[1].top_m, 0.035, 1e-12);
}

TEST(SpanMap, SphereVolumeConvergesUnderRefinement) {
  const TriangleMesh sphere = make_sphere(0.02, 64);
  const double exact = signed_volume_m3(sphere);
  auto error = [&](int n) {
    return std::abs(solid_volume_m3(peel_spans(sphere, grid(n, 0.05 / n, -0.025))) - exact) / exact;
  };
  const double coarse = error(8), fine = error(64);
  EXPECT_LT(fine, coarse);
  EXPECT_LT(fine, 0.002);
}

TEST(SpanMap, BucketFloorAndWallsAreSpansAndItsCavityIsOpen) {
  const SpanMap map = peel_spans(testing::bucket_mesh(), grid(40, 0.0025, -0.05));
  int i, j;
  ASSERT_TRUE(map.cell_at(0.0, 0.0, &i, &j));
  const std::int64_t centre = map.cell(i, j);
  ASSERT_EQ(map.count(centre), 1);
  EXPECT_NEAR(map.begin(centre)[0].bottom_m, -0.025, 1e-12);
  EXPECT_NEAR(map.begin(centre)[0].top_m, -0.020, 1e-12);  // the floor, 5 mm thick
  ASSERT_TRUE(map.cell_at(0.0385, 0.0, &i, &j));
  const std::int64_t wall = map.cell(i, j);
  ASSERT_EQ(map.count(wall), 1);
  EXPECT_NEAR(map.begin(wall)[0].top_m, 0.025, 1e-12);  // the rim
  EXPECT_NEAR(solid_volume_m3(map), signed_volume_m3(testing::bucket_mesh()), 0.05 * signed_volume_m3(testing::bucket_mesh()));
}

// peel_spans' rasterisation written plainly (span_map.h): per triangle,
// per cell centre of its box (one cell beyond), the three edge functions
// each evaluated from the lexicographically smaller end of its edge, a
// centre on an edge kept by the top-left rule, z interpolated.
std::vector<SpanHit> plain_hits(const TriangleMesh& mesh, const Grid& g) {
  auto edge = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v, const Eigen::Vector2d& p) {
    auto raw = [](const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& q) {
      return (b.x() - a.x()) * (q.y() - a.y()) - (b.y() - a.y()) * (q.x() - a.x());
    };
    const bool u_first = u.x() < v.x() || (u.x() == v.x() && u.y() < v.y());
    return u_first ? raw(u, v, p) : -raw(v, u, p);
  };
  auto covers = [](double w, const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return w > 0.0 || (w == 0.0 && (v.y() < u.y() || (v.y() == u.y() && v.x() < u.x())));
  };
  std::vector<SpanHit> hits;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const double area = edge(a.head<2>(), b.head<2>(), c.head<2>());
    if (area == 0.0) continue;
    const int winding = area < 0.0 ? +1 : -1;
    if (area < 0.0) std::swap(b, c);
    const Eigen::Vector2d a2 = a.head<2>(), b2 = b.head<2>(), c2 = c.head<2>();
    auto first = [&](double lo, double origin) {
      return std::max(0, static_cast<int>(std::ceil((lo - origin) / g.cell_size_m - 0.5)) - 1);
    };
    auto last = [&](double hi, double origin, int n) {
      return std::min(n - 1, static_cast<int>(std::floor((hi - origin) / g.cell_size_m - 0.5)) + 1);
    };
    for (int j = first(std::min({a.y(), b.y(), c.y()}), g.origin_y_m);
         j <= last(std::max({a.y(), b.y(), c.y()}), g.origin_y_m, g.ny); ++j) {
      for (int i = first(std::min({a.x(), b.x(), c.x()}), g.origin_x_m);
           i <= last(std::max({a.x(), b.x(), c.x()}), g.origin_x_m, g.nx); ++i) {
        const Eigen::Vector2d p(g.centre_x(i), g.centre_y(j));
        const double wa = edge(b2, c2, p), wb = edge(c2, a2, p), wc = edge(a2, b2, p);
        if (!covers(wa, b2, c2) || !covers(wb, c2, a2) || !covers(wc, a2, b2) || !(wa + wb + wc > 0.0)) continue;
        hits.push_back({static_cast<std::int64_t>(j) * g.nx + i, (wa * a.z() + wb * b.z() + wc * c.z()) / (wa + wb + wc),
                        winding});
      }
    }
  }
  return hits;
}

// peel_spans (which works each edge's end order and ownership out once per
// triangle, and sorts the hits by cell first) gives the plain
// rasterisation's spans to the bit, whatever the hits' order: the bucket
// turned by odd angles, a box whose edges run through cell centres, and two
// boxes touching.
TEST(SpanMap, PeelingMatchesThePlainRasterisationBitForBit) {
  const Grid g = grid(44, 0.0025, -0.055);
  std::vector<TriangleMesh> meshes;
  for (const double deg : {0.0, 17.0, 80.0, 135.0, 211.0}) {
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(deg * M_PI / 180.0, Eigen::Vector3d(0.3, 1.0, 0.2).normalized()));
    meshes.push_back(transformed(testing::bucket_mesh(), Pose{{0.001, -0.002, 0.03}, turn}));
  }
  const TriangleMesh box = transformed(make_box({0.01, 0.01, 0.005}), Pose{{0.00125, 0.00125, 0.05}, Eigen::Quaterniond::Identity()});
  meshes.push_back(box);
  // touching boxes: hits at one height, an exit and an entry, which must merge in either order given
  meshes.push_back(merged(box, transformed(box, Pose{{0.004, 0.0, 0.01}, Eigen::Quaterniond::Identity()})));
  std::mt19937_64 rng(7);
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    std::vector<SpanHit> hits = plain_hits(meshes[k], g);
    std::shuffle(hits.begin(), hits.end(), rng);  // spans_from_hits takes them in any order
    const SpanMap peeled = peel_spans(meshes[k], g), plain = spans_from_hits(hits, g);
    ASSERT_FALSE(peeled.empty()) << k;
    EXPECT_EQ(peeled.first, plain.first) << k;
    ASSERT_EQ(peeled.spans.size(), plain.spans.size()) << k;
    for (std::size_t s = 0; s < plain.spans.size(); ++s) {
      EXPECT_EQ(peeled.spans[s].bottom_m, plain.spans[s].bottom_m) << k << " " << s;
      EXPECT_EQ(peeled.spans[s].top_m, plain.spans[s].top_m) << k << " " << s;
    }
  }
}

TEST(SpanMap, SpanUnderAndOverflow) {
  SpanMap map;
  map.grid = Grid{1, 1, 0.01, 0, 0};
  map.first = {0, 2};
  map.spans = {{0.0, 0.01, 0.0}, {0.02, 0.03, 0.0}};
  EXPECT_EQ(span_under(map, 0, -0.01), -1);
  EXPECT_EQ(span_under(map, 0, 0.005), 0);   // inside the lower
  EXPECT_EQ(span_under(map, 0, 0.015), 0);   // on it
  EXPECT_EQ(span_under(map, 0, 0.025), 1);
  map.spans[0].material_m = 0.015;           // reaches 5 mm into the upper span
  EXPECT_NEAR(push_overflow_up(&map, 0), 0.005, 1e-15);
  EXPECT_NEAR(map.spans[0].level_m(), 0.02, 1e-15);
  EXPECT_NEAR(map.spans[1].material_m, 0.005, 1e-15);
  EXPECT_NEAR(map.material_m3(), 0.015 * 1e-4, 1e-18);
}

}  // namespace
}  // namespace repose
