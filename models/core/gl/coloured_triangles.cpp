#include "models/core/gl/coloured_triangles.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>

#include "models/core/base/error.h"

namespace repose {

void ColouredTriangles::add_vertex(const Eigen::Vector3d& position, const Eigen::Vector3d& rgb01) {
  for (int k = 0; k < 3; ++k) xyz.push_back(static_cast<float>(position[k]));
  for (int k = 0; k < 3; ++k) rgb.push_back(static_cast<std::uint8_t>(std::lround(std::clamp(rgb01[k], 0.0, 1.0) * 255.0)));
}

void draw_triangles(const ColouredTriangles& t) {
  REPOSE_DEMAND(t.xyz.size() == t.rgb.size());
  if (t.xyz.empty()) return;
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, t.xyz.data());
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, t.rgb.data());
  if (t.indices.empty()) {
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(t.xyz.size() / 3));
  } else {
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(t.indices.size()), GL_UNSIGNED_INT, t.indices.data());
  }
  glDisableClientState(GL_COLOR_ARRAY);
  glDisableClientState(GL_VERTEX_ARRAY);
}

RgbImage read_image(const OsmesaContext& context, int width_px, int height_px, int supersample) {
  const int s = supersample;
  REPOSE_DEMAND(s >= 1 && context.width_px() == width_px * s && context.height_px() == height_px * s);
  const std::vector<std::uint8_t>& rgba = context.rgba();
  RgbImage img;
  img.width = width_px;
  img.height = height_px;
  img.rgb.resize(static_cast<std::size_t>(width_px) * height_px * 3);
  const int big_width = width_px * s;
  for (int row = 0; row < height_px; ++row) {
    const int big_row0 = (height_px - 1 - row) * s;  // GL row 0 is the bottom
    for (int col = 0; col < width_px; ++col) {
      for (int k = 0; k < 3; ++k) {
        int sum = 0;
        for (int dy = 0; dy < s; ++dy) {
          for (int dx = 0; dx < s; ++dx) {
            sum += rgba[(static_cast<std::size_t>(big_row0 + dy) * big_width + col * s + dx) * 4 + k];
          }
        }
        img.rgb[(static_cast<std::size_t>(row) * width_px + col) * 3 + k] =
            static_cast<std::uint8_t>((sum + s * s / 2) / (s * s));
      }
    }
  }
  return img;
}

}  // namespace repose
