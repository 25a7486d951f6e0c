#pragma once
// Depth images over a height-field grid: one pixel per cell, orthographic,
// looking straight up from below or straight down from above. This is the
// Z-buffer collision test of the ground model (from below: the underside of
// an object over each cell) and the shadow-map machinery of the snow model
// (from above: the top surface).
//
// Two independent implementations compute the same image:
//   depth_image_cpu    - a vertical ray through each cell centre against every triangle
//   OsmesaDepthRenderer (osmesa_depth_renderer.h) - OpenGL rasterisation, read back from the depth buffer
// A pixel samples the surface at the cell centre, as GL samples pixel centres.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "models/core/geometry/grid.h"
#include "models/core/geometry/height_field.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {

enum class ViewFrom { kBelow, kAbove };

struct DepthImage {
  Grid grid;
  ViewFrom view = ViewFrom::kBelow;
  // ny x nx. From below: the lowest z of the surface over the cell centre
  // (the object's underside); from above: the highest z. Only meaningful where covered.
  ArrayXXdR z_m;
  // ny x nx, 1 where a surface was seen over the cell centre.
  Eigen::Array<std::uint8_t, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> covered;

  bool is_covered(int i, int j) const { return covered(j, i) != 0; }
  double z(int i, int j) const { return z_m(j, i); }
};

// Vertical z range that an OpenGL depth image resolves; the OSMesa path clips
// surfaces outside it (the CPU path has no range and clips nothing).
struct DepthRange {
  double z_min_m = -1.0;
  double z_max_m = 1.0;
};

DepthImage depth_image_cpu(const std::vector<TriangleMesh>& meshes, const Grid& grid, ViewFrom view);
// One mesh, without copying it into a vector first (the ground's collision
// renders a placed body every step).
DepthImage depth_image_cpu(const TriangleMesh& mesh, const Grid& grid, ViewFrom view);

// depth_image_cpu of one mesh, bit for bit, for a caller that renders a
// mesh again and again (the ground's underside renderer, every step).
// Which cells a triangle covers and its barycentric weights there depend on
// the faces and on x and y alone; they are kept for the last mesh, and a
// mesh with the same faces and the same x and y (a body pressed straight
// down or lifted: only its z moved) is drawn from them, interpolating z
// alone. Same inputs are compared bit for bit, so the image never differs.
class DepthImageCpuCache {
 public:
  DepthImage render(const TriangleMesh& mesh, const Grid& grid, ViewFrom view);

  // One covered cell centre of one face, in the order they were drawn.
  struct Hit {
    int face;
    int i, j;
    double wa, wb, wc;
  };

 private:
  bool same_footing(const TriangleMesh& mesh, const Grid& grid, ViewFrom view) const;

  bool valid_ = false;
  Grid grid_;
  ViewFrom view_ = ViewFrom::kBelow;
  MatrixX3iR faces_;
  std::vector<double> xy_;  // x, y of each vertex
  std::vector<Hit> hits_;
};

}  // namespace repose
