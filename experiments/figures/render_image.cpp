#include "experiments/figures/render_image.h"

#include <GL/gl.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "models/core/base/error.h"
#include "models/core/gl/coloured_triangles.h"
#include "models/core/gl/osmesa_context.h"

namespace repose {

namespace {

constexpr double kDefaultElevationRad = 35.0 * std::numbers::pi / 180.0;

double lambert(const Eigen::Vector3d& normal, const RenderImageOptions& o) {
  const double diffuse = std::max(0.0, normal.dot(o.light_direction.normalized()));
  return o.ambient + (1.0 - o.ambient) * diffuse;
}

// The field as a surface through the cell centres, smooth-shaded with
// normals from central differences and coloured by height.
ColouredTriangles ground_triangles(const HeightField& field, const Eigen::Vector3d& origin,
                                   const RenderImageOptions& o) {
  ColouredTriangles t;
  const Grid& g = field.grid();
  const double lo = field.min_height_m(), hi = field.max_height_m();
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const int il = std::max(i - 1, 0), ir = std::min(i + 1, g.nx - 1);
      const int jd = std::max(j - 1, 0), ju = std::min(j + 1, g.ny - 1);
      const double dhdx = ir > il ? (field.at(ir, j) - field.at(il, j)) / ((ir - il) * g.cell_size_m) : 0.0;
      const double dhdy = ju > jd ? (field.at(i, ju) - field.at(i, jd)) / ((ju - jd) * g.cell_size_m) : 0.0;
      const Eigen::Vector3d normal = Eigen::Vector3d(-dhdx, -dhdy, 1.0).normalized();
      const double s = hi > lo ? (field.at(i, j) - lo) / (hi - lo) : 0.5;
      const Eigen::Vector3d colour = ((1 - s) * o.ground_low_rgb + s * o.ground_high_rgb) * lambert(normal, o);
      t.add_vertex(Eigen::Vector3d(g.centre_x(i), g.centre_y(j), field.at(i, j)) - origin, colour);
    }
  }
  for (int j = 0; j + 1 < g.ny; ++j) {
    for (int i = 0; i + 1 < g.nx; ++i) {
      const unsigned a = static_cast<unsigned>(j * g.nx + i), b = a + 1;
      const unsigned c = a + static_cast<unsigned>(g.nx), d = c + 1;
      t.indices.insert(t.indices.end(), {a, b, d, a, d, c});
    }
  }
  return t;
}

// Objects flat-shaded per face, lit on the side that faces the eye.
ColouredTriangles object_triangles(const std::vector<TriangleMesh>& objects, const Eigen::Vector3d& origin,
                                   const Eigen::Vector3d& eye, const RenderImageOptions& o) {
  ColouredTriangles t;
  for (const TriangleMesh& m : objects) {
    for (Eigen::Index f = 0; f < m.F.rows(); ++f) {
      const Eigen::Vector3d a = m.V.row(m.F(f, 0)), b = m.V.row(m.F(f, 1)), c = m.V.row(m.F(f, 2));
      Eigen::Vector3d n = (b - a).cross(c - a);
      if (n.squaredNorm() == 0.0) continue;
      n.normalize();
      if (n.dot(eye - a) < 0) n = -n;
      const Eigen::Vector3d colour = o.object_rgb * lambert(n, o);
      for (const Eigen::Vector3d* p : {&a, &b, &c}) t.add_vertex(*p - origin, colour);
    }
  }
  return t;
}

// A coloured mesh smooth-shaded: area-weighted vertex normals turned towards the eye.
ColouredTriangles coloured_mesh_triangles(const ColouredMesh& m, const Eigen::Vector3d& origin,
                                          const Eigen::Vector3d& eye, const RenderImageOptions& o) {
  ColouredTriangles t;
  const Eigen::Index nv = m.mesh.V.rows();
  std::vector<Eigen::Vector3d> normals(static_cast<std::size_t>(nv), Eigen::Vector3d::Zero());
  for (Eigen::Index f = 0; f < m.mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = m.mesh.V.row(m.mesh.F(f, 0)), b = m.mesh.V.row(m.mesh.F(f, 1)),
                          c = m.mesh.V.row(m.mesh.F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);  // twice the area, along the normal
    for (int k = 0; k < 3; ++k) normals[static_cast<std::size_t>(m.mesh.F(f, k))] += n;
  }
  for (Eigen::Index v = 0; v < nv; ++v) {
    const Eigen::Vector3d p = m.mesh.V.row(v);
    Eigen::Vector3d n = normals[static_cast<std::size_t>(v)];
    n = n.squaredNorm() > 0.0 ? n.normalized() : Eigen::Vector3d((eye - p).normalized());
    if (n.dot(eye - p) < 0) n = -n;
    t.add_vertex(p - origin, m.vertex_rgb[static_cast<std::size_t>(v)].cwiseMax(0.0).cwiseMin(1.0) * lambert(n, o));
  }
  for (Eigen::Index f = 0; f < m.mesh.F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) t.indices.push_back(static_cast<unsigned>(m.mesh.F(f, k)));
  }
  if (t.indices.empty()) t.xyz.clear();  // nothing to draw (unindexed drawing would misread the vertices)
  return t;
}

// World-to-eye rotation and translation relative to the target (gluLookAt).
Eigen::Matrix4d view_matrix(const CameraSpec& camera) {
  const Eigen::Vector3d eye = camera.position_m - camera.target_m;
  const Eigen::Vector3d forward = (-eye).normalized();
  const Eigen::Vector3d side = forward.cross(camera.up).normalized();
  const Eigen::Vector3d up = side.cross(forward);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = side.transpose();
  m.block<1, 3>(1, 0) = up.transpose();
  m.block<1, 3>(2, 0) = -forward.transpose();
  m.block<3, 1>(0, 3) = -m.block<3, 3>(0, 0) * eye;
  return m;
}

// gluPerspective.
Eigen::Matrix4d projection_matrix(const CameraSpec& camera, double near_m, double far_m) {
  const double f = 1.0 / std::tan(camera.fov_y_rad / 2);
  const double aspect = static_cast<double>(camera.width_px) / camera.height_px;
  Eigen::Matrix4d p = Eigen::Matrix4d::Zero();
  p(0, 0) = f / aspect;
  p(1, 1) = f;
  p(2, 2) = (far_m + near_m) / (near_m - far_m);
  p(2, 3) = 2 * far_m * near_m / (near_m - far_m);
  p(3, 2) = -1;
  return p;
}

// Near and far planes that bracket everything drawn, for the depth buffer's resolution.
void clip_planes(const std::vector<const ColouredTriangles*>& parts, const Eigen::Matrix4d& view, double* near_m,
                 double* far_m) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  for (const ColouredTriangles* t : parts) {
    for (std::size_t k = 0; k + 2 < t->xyz.size(); k += 3) {
      const double depth = -view.row(2).dot(Eigen::RowVector4d(t->xyz[k], t->xyz[k + 1], t->xyz[k + 2], 1.0));
      lo = std::min(lo, depth);
      hi = std::max(hi, depth);
    }
  }
  if (!(hi > 0.0)) hi = 1.0;  // nothing in front of the camera
  *far_m = hi * 1.01;
  *near_m = std::max(lo * 0.99, *far_m * 1e-4);
}

void validate(const CameraSpec& c, const RenderImageOptions& o, int max_px) {
  auto fail = [](const std::string& what) { throw InputError("camera: " + what); };
  if (c.width_px < 1 || c.height_px < 1) fail("width_px and height_px must be >= 1");
  if (o.supersample < 1) fail("supersample must be >= 1");
  if (static_cast<long>(c.width_px) * o.supersample > max_px || static_cast<long>(c.height_px) * o.supersample > max_px) {
    fail("image of " + std::to_string(c.width_px) + " x " + std::to_string(c.height_px) + " px at supersample " +
         std::to_string(o.supersample) + " exceeds the off-screen limit of " + std::to_string(max_px) + " px");
  }
  if (!(c.fov_y_rad > 0.0 && c.fov_y_rad < std::numbers::pi)) fail("fov must lie in (0, 180) degrees");
  const Eigen::Vector3d view = c.target_m - c.position_m;
  if (!view.allFinite() || view.norm() == 0.0) fail("position and target must differ");
  if (!c.up.allFinite() || view.normalized().cross(c.up).norm() < 1e-9) fail("up must not be along the view direction");
}

// Draws the parts (vertices relative to camera.target_m, so that float keeps
// its precision near the view) into the current context
// (made current at the supersampled size) and reads the image back.
RgbImage draw_parts(const std::vector<const ColouredTriangles*>& parts, const CameraSpec& camera,
                    const RenderImageOptions& options, const OsmesaContext& context) {
  const Eigen::Matrix4d view = view_matrix(camera);
  double near_m = 0, far_m = 0;
  clip_planes(parts, view, &near_m, &far_m);
  const Eigen::Matrix4d projection = projection_matrix(camera, near_m, far_m);

  glMatrixMode(GL_PROJECTION);
  glLoadMatrixd(projection.data());  // Eigen is column-major, as GL expects
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixd(view.data());
  glDisable(GL_CULL_FACE);
  glDisable(GL_LIGHTING);
  glDisable(GL_DITHER);
  glShadeModel(GL_SMOOTH);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  const Eigen::Vector3d bg = options.background_rgb.cwiseMax(0.0).cwiseMin(1.0);
  glClearColor(static_cast<float>(bg.x()), static_cast<float>(bg.y()), static_cast<float>(bg.z()), 1.0f);
  glClearDepth(1.0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  for (const ColouredTriangles* t : parts) draw_triangles(*t);
  glFinish();
  return read_image(context, camera.width_px, camera.height_px, options.supersample);
}

}  // namespace

CameraSpec camera_around(const Aabb& box, const Eigen::Vector3d& from_direction, int width_px, int height_px) {
  CameraSpec c;
  c.width_px = width_px;
  c.height_px = height_px;
  c.target_m = (box.min + box.max) / 2;
  const double radius = std::max((box.max - box.min).norm() / 2, 1e-3);
  // the narrower of the vertical and horizontal half-angles must hold the bounding sphere
  const double aspect = static_cast<double>(width_px) / height_px;
  const double half = std::min(c.fov_y_rad / 2, std::atan(std::tan(c.fov_y_rad / 2) * aspect));
  const double distance = 1.05 * radius / std::sin(half);
  c.position_m = c.target_m + distance * from_direction.normalized();
  c.up = Eigen::Vector3d::UnitZ();
  return c;
}

CameraSpec default_camera(const HeightField& field, const std::vector<TriangleMesh>& objects, int width_px,
                          int height_px) {
  const Grid& g = field.grid();
  Aabb box;
  box.extend(Eigen::Vector3d(g.origin_x_m, g.origin_y_m, field.min_height_m()));
  box.extend(Eigen::Vector3d(g.origin_x_m + g.extent_x_m(), g.origin_y_m + g.extent_y_m(), field.max_height_m()));
  for (const TriangleMesh& m : objects) {
    if (m.empty()) continue;
    const Aabb b = bounding_box(m);
    box.extend(b.min);
    box.extend(b.max);
  }
  const Eigen::Vector3d south_east(std::numbers::sqrt2 / 2, -std::numbers::sqrt2 / 2, 0.0);
  const Eigen::Vector3d direction =
      std::cos(kDefaultElevationRad) * south_east + std::sin(kDefaultElevationRad) * Eigen::Vector3d::UnitZ();
  return camera_around(box, direction, width_px, height_px);
}

RgbImage render_image(const HeightField& field, const std::vector<TriangleMesh>& objects, const CameraSpec& camera,
                      const RenderImageOptions& options) {
  const int s = options.supersample;
  OsmesaContext context(1, 1);
  validate(camera, options, context.max_size_px());
  context.make_current(camera.width_px * s, camera.height_px * s);

  const ColouredTriangles ground = ground_triangles(field, camera.target_m, options);
  const ColouredTriangles bodies = object_triangles(objects, camera.target_m, camera.position_m, options);
  return draw_parts({&ground, &bodies}, camera, options, context);
}

RgbImage render_coloured_meshes(const std::vector<ColouredMesh>& meshes, const CameraSpec& camera,
                                const RenderImageOptions& options) {
  const int s = options.supersample;
  OsmesaContext context(1, 1);
  validate(camera, options, context.max_size_px());
  for (const ColouredMesh& m : meshes) {
    if (m.vertex_rgb.size() != static_cast<std::size_t>(m.mesh.V.rows())) {
      throw InputError("render: a coloured mesh needs one colour per vertex (" + std::to_string(m.mesh.V.rows()) +
                       " vertices, " + std::to_string(m.vertex_rgb.size()) + " colours)");
    }
  }
  context.make_current(camera.width_px * s, camera.height_px * s);
  std::vector<ColouredTriangles> parts;
  parts.reserve(meshes.size());
  for (const ColouredMesh& m : meshes) parts.push_back(coloured_mesh_triangles(m, camera.target_m, camera.position_m, options));
  std::vector<const ColouredTriangles*> pointers;
  for (const ColouredTriangles& t : parts) pointers.push_back(&t);
  return draw_parts(pointers, camera, options, context);
}

std::optional<Eigen::Vector2d> project_to_image(const CameraSpec& camera, const Eigen::Vector3d& point_m) {
  const Eigen::Vector4d eye = view_matrix(camera) * (point_m - camera.target_m).homogeneous();
  if (eye.z() >= 0.0) return std::nullopt;  // behind the camera
  const Eigen::Vector4d clip = projection_matrix(camera, 1.0, 2.0) * eye;  // x, y do not depend on near/far
  const double x_ndc = clip.x() / clip.w(), y_ndc = clip.y() / clip.w();
  return Eigen::Vector2d((x_ndc + 1) / 2 * camera.width_px, (1 - y_ndc) / 2 * camera.height_px);
}

}  // namespace repose
