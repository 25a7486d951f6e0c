#pragma once
// Coloured triangles drawn into the current OSMesa context, and the image
// read back from it: the part of drawing a lit mesh that the figures'
// renderer (experiments/figures/render_image.cpp) and the snow pictures
// (models/snow/snow_picture.cpp) share. Each caller sets its own camera
// (projection and model-view matrices) and its own shading.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "models/core/gl/osmesa_context.h"
#include "models/core/io/png_io.h"

namespace repose {

struct ColouredTriangles {
  std::vector<float> xyz;          // 3 per vertex, in the frame the current matrices expect
  std::vector<std::uint8_t> rgb;   // 3 per vertex
  std::vector<unsigned> indices;   // empty: every three vertices are a triangle

  // Appends a vertex; its colour's components are clamped to [0, 1].
  void add_vertex(const Eigen::Vector3d& position, const Eigen::Vector3d& rgb01);
};

// Draws the triangles with the current matrices and depth state (nothing
// when empty). Colours are per vertex, interpolated as glShadeModel says.
void draw_triangles(const ColouredTriangles& triangles);

// The context's colour buffer, drawn at (width_px * supersample) x
// (height_px * supersample) with row 0 at the bottom, as a top-down RGB image
// of width_px x height_px, each pixel the rounded mean of its s x s block.
RgbImage read_image(const OsmesaContext& context, int width_px, int height_px, int supersample);

}  // namespace repose
