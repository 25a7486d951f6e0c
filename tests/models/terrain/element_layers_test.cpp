#include "models/terrain/element_layers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "models/core/base/error.h"
#include "models/terrain/terrain.h"
#include "tests/models/terrain/terrain_fixtures.h"

namespace repose {
namespace {

using Vec3 = Eigen::Vector3d;

// Closest point on triangle abc to p (Ericson, Real-Time Collision Detection, 5.1.5).
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

double distance_to_mesh_m(const TriangleMesh& mesh, const Vec3& p) {
  double best = INFINITY;
  for (int f = 0; f < mesh.F.rows(); ++f) {
    const Vec3 a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    best = std::min(best, (closest_on_triangle(p, a, b, c) - p).norm());
  }
  return best;
}

struct Slope {
  Terrain terrain;
  TerrainSurface surface;
};

Slope cone_slope() {
  TerrainOptions o;
  o.slope_rad = 35.0 * std::numbers::pi / 180.0;
  o.contour_interval_m = 2.0;
  o.sample_spacing_m = 3.0;
  Terrain t = build_terrain({{"foot", test::circle_polygon(Point2(0, 0), 60.0, 48), 0.0}}, o);
  TerrainSurface s(t.mesh);
  return {std::move(t), std::move(s)};
}

ElementSource two_layer_source() {
  ElementSource src;
  src.region_m = test::rectangle_polygon(10, -8, 30, 8);  // on the cone's flank, across a ridge of the 48-gon
  src.layers = {{"bedrock debris", 1.0, 2, 0.7, 0.1}, {"topsoil", 0.6, 1, 0.4, 0.3}};
  return src;
}

ElementSource random_bed_source(std::uint64_t seed) {
  ElementSource src = two_layer_source();
  src.gap_fraction = 0.02;
  src.radius_spread = 0.3;
  src.position_jitter = 1.0;
  src.seed = seed;
  return src;
}

void expect_no_overlap_and_rest_on_the_surface(const Slope& slope, const ElementLayout& layout) {
  const auto& es = layout.elements;
  ASSERT_GT(es.size(), 200u);
  EXPECT_EQ(layout.skipped_off_terrain, 0);
  for (std::size_t i = 0; i < es.size(); ++i) {
    for (std::size_t j = i + 1; j < es.size(); ++j) {
      ASSERT_GE((es[i].centre_m - es[j].centre_m).norm(), es[i].radius_m + es[j].radius_m) << i << " " << j;
    }
  }
  int touching = 0;
  for (const PlacedElement& e : es) {
    const double d = distance_to_mesh_m(slope.terrain.mesh, e.centre_m);
    ASSERT_GE(d, e.radius_m - 1e-9);
    if (d < e.radius_m + 1e-6) ++touching;
  }
  // the first row rests on the ground: every sphere of it touches
  const std::size_t first_row = std::count_if(es.begin(), es.end(), [&](const PlacedElement& e) {
    return e.layer == 0 && e.centre_m.z() < slope.surface.height_at(e.centre_m.head<2>()).value() + 1.5;
  });
  EXPECT_GE(touching, static_cast<int>(first_row) - 2);
  EXPECT_GT(touching, 50);
}

TEST(ElementLayers, NoTwoElementsOverlapAndAllRestOnOrAboveTheSurface) {
  const Slope slope = cone_slope();
  expect_no_overlap_and_rest_on_the_surface(slope, place_element_layers(slope.surface, two_layer_source()));
}

TEST(ElementLayers, ARandomBedKeepsItsElementsApartAndOnTheSurface) {
  const Slope slope = cone_slope();
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    SCOPED_TRACE(seed);
    expect_no_overlap_and_rest_on_the_surface(slope, place_element_layers(slope.surface, random_bed_source(seed)));
  }
}

TEST(ElementLayers, TheSeedDrawsTheRadiiOverTheirRangeAndMovesTheCentres) {
  const Slope slope = cone_slope();
  const ElementSource src1 = random_bed_source(1), src2 = random_bed_source(2);
  const ElementLayout a = place_element_layers(slope.surface, src1);
  const ElementLayout again = place_element_layers(slope.surface, src1);
  const ElementLayout b = place_element_layers(slope.surface, src2);
  ASSERT_EQ(a.elements.size(), again.elements.size());
  for (std::size_t i = 0; i < a.elements.size(); ++i) ASSERT_EQ(a.elements[i].centre_m, again.elements[i].centre_m);
  const std::size_t n = std::min(a.elements.size(), b.elements.size());
  int radius_differs = 0, xy_differs = 0;
  for (std::size_t i = 0; i < n; ++i) {
    radius_differs += a.elements[i].radius_m != b.elements[i].radius_m;
    xy_differs += (a.elements[i].centre_m.head<2>() - b.elements[i].centre_m.head<2>()).norm() > 1e-6;
  }
  EXPECT_GT(radius_differs, static_cast<int>(n * 9 / 10));
  EXPECT_GT(xy_differs, static_cast<int>(n * 9 / 10));
  // each layer's radii fill [r (1 - spread), r]: uniform, so their mean is r (1 - spread / 2)
  for (int layer = 0; layer < 2; ++layer) {
    const double r = src1.layers[static_cast<std::size_t>(layer)].radius_m;
    double lo = INFINITY, hi = 0.0, sum = 0.0;
    int count = 0;
    for (const PlacedElement& e : a.elements) {
      if (e.layer != layer) continue;
      lo = std::min(lo, e.radius_m), hi = std::max(hi, e.radius_m), sum += e.radius_m, ++count;
    }
    ASSERT_GT(count, 50);
    EXPECT_GE(lo, r * (1.0 - src1.radius_spread));
    EXPECT_LE(hi, r);
    EXPECT_LT(lo, r * (1.0 - 0.9 * src1.radius_spread));
    EXPECT_GT(hi, r * (1.0 - 0.1 * src1.radius_spread));
    // standard error of the mean of a uniform over 0.3 r: 0.087 r / sqrt(count); 4 of them
    EXPECT_NEAR(sum / count, r * (1.0 - 0.5 * src1.radius_spread), 4.0 * 0.087 * r / std::sqrt(count));
  }
}

TEST(ElementLayers, WithoutSpreadOrJitterTheSeedIsNotUsed) {
  const Slope slope = cone_slope();
  ElementSource one = two_layer_source(), two = two_layer_source();
  two.seed = 2;
  const ElementLayout a = place_element_layers(slope.surface, one), b = place_element_layers(slope.surface, two);
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (std::size_t i = 0; i < a.elements.size(); ++i) {
    EXPECT_EQ(a.elements[i].centre_m, b.elements[i].centre_m);
    EXPECT_EQ(a.elements[i].radius_m, one.layers[static_cast<std::size_t>(a.elements[i].layer)].radius_m);
  }
}

TEST(ElementLayers, ARandomBedsBadSpreadOrJitterNamesTheField) {
  ElementSource src = two_layer_source();
  src.radius_spread = 1.0;
  EXPECT_THROW(
      {
        try {
          src.validate();
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("radius_spread = 1"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
  src.radius_spread = 0.0;
  src.position_jitter = -0.1;
  EXPECT_THROW(
      {
        try {
          src.validate();
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("position_jitter = -0.1"), std::string::npos) << e.what();
          throw;
        }
      },
      InputError);
}

TEST(ElementLayers, LayersStackInOrder) {
  const Slope slope = cone_slope();
  const ElementLayout layout = place_element_layers(slope.surface, two_layer_source());
  // above every point, the top layer lies over the bottom layer
  double bottom_mean = 0, top_mean = 0;
  int nb = 0, nt = 0;
  for (const PlacedElement& e : layout.elements) {
    const double above = e.centre_m.z() - slope.surface.height_at(e.centre_m.head<2>()).value();
    (e.layer == 0 ? bottom_mean : top_mean) += above;
    ++(e.layer == 0 ? nb : nt);
  }
  ASSERT_GT(nb, 0);
  ASSERT_GT(nt, 0);
  EXPECT_LT(bottom_mean / nb, top_mean / nt);
  EXPECT_GT(top_mean / nt, 2.0);  // above two rows of 1 m spheres
}

TEST(ElementLayers, SameInputSameLayout) {
  const Slope slope = cone_slope();
  const ElementLayout a = place_element_layers(slope.surface, two_layer_source());
  const ElementLayout b = place_element_layers(slope.surface, two_layer_source());
  ASSERT_EQ(a.elements.size(), b.elements.size());
  for (std::size_t i = 0; i < a.elements.size(); ++i) EXPECT_EQ(a.elements[i].centre_m, b.elements[i].centre_m);
}

TEST(ElementLayers, InvalidLayerNamesTheField) {
  ElementSource src = two_layer_source();
  src.layers[1].restitution = 1.5;
  try {
    src.validate();
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("layers[1] ('topsoil'): restitution"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace repose
