#pragma once
// Shadow maps along a snowfall direction (the snow paper 2.2.1 and 2.2.3,
// Fig. 3 and 5): the whole scene is seen along the direction snow travels,
// and a point of a snow map is reached by snow from that direction (lit)
// unless something lies above it along the direction.
//
// How: every occluder is turned into the light frame (u, v, w), w pointing
// back towards where the snow comes from, and rendered top-down in that
// frame (TopDownRenderer: the highest w over each (u, v) pixel, the first
// surface falling snow meets). A point p is lit when w(p) + bias >= the
// image's w at the pixel containing (u(p), v(p)) (nearest pixel, as the
// paper's Z-buffer comparison), or when that pixel saw nothing.
//
// Bias: the point lies on a surface that is itself in the image, sampled up
// to half a pixel away; on a surface tilted by t against the light frame its
// w changes by up to (pixel / sqrt 2) * tan t across that offset. The bias,
// shadow_bias_cells * pixel * (1 + tan(tilt of the direction)), covers level
// surfaces at any tilt; steeper surfaces can shadow themselves (acne), and
// an occluder thinner than the bias does not shadow (a leak). The ray-cast
// baseline (ray_cast_probability.h) uses the same bias, so the two differ by
// the image's sampling only.

#include <vector>

#include <Eigen/Core>

#include "models/core/geometry/depth_image.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/snow/snow_map.h"
#include "models/snow/top_down_renderer.h"

namespace repose {

// An orthonormal frame with w = -travel. For straight-down snow it is
// (x, y, z), so the shadow map is the top-down image itself.
struct LightFrame {
  Eigen::Vector3d u, v, w;
  Eigen::Vector3d to_light(const Eigen::Vector3d& p) const { return {p.dot(u), p.dot(v), p.dot(w)}; }
};

LightFrame light_frame(const Eigen::Vector3d& travel);

// The bias (m) for a direction: shadow_bias_cells * pixel_m * (1 + tan(tilt)).
double shadow_bias_m(const Eigen::Vector3d& travel, double pixel_m, double shadow_bias_cells);

struct ShadowMap {
  LightFrame frame;
  DepthImage depth;  // over the (u, v) plane, z = w
  double bias_m = 0.0;

  bool is_lit(const Eigen::Vector3d& p_world) const;
};

// The shadow map of `occluders` along `travel`, with pixels of pixel_m,
// covering the occluders and every point of `maps`.
ShadowMap render_shadow_map(const std::vector<TriangleMesh>& occluders, const std::vector<SnowMap>& maps,
                            const Eigen::Vector3d& travel, double pixel_m, double shadow_bias_cells,
                            TopDownRenderer* renderer);

}  // namespace repose
