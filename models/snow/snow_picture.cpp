#include "models/snow/snow_picture.h"

#include <GL/gl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "models/core/base/error.h"
#include "models/core/gl/coloured_triangles.h"
#include "models/core/gl/osmesa_context.h"
#include "models/snow/snow_surface_mesh.h"

namespace repose {

namespace {

using Rgb = std::array<double, 3>;
constexpr Rgb kObjectRgb{0.40, 0.42, 0.46}, kSoilRgb{0.55, 0.42, 0.28}, kSnowRgb{0.97, 0.98, 1.0};

// The camera's frame: right and up span the picture, toward points at the eye.
struct Camera {
  Eigen::Vector3d right, up, toward;
  double u0 = 0, v0 = 0, w0 = 0, scale = 1, w_span = 1;  // picture = (p.right - u0) * scale, ...
};

Camera make_camera(const SnowModel& model, const SnowPictureOptions& o, double z_top_m) {
  const double el = o.view_elevation_rad, az = o.view_azimuth_rad;
  Camera c;
  c.toward = Eigen::Vector3d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  c.right = Eigen::Vector3d(-std::sin(az), std::cos(az), 0.0);
  c.up = c.toward.cross(c.right);
  const Grid& g = model.grid;
  double z_min = std::numeric_limits<double>::infinity();
  for (const SnowMap& m : model.maps) {
    for (int j = 0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) {
        if (m.covered(i, j)) z_min = std::min(z_min, m.base_z(i, j));
      }
    }
  }
  if (!std::isfinite(z_min)) z_min = z_top_m - g.cell_size_m;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d p(k & 1 ? g.origin_x_m + g.extent_x_m() : g.origin_x_m,
                            k & 2 ? g.origin_y_m + g.extent_y_m() : g.origin_y_m, k & 4 ? z_top_m : z_min);
    const double q[3] = {p.dot(c.right), p.dot(c.up), p.dot(c.toward)};
    for (int a = 0; a < 3; ++a) lo[a] = std::min(lo[a], q[a]), hi[a] = std::max(hi[a], q[a]);
  }
  const double margin = 1.05;
  c.scale = std::min(o.width_px / ((hi[0] - lo[0]) * margin), o.height_px / ((hi[1] - lo[1]) * margin));
  c.u0 = 0.5 * (lo[0] + hi[0]);
  c.v0 = 0.5 * (lo[1] + hi[1]);
  c.w0 = 0.5 * (lo[2] + hi[2]);
  c.w_span = std::max(hi[2] - lo[2], 1e-9) * 1.2;  // the depth range with room to spare
  return c;
}

double lambert(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  static const Eigen::Vector3d kSun = Eigen::Vector3d(-0.4, -0.6, 1.0).normalized();
  Eigen::Vector3d n = (b - a).cross(c - a);
  if (n.norm() == 0.0) return 0.45;
  n.normalize();
  return 0.45 + 0.55 * std::abs(n.dot(kSun));  // both faces lit: open meshes show their insides
}

// A flat-shaded triangle, its vertices in pixels about the picture's centre.
void add_triangle(const Camera& cam, const Eigen::Vector3d (&p)[3], const Rgb& colour, ColouredTriangles* b) {
  const double shade = lambert(p[0], p[1], p[2]);
  for (const Eigen::Vector3d& q : p) {
    b->add_vertex(Eigen::Vector3d((q.dot(cam.right) - cam.u0) * cam.scale, (q.dot(cam.up) - cam.v0) * cam.scale,
                                  2.0 * (q.dot(cam.toward) - cam.w0) / cam.w_span),  // glOrtho negates: nearer is smaller
                  Eigen::Vector3d(colour[0], colour[1], colour[2]) * shade);
  }
}

// Colour of a triangle of ground snow: soil mixing to snow over the first quarter cell of depth.
Rgb ground_rgb(double mean_depth_m, double full_m) {
  const double f = std::clamp(mean_depth_m / full_m, 0.0, 1.0);
  return {kSoilRgb[0] + f * (kSnowRgb[0] - kSoilRgb[0]), kSoilRgb[1] + f * (kSnowRgb[1] - kSoilRgb[1]),
          kSoilRgb[2] + f * (kSnowRgb[2] - kSoilRgb[2])};
}

// The mesh's triangles in `colour`; with `depth` (the ground's snow, on
// `grid`), each coloured by the mean depth at its corners (cell centres).
void add_mesh(const Camera& cam, const TriangleMesh& mesh, const Rgb& colour, const ArrayXXdR* depth, const Grid& grid,
              ColouredTriangles* b) {
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d p[3] = {mesh.V.row(mesh.F(f, 0)).transpose(), mesh.V.row(mesh.F(f, 1)).transpose(),
                                  mesh.V.row(mesh.F(f, 2)).transpose()};
    if (depth == nullptr) {
      add_triangle(cam, p, colour, b);
      continue;
    }
    double d = 0.0;
    for (const Eigen::Vector3d& q : p) {
      const int i = std::clamp(static_cast<int>(std::floor((q.x() - grid.origin_x_m) / grid.cell_size_m)), 0, grid.nx - 1);
      const int j = std::clamp(static_cast<int>(std::floor((q.y() - grid.origin_y_m) / grid.cell_size_m)), 0, grid.ny - 1);
      d += (*depth)(j, i) / 3.0;
    }
    add_triangle(cam, p, ground_rgb(d, 0.25 * grid.cell_size_m), b);
  }
}

}  // namespace

double snow_picture_top_m(const SnowModel& model, double snowfall_scale) {
  double top = -std::numeric_limits<double>::infinity();
  for (const TriangleMesh& m : model.occluders) {
    if (m.V.rows() > 0) top = std::max(top, m.V.col(2).maxCoeff());
  }
  for (const SnowMap& m : model.maps) {
    for (int j = 0; j < m.grid().ny; ++j) {
      for (int i = 0; i < m.grid().nx; ++i) {
        if (m.covered(i, j)) top = std::max(top, m.base_z(i, j));
      }
    }
  }
  if (!std::isfinite(top)) top = 0.0;
  const double fallen = model.options.snowfall.depth_between_m(0.0, model.time.duration_s) * snowfall_scale;
  return top + std::max(2.0 * fallen, model.grid.cell_size_m);
}

SnowPictureRenderer::SnowPictureRenderer(const SnowModel& model, const SnowPictureOptions& options, double z_top_m)
    : model_(model), options_(options), z_top_m_(z_top_m) {
  validate(options_);
  REPOSE_DEMAND(std::isfinite(z_top_m_));
  context_ = std::make_unique<OsmesaContext>(options_.width_px, options_.height_px);
}

SnowPictureRenderer::~SnowPictureRenderer() = default;

RgbImage SnowPictureRenderer::render(const SnowState& state) {
  REPOSE_DEMAND(state.depth_m.size() == model_.maps.size());
  const Camera cam = make_camera(model_, options_, z_top_m_);
  ColouredTriangles objects, snow;
  for (std::size_t k = 0; k < model_.occluders.size(); ++k) {
    if (model_.occluder_map[k] != model_.ground_map) add_mesh(cam, model_.occluders[k], kObjectRgb, nullptr, model_.grid, &objects);
  }
  for (std::size_t m = 0; m < model_.maps.size(); ++m) {
    const bool ground = static_cast<int>(m) == model_.ground_map;
    // the ground's whole surface (bare soil too); an object map's snow where there is some
    const double min_depth = ground ? -1.0 : 1e-3 * model_.grid.cell_size_m;
    const TriangleMesh mesh = snow_surface_mesh(model_.maps[m], state.depth_m[m], min_depth);
    add_mesh(cam, mesh, kSnowRgb, ground ? &state.depth_m[m] : nullptr, model_.grid, &snow);
  }
  context_->make_current(options_.width_px, options_.height_px);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(-0.5 * options_.width_px, 0.5 * options_.width_px, -0.5 * options_.height_px, 0.5 * options_.height_px,
          -1.0, 1.0);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glDisable(GL_CULL_FACE);
  glDisable(GL_LIGHTING);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(kSnowPictureBackground[0] / 255.0f, kSnowPictureBackground[1] / 255.0f,
               kSnowPictureBackground[2] / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  draw_triangles(objects);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(-1.0f, -4.0f);  // snow over the surface it lies on wins the depth test
  draw_triangles(snow);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glFinish();
  return read_image(*context_, options_.width_px, options_.height_px, 1);
}

}  // namespace repose
