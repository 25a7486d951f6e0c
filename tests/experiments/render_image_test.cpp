// Figures rendered with OSMesa: size, content, where objects land, and
// determinism (same input, same bytes).

#include "experiments/figures/render_image.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <tuple>

#include "models/core/base/error.h"
#include "models/core/gl/osmesa_depth_renderer.h"

namespace repose {
namespace {

// A smooth mound on a 1.2 m x 0.9 m field with an off-centre origin.
HeightField mound() {
  const Grid g{60, 45, 0.02, -0.3, 0.2};
  HeightField f(g, 0.0);
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const double dx = g.centre_x(i) - 0.3, dy = g.centre_y(j) - 0.65;
      f.at(i, j) = 0.1 * std::exp(-(dx * dx + dy * dy) / 0.05);
    }
  }
  return f;
}

TriangleMesh sphere_at(const Eigen::Vector3d& centre, double radius) {
  Pose pose;
  pose.position_m = centre;
  return transformed(make_sphere(radius, 24), pose);
}

std::tuple<int, int, int> pixel(const RgbImage& img, int col, int row) {
  const std::size_t k = (static_cast<std::size_t>(row) * img.width + col) * 3;
  return {img.rgb[k], img.rgb[k + 1], img.rgb[k + 2]};
}

TEST(RenderImage, HasTheRequestedSize) {
  const HeightField field = mound();
  const CameraSpec camera = default_camera(field, {}, 161, 97);
  const RgbImage img = render_image(field, {}, camera);
  EXPECT_EQ(img.width, 161);
  EXPECT_EQ(img.height, 97);
  EXPECT_EQ(img.rgb.size(), 161u * 97u * 3u);
}

TEST(RenderImage, ShowsShadedGroundOnTheBackground) {
  const HeightField field = mound();
  const RgbImage img = render_image(field, {}, default_camera(field, {}, 200, 150));
  std::set<std::tuple<int, int, int>> colours;
  int background = 0;
  for (int row = 0; row < img.height; ++row) {
    for (int col = 0; col < img.width; ++col) {
      colours.insert(pixel(img, col, row));
      background += pixel(img, col, row) == std::make_tuple(255, 255, 255);
    }
  }
  EXPECT_GT(colours.size(), 50u);  // shading and the height colour map vary
  EXPECT_GT(background, 0);        // the field fits inside the view
  EXPECT_LT(background, img.width * img.height);
}

TEST(RenderImage, AnObjectChangesOnlyThePixelsWhereItProjects) {
  const HeightField field = mound();
  const Eigen::Vector3d centre(0.1, 0.5, 0.35);
  const double radius = 0.08;
  const std::vector<TriangleMesh> objects = {sphere_at(centre, radius)};
  const CameraSpec camera = default_camera(field, objects, 240, 180);
  const RgbImage without = render_image(field, {}, camera);
  const RgbImage with = render_image(field, objects, camera);

  const auto c = project_to_image(camera, centre);
  ASSERT_TRUE(c.has_value());
  const int col = static_cast<int>(c->x()), row = static_cast<int>(c->y());
  ASSERT_TRUE(col >= 0 && col < camera.width_px && row >= 0 && row < camera.height_px);
  EXPECT_NE(pixel(with, col, row), pixel(without, col, row));
  const auto [r, g, b] = pixel(with, col, row);
  EXPECT_GT(r, g + 30);  // the object colour is red-brown, the ground sand
  EXPECT_GT(r, b + 30);

  // the sphere's image lies within the projection of its bounding box; no
  // shadows are drawn, so every pixel outside that stays as it was
  double reach_px = 0.0;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d corner =
        centre + radius * Eigen::Vector3d((k & 1) ? 1 : -1, (k & 2) ? 1 : -1, (k & 4) ? 1 : -1);
    reach_px = std::max(reach_px, (*project_to_image(camera, corner) - *c).norm());
  }
  int changed = 0;
  for (int y = 0; y < camera.height_px; ++y) {
    for (int x = 0; x < camera.width_px; ++x) {
      if (pixel(with, x, y) == pixel(without, x, y)) continue;
      ++changed;
      EXPECT_LE((Eigen::Vector2d(x + 0.5, y + 0.5) - *c).norm(), reach_px + 1.5) << "pixel " << x << ", " << y;
    }
  }
  EXPECT_GT(changed, 20);
}

TEST(RenderImage, SameInputGivesSameBytes) {
  const HeightField field = mound();
  const std::vector<TriangleMesh> objects = {sphere_at({0.2, 0.6, 0.2}, 0.1)};
  const CameraSpec camera = default_camera(field, objects, 150, 100);
  EXPECT_EQ(render_image(field, objects, camera).rgb, render_image(field, objects, camera).rgb);
}

TEST(RenderImage, WithoutSupersamplingTheImageIsStillComplete) {
  const HeightField field = mound();
  RenderImageOptions options;
  options.supersample = 1;
  const CameraSpec camera = default_camera(field, {}, 90, 70);
  const RgbImage img = render_image(field, {}, camera, options);
  EXPECT_EQ(img.rgb.size(), 90u * 70u * 3u);
  // the middle of the field is in the middle of the image, and it is ground
  EXPECT_NE(pixel(img, 45, 35), std::make_tuple(255, 255, 255));
}

TEST(RenderImage, LeavesADepthRendererOnTheSameThreadWorking) {
  // two OSMesa contexts on one thread: each makes itself current before drawing
  OsmesaDepthRenderer renderer;
  const HeightField field = mound();
  const std::vector<TriangleMesh> objects = {sphere_at({0.2, 0.6, 0.2}, 0.1)};
  const DepthImage before = renderer.render(objects, field.grid(), ViewFrom::kBelow, DepthRange{-1.0, 1.0});
  const RgbImage img = render_image(field, objects, default_camera(field, objects, 64, 48));
  const DepthImage after = renderer.render(objects, field.grid(), ViewFrom::kBelow, DepthRange{-1.0, 1.0});
  EXPECT_GT(before.covered.cast<int>().sum(), 50);
  EXPECT_TRUE((before.covered == after.covered).all());
  EXPECT_TRUE((before.z_m == after.z_m || before.covered == 0).all());
}

TEST(DefaultCamera, LooksFromTheSouthEastAt35Degrees) {
  const HeightField field = mound();
  const CameraSpec c = default_camera(field);
  const Eigen::Vector3d d = c.position_m - c.target_m;
  EXPECT_GT(d.x(), 0.0);  // east
  EXPECT_LT(d.y(), 0.0);  // south
  EXPECT_NEAR(d.x(), -d.y(), 1e-12);
  EXPECT_NEAR(std::asin(d.z() / d.norm()), 35.0 * std::numbers::pi / 180.0, 1e-12);
  // every corner of the field is inside the image
  const Grid& g = field.grid();
  for (double x : {g.origin_x_m, g.origin_x_m + g.extent_x_m()}) {
    for (double y : {g.origin_y_m, g.origin_y_m + g.extent_y_m()}) {
      const auto p = project_to_image(c, {x, y, 0.0});
      ASSERT_TRUE(p.has_value());
      EXPECT_GT(p->x(), 0.0);
      EXPECT_LT(p->x(), c.width_px);
      EXPECT_GT(p->y(), 0.0);
      EXPECT_LT(p->y(), c.height_px);
    }
  }
}

TEST(RenderImage, RefusesAnUnusableCamera) {
  const HeightField field = mound();
  CameraSpec c = default_camera(field);
  c.target_m = c.position_m;
  EXPECT_THROW(render_image(field, {}, c), InputError);
  c = default_camera(field);
  c.up = c.target_m - c.position_m;
  EXPECT_THROW(render_image(field, {}, c), InputError);
  c = default_camera(field);
  c.width_px = 0;
  EXPECT_THROW(render_image(field, {}, c), InputError);
  c = default_camera(field);
  c.fov_y_rad = std::numbers::pi;
  EXPECT_THROW(render_image(field, {}, c), InputError);
}

}  // namespace
}  // namespace repose
