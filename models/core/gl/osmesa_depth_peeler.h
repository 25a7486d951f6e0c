#pragma once
// Depth peeling with OpenGL through OSMesa (Everitt 2001): every surface of
// a mesh over each cell centre, not only the nearest. Seen from below, pass
// k renders the mesh with the depth test LESS and a fragment shader that
// discards every fragment not farther than layer k - 1 at its pixel (kept
// in a float texture), so the depth buffer holds layer k: the next surface
// up. Passes stop when no pixel has a layer left.
//
// Layers are read from the 24-bit depth buffer: heights are quantised to
// (z_max - z_min) / (2^24 - 1), and surfaces closer than two such steps
// count as one (a fragment of the layer just read is discarded by that
// margin in the next pass, since the buffer holds it rounded). Peel faces
// turned one way at a time (all down, or all up) so that coincident
// surfaces of opposite orientation (two touching parts, a silhouette) are
// both seen; GL's rasterisation rule gives a centre on an edge shared by
// two triangles to exactly one of them, as the CPU path's rule does.
//
// One pixel per grid cell (as OsmesaDepthRenderer); grids larger than the
// context's maximum viewport are refused, not tiled. One peeler per thread.

#include <vector>

#include "models/core/geometry/depth_image.h"
#include "models/core/gl/osmesa_context.h"

namespace repose {

struct DepthLayers {
  Grid grid;
  // per cell (row-major, j outer): the heights of the surfaces over its centre, ascending
  std::vector<std::vector<double>> z_m;
};

class OsmesaDepthPeeler {
 public:
  // Throws std::runtime_error when OpenGL or its shaders cannot be started.
  OsmesaDepthPeeler();
  ~OsmesaDepthPeeler();
  OsmesaDepthPeeler(const OsmesaDepthPeeler&) = delete;
  OsmesaDepthPeeler& operator=(const OsmesaDepthPeeler&) = delete;

  // The layers of `mesh` seen from below over `grid` within `range` (surfaces
  // outside it are clipped). At most max_layers per cell; InputError when a
  // cell has more, or the grid exceeds the maximum viewport.
  DepthLayers peel_from_below(const TriangleMesh& mesh, const Grid& grid, DepthRange range, int max_layers = 256);

 private:
  OsmesaContext context_;
  unsigned program_ = 0;
  unsigned texture_ = 0;
};

}  // namespace repose
