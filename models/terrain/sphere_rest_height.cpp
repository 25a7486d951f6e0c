#include "models/terrain/sphere_rest_height.h"

#include <algorithm>
#include <cmath>

#include "models/core/base/error.h"

namespace repose {

namespace {

using Vec3 = Eigen::Vector3d;

// Highest centre over the points of one feature: q_z + sqrt(r^2 - |q_xy - c|^2).
std::optional<double> over_point(const Vec3& q, const Point2& c, double r) {
  const double d2 = (q.head<2>() - c).squaredNorm();
  if (d2 > r * r) return std::nullopt;
  return q.z() + std::sqrt(r * r - d2);
}

// Over a segment: g(t) = z(t) + sqrt(r^2 - d(t)^2) is concave where defined,
// so a golden-section search over the part within reach finds its maximum.
std::optional<double> over_segment(const Vec3& a, const Vec3& b, const Point2& c, double r) {
  const Point2 ab = b.head<2>() - a.head<2>();
  const double len2 = ab.squaredNorm();
  if (len2 == 0.0) return over_point(a, c, r);
  // the t range whose horizontal distance to c is below r
  const double t0 = (c - a.head<2>()).dot(ab) / len2;
  const double perp2 = (a.head<2>() + t0 * ab - c).squaredNorm();
  if (perp2 >= r * r) return std::nullopt;
  const double half = std::sqrt((r * r - perp2) / len2);
  double lo = std::max(0.0, t0 - half), hi = std::min(1.0, t0 + half);
  if (lo > hi) return std::nullopt;
  auto g = [&](double t) {
    const Vec3 q = a + t * (b - a);
    return q.z() + std::sqrt(std::max(0.0, r * r - (q.head<2>() - c).squaredNorm()));
  };
  constexpr double kInvPhi = 0.6180339887498949;
  for (int it = 0; it < 100 && hi - lo > 1e-15; ++it) {
    const double m1 = hi - kInvPhi * (hi - lo), m2 = lo + kInvPhi * (hi - lo);
    if (g(m1) < g(m2)) lo = m1; else hi = m2;
  }
  return g(0.5 * (lo + hi));
}

// Touching the face's plane inside the triangle: centre = contact + r n.
std::optional<double> over_face_interior(const Vec3& a, const Vec3& b, const Vec3& c3, const Point2& c, double r) {
  Vec3 n = (b - a).cross(c3 - a);
  if (n.z() <= 0.0) return std::nullopt;  // vertical or folded: edges decide
  n.normalize();
  const Point2 contact_xy = c - r * n.head<2>();
  const double det = (b.x() - a.x()) * (c3.y() - a.y()) - (c3.x() - a.x()) * (b.y() - a.y());
  const double u = ((contact_xy.x() - a.x()) * (c3.y() - a.y()) - (c3.x() - a.x()) * (contact_xy.y() - a.y())) / det;
  const double v = ((b.x() - a.x()) * (contact_xy.y() - a.y()) - (contact_xy.x() - a.x()) * (b.y() - a.y())) / det;
  if (u < 0.0 || v < 0.0 || u + v > 1.0) return std::nullopt;
  const double contact_z = a.z() + u * (b.z() - a.z()) + v * (c3.z() - a.z());
  return contact_z + r * n.z();
}

}  // namespace

std::optional<double> sphere_rest_height_m(const TerrainSurface& surface, const Point2& xy, double radius_m) {
  REPOSE_DEMAND(radius_m > 0.0);
  const TriangleMesh& mesh = surface.mesh();
  std::optional<double> best;
  auto take = [&](std::optional<double> z) {
    if (z && (!best || *z > *best)) best = z;
  };
  const Point2 reach = Point2::Constant(radius_m);
  for (int f : surface.faces_near(xy - reach, xy + reach)) {
    const Vec3 a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    take(over_face_interior(a, b, c, xy, radius_m));
    take(over_segment(a, b, xy, radius_m));
    take(over_segment(b, c, xy, radius_m));
    take(over_segment(c, a, xy, radius_m));
  }
  return best;
}

std::optional<double> sphere_on_sphere_height_m(const Point2& xy, double radius_m, const Eigen::Vector3d& below_m,
                                                double below_radius_m, double gap_m) {
  const double reach = radius_m + below_radius_m + gap_m;
  const double d2 = (xy - below_m.head<2>()).squaredNorm();
  if (d2 >= reach * reach) return std::nullopt;
  return below_m.z() + std::sqrt(reach * reach - d2);
}

}  // namespace repose
