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

TEST(ElementLayers, NoTwoElementsOverlapAndAllRestOnOrAboveTheSurface) {
  const Slope slope = cone_slope();
  const ElementLayout layout = place_element_layers(slope.surface, two_layer_source());
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
