// Coloured triangles drawn off-screen and read back: the image is top-down,
// colours are clamped, and a supersampled buffer is averaged block by block.

#include "models/core/gl/coloured_triangles.h"

#include <GL/gl.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdint>

namespace repose {
namespace {

using Pixel = std::array<int, 3>;

Pixel pixel(const RgbImage& img, int col, int row) {
  const std::size_t k = (static_cast<std::size_t>(row) * img.width + col) * 3;
  return {img.rgb[k], img.rgb[k + 1], img.rgb[k + 2]};
}

// Identity matrices (vertices in normalised device coordinates), a white background.
void clear_white(OsmesaContext* context, int width_px, int height_px) {
  context->make_current(width_px, height_px);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_DEPTH_TEST);
  glClearColor(1.0f, 1.0f, 1.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
}

TEST(ColouredTriangles, AddVertexClampsTheColour) {
  ColouredTriangles t;
  t.add_vertex(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(1.7, -0.2, 0.5));
  ASSERT_EQ(t.xyz.size(), 3u);
  EXPECT_FLOAT_EQ(t.xyz[2], 3.0f);
  EXPECT_EQ(t.rgb, (std::vector<std::uint8_t>{255, 0, 128}));
}

TEST(ColouredTriangles, TheLowerLeftTriangleIsAtTheImagesBottomLeft) {
  OsmesaContext context(1, 1);
  clear_white(&context, 40, 20);
  ColouredTriangles t;
  for (const auto& [x, y] : {std::pair{-1.0, -1.0}, {1.0, -1.0}, {-1.0, 1.0}}) {
    t.add_vertex(Eigen::Vector3d(x, y, 0), Eigen::Vector3d(1, 0, 0));
  }
  draw_triangles(t);
  glFinish();
  const RgbImage img = read_image(context, 40, 20, 1);
  ASSERT_EQ(img.width, 40);
  ASSERT_EQ(img.height, 20);
  EXPECT_EQ(pixel(img, 0, 19), (Pixel{255, 0, 0}));      // bottom left: red
  EXPECT_EQ(pixel(img, 39, 0), (Pixel{255, 255, 255}));  // top right: background
  int red = 0;
  for (int row = 0; row < 20; ++row) {
    for (int col = 0; col < 40; ++col) red += pixel(img, col, row) == Pixel{255, 0, 0};
  }
  EXPECT_NEAR(red, 400, 20);  // half of the picture, give or take the diagonal's pixels
}

TEST(ColouredTriangles, ASupersampledBufferIsAveragedBlockByBlock) {
  OsmesaContext context(1, 1);
  const int s = 4;
  clear_white(&context, 2 * s, 1 * s);
  ColouredTriangles t;  // the left half of the buffer black, as two indexed triangles
  for (const auto& [x, y] : {std::pair{-1.0, -1.0}, {0.0, -1.0}, {0.0, 1.0}, {-1.0, 1.0}}) {
    t.add_vertex(Eigen::Vector3d(x, y, 0), Eigen::Vector3d(0, 0, 0));
  }
  t.indices = {0, 1, 2, 0, 2, 3};
  draw_triangles(t);
  glFinish();
  const RgbImage img = read_image(context, 2, 1, s);
  EXPECT_EQ(pixel(img, 0, 0), (Pixel{0, 0, 0}));
  EXPECT_EQ(pixel(img, 1, 0), (Pixel{255, 255, 255}));
}

}  // namespace
}  // namespace repose
