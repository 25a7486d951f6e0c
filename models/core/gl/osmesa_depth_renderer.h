#pragma once
// Depth images (depth_image.h) rendered with OpenGL through OSMesa: the
// Z-buffer of the ground model and the shadow maps of the snow model.
//
// Camera: orthographic, one pixel per grid cell, pixel centre = cell centre,
// so GL's pixel-centre sampling equals depth_image_cpu's vertical ray. The
// depth buffer holds d = (z - z_min) / (z_max - z_min) looking up from below
// (the depth test LESS keeps the lowest z) and d = (z_max - z) / (z_max - z_min)
// looking down from above (keeps the highest z). Surfaces outside the
// DepthRange are clipped away; a surface exactly at the far end (z_max from
// below, z_min from above) counts as not covered.
//
// Resolution: 24-bit depth, so z is quantised to (z_max - z_min) / (2^24 - 1);
// keep the range tight around what matters (2 m resolves 0.12 um).
// Face culling is off: open and concave meshes show their inner faces.
// Grids larger than the context's maximum viewport (16384 px with llvmpipe)
// are rendered in tiles.
//
// One renderer per thread (it owns an OsmesaContext).

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "models/core/geometry/depth_image.h"
#include "models/core/geometry/grid.h"
#include "models/core/geometry/height_field.h"
#include "models/core/gl/osmesa_context.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {

using ArrayXXu8R = Eigen::Array<std::uint8_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The objects' depth image with the ground drawn first, as the ground paper's
// Z-buffer test does: depth is the nearer of ground and objects per cell.
struct GroundContactImage {
  // z_m: the nearer of the ground height and the objects' surface (all cells
  // covered where the ground lies inside the depth range).
  DepthImage nearest;
  // ny x nx, 1 where an object's surface is strictly nearer than the ground:
  // seen from below, where an object's underside dips below the ground surface.
  ArrayXXu8R object_nearer;
};

// Vertices of `mesh` in normalised device coordinates of the pixel window
// [i0, i0 + width) x [j0, j0 + height) of `grid`: #V x 3 floats, cell centre
// (i + 0.5, j + 0.5) on the pixel centre, depth d of z (above) on 2d - 1.
// Shared by the renderers that draw depth images (osmesa_depth_peeler.h).
std::vector<float> depth_device_coordinates(const TriangleMesh& mesh, const Grid& grid, int i0, int j0, int width,
                                            int height, ViewFrom view, DepthRange range);

// The GL state of a depth-only render: identity matrices, no culling,
// lighting, blending or stencil, colour writes off, depth test LESS; clears
// the depth (to 1) and stencil buffers of the current context.
void set_depth_only_gl_state();

class OsmesaDepthRenderer {
 public:
  // max_tile_px: the largest tile side rendered at once (clamped to the
  // context's maximum viewport); smaller values only exist to test tiling.
  explicit OsmesaDepthRenderer(int max_tile_px = 4096);

  DepthImage render(const std::vector<TriangleMesh>& meshes, const Grid& grid, ViewFrom view, DepthRange range);

  // Draws the ground height field first (each cell a flat square at its
  // height, so the pixel samples exactly h(i, j)), then the objects with the
  // depth test LESS; the stencil marks where an object won.
  GroundContactImage render_with_ground(const std::vector<TriangleMesh>& meshes, const HeightField& ground,
                                        ViewFrom view, DepthRange range);

  // The z step of the depth buffer over a range (m).
  double depth_step_m(DepthRange range) const;
  int tile_px() const { return tile_px_; }

 private:
  GroundContactImage render_tiles(const std::vector<TriangleMesh>& meshes, const HeightField* ground, const Grid& grid,
                                  ViewFrom view, DepthRange range);

  OsmesaContext context_;
  int tile_px_ = 0;
};

}  // namespace repose
