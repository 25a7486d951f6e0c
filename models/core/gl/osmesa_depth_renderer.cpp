#include "models/core/gl/osmesa_depth_renderer.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "models/core/base/error.h"

namespace repose {

namespace {

constexpr std::uint32_t kClearDepth = 0xFFFFFFFFu;  // depth 1.0 read back as GL_UNSIGNED_INT

// The pixels of one tile: columns [i0, i0 + width) and rows [j0, j0 + height) of the grid.
struct Tile {
  int i0 = 0, j0 = 0, width = 0, height = 0;
};

// Normalised depth d in [0, 1] of height z: 0 is nearest to the eye.
double depth_of(double z_m, ViewFrom view, DepthRange range) {
  const double span = range.z_max_m - range.z_min_m;
  return view == ViewFrom::kBelow ? (z_m - range.z_min_m) / span : (range.z_max_m - z_m) / span;
}

double z_of(double depth, ViewFrom view, DepthRange range) {
  const double span = range.z_max_m - range.z_min_m;
  return view == ViewFrom::kBelow ? range.z_min_m + depth * span : range.z_max_m - depth * span;
}

std::vector<float> device_coordinates(const TriangleMesh& mesh, const Grid& grid, const Tile& tile, ViewFrom view,
                                      DepthRange range) {
  return depth_device_coordinates(mesh, grid, tile.i0, tile.j0, tile.width, tile.height, view, range);
}

void draw_meshes(const std::vector<TriangleMesh>& meshes, const Grid& grid, const Tile& tile, ViewFrom view,
                 DepthRange range) {
  glEnableClientState(GL_VERTEX_ARRAY);
  for (const TriangleMesh& mesh : meshes) {
    if (mesh.empty()) continue;
    const std::vector<float> ndc = device_coordinates(mesh, grid, tile, view, range);
    glVertexPointer(3, GL_FLOAT, 0, ndc.data());
    // F is row-major #F x 3 non-negative ints: directly an index array
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(mesh.F.size()), GL_UNSIGNED_INT, mesh.F.data());
  }
  glDisableClientState(GL_VERTEX_ARRAY);
}

// Writes the ground heights of the tile straight into the depth buffer: one
// depth per pixel, exactly h(i, j) at the cell centre.
void draw_ground_depth(const HeightField& ground, const Tile& tile, ViewFrom view, DepthRange range) {
  std::vector<float> depth(static_cast<std::size_t>(tile.width) * static_cast<std::size_t>(tile.height));
  for (int r = 0; r < tile.height; ++r) {
    for (int c = 0; c < tile.width; ++c) {
      const double d = depth_of(ground.at(tile.i0 + c, tile.j0 + r), view, range);
      depth[static_cast<std::size_t>(r) * tile.width + c] = static_cast<float>(std::clamp(d, 0.0, 1.0));
    }
  }
  glDepthFunc(GL_ALWAYS);
  glRasterPos2f(-1.0f, -1.0f);  // window (0, 0) with identity matrices
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glDrawPixels(tile.width, tile.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  glDepthFunc(GL_LESS);
}

void validate(const Grid& grid, DepthRange range) {
  if (!(grid.nx >= 1 && grid.ny >= 1 && grid.cell_size_m > 0.0 && std::isfinite(grid.cell_size_m))) {
    throw InputError("depth image: the grid needs nx, ny >= 1 and a positive cell size, got " +
                     std::to_string(grid.nx) + " x " + std::to_string(grid.ny) + " cells of " +
                     std::to_string(grid.cell_size_m) + " m");
  }
  if (!(std::isfinite(range.z_min_m) && std::isfinite(range.z_max_m) && range.z_max_m > range.z_min_m)) {
    throw InputError("depth image: the depth range needs finite z_min_m < z_max_m, got [" +
                     std::to_string(range.z_min_m) + ", " + std::to_string(range.z_max_m) + "]");
  }
}

}  // namespace

// Computed in double relative to the pixel window so that float keeps
// sub-pixel precision on any grid.
std::vector<float> depth_device_coordinates(const TriangleMesh& mesh, const Grid& grid, int i0, int j0, int width,
                                            int height, ViewFrom view, DepthRange range) {
  std::vector<float> out(static_cast<std::size_t>(mesh.V.rows()) * 3);
  for (Eigen::Index v = 0; v < mesh.V.rows(); ++v) {
    const double u = (mesh.V(v, 0) - grid.origin_x_m) / grid.cell_size_m - i0;
    const double w = (mesh.V(v, 1) - grid.origin_y_m) / grid.cell_size_m - j0;
    const std::size_t k = static_cast<std::size_t>(v) * 3;
    out[k + 0] = static_cast<float>(2.0 * u / width - 1.0);
    out[k + 1] = static_cast<float>(2.0 * w / height - 1.0);
    out[k + 2] = static_cast<float>(2.0 * depth_of(mesh.V(v, 2), view, range) - 1.0);
  }
  return out;
}

void set_depth_only_gl_state() {
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_CULL_FACE);  // open and concave meshes show their inner faces
  glDisable(GL_LIGHTING);
  glDisable(GL_BLEND);
  glDisable(GL_DITHER);
  glDisable(GL_STENCIL_TEST);
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // only depth matters
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glDepthRange(0.0, 1.0);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

OsmesaDepthRenderer::OsmesaDepthRenderer(int max_tile_px) : context_(1, 1) {
  REPOSE_DEMAND(max_tile_px >= 1);
  tile_px_ = std::min(max_tile_px, context_.max_size_px());
}

double OsmesaDepthRenderer::depth_step_m(DepthRange range) const {
  return (range.z_max_m - range.z_min_m) / (std::ldexp(1.0, context_.depth_bits()) - 1.0);
}

DepthImage OsmesaDepthRenderer::render(const std::vector<TriangleMesh>& meshes, const Grid& grid, ViewFrom view,
                                       DepthRange range) {
  return render_tiles(meshes, nullptr, grid, view, range).nearest;
}

GroundContactImage OsmesaDepthRenderer::render_with_ground(const std::vector<TriangleMesh>& meshes,
                                                           const HeightField& ground, ViewFrom view,
                                                           DepthRange range) {
  REPOSE_DEMAND(ground.all_finite());
  return render_tiles(meshes, &ground, ground.grid(), view, range);
}

GroundContactImage OsmesaDepthRenderer::render_tiles(const std::vector<TriangleMesh>& meshes,
                                                     const HeightField* ground, const Grid& grid, ViewFrom view,
                                                     DepthRange range) {
  validate(grid, range);
  GroundContactImage out;
  DepthImage& img = out.nearest;
  img.grid = grid;
  img.view = view;
  img.z_m = ArrayXXdR::Constant(grid.ny, grid.nx, std::numeric_limits<double>::quiet_NaN());
  img.covered.setZero(grid.ny, grid.nx);
  out.object_nearer.setZero(grid.ny, grid.nx);

  std::vector<std::uint32_t> depth;
  std::vector<std::uint8_t> stencil;
  for (int j0 = 0; j0 < grid.ny; j0 += tile_px_) {
    for (int i0 = 0; i0 < grid.nx; i0 += tile_px_) {
      const Tile tile{i0, j0, std::min(tile_px_, grid.nx - i0), std::min(tile_px_, grid.ny - j0)};
      context_.make_current(tile.width, tile.height);
      set_depth_only_gl_state();
      if (ground != nullptr) {
        draw_ground_depth(*ground, tile, view, range);
        // mark every pixel where an object fragment passes the depth test
        glEnable(GL_STENCIL_TEST);
        glStencilFunc(GL_ALWAYS, 1, 0xFF);
        glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
      }
      draw_meshes(meshes, grid, tile, view, range);

      const std::size_t pixels = static_cast<std::size_t>(tile.width) * static_cast<std::size_t>(tile.height);
      depth.resize(pixels);
      glPixelStorei(GL_PACK_ALIGNMENT, 1);
      glReadPixels(0, 0, tile.width, tile.height, GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, depth.data());
      if (ground != nullptr) {
        stencil.resize(pixels);
        glReadPixels(0, 0, tile.width, tile.height, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, stencil.data());
      }
      // window row r is grid row j0 + r: both grow with y, no flip
      for (int r = 0; r < tile.height; ++r) {
        for (int c = 0; c < tile.width; ++c) {
          const std::size_t k = static_cast<std::size_t>(r) * tile.width + c;
          if (depth[k] == kClearDepth) continue;
          const double d = depth[k] / static_cast<double>(kClearDepth);
          img.z_m(j0 + r, i0 + c) = z_of(d, view, range);
          img.covered(j0 + r, i0 + c) = 1;
          if (ground != nullptr) out.object_nearer(j0 + r, i0 + c) = stencil[k] != 0 ? 1 : 0;
        }
      }
    }
  }
  return out;
}

}  // namespace repose
