#include "models/core/geometry/triangle_mesh.h"

#include <cmath>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

#include "models/core/base/error.h"

namespace repose {

Aabb bounding_box(const TriangleMesh& mesh) { return bounding_box(mesh.V); }

Aabb bounding_box(const MatrixX3dR& V) {
  Aabb box;
  if (V.rows() == 0) return box;
  // one pass over the rows: Eigen's column reductions stride through the
  // row-major matrix once per column, and this runs on every placed body
  double lo[3], hi[3];
  for (int k = 0; k < 3; ++k) lo[k] = hi[k] = V(0, k);
  const double* v = V.data();
  for (Eigen::Index r = 1; r < V.rows(); ++r) {
    for (int k = 0; k < 3; ++k) {
      const double x = v[3 * r + k];
      lo[k] = x < lo[k] ? x : lo[k];
      hi[k] = x > hi[k] ? x : hi[k];
    }
  }
  box.min = Eigen::Vector3d(lo[0], lo[1], lo[2]);
  box.max = Eigen::Vector3d(hi[0], hi[1], hi[2]);
  return box;
}

MatrixX3dR transformed_vertices(const MatrixX3dR& V, const Pose& pose) {
  MatrixX3dR out(V.rows(), 3);
  const Eigen::Matrix3d R = pose.orientation.normalized().toRotationMatrix();
  for (Eigen::Index r = 0; r < V.rows(); ++r) out.row(r) = (R * V.row(r).transpose() + pose.position_m).transpose();
  return out;
}

TriangleMesh transformed(const TriangleMesh& mesh, const Pose& pose) {
  TriangleMesh out;
  out.F = mesh.F;
  out.V = transformed_vertices(mesh.V, pose);
  return out;
}

TriangleMesh scaled(const TriangleMesh& mesh, const Eigen::Vector3d& scale) {
  TriangleMesh out = mesh;
  for (Eigen::Index r = 0; r < out.V.rows(); ++r) out.V.row(r) = out.V.row(r).cwiseProduct(scale.transpose());
  // a mirror (odd number of negative scales) flips the orientation
  if (scale.x() * scale.y() * scale.z() < 0) out.F.col(1).swap(out.F.col(2));
  return out;
}

TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b) {
  TriangleMesh out;
  out.V.resize(a.V.rows() + b.V.rows(), 3);
  out.V << a.V, b.V;
  out.F.resize(a.F.rows() + b.F.rows(), 3);
  out.F << a.F, (b.F.array() + static_cast<int>(a.V.rows())).matrix();
  return out;
}

double signed_volume_m3(const TriangleMesh& mesh) {
  double six_v = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0));
    const Eigen::Vector3d b = mesh.V.row(mesh.F(f, 1));
    const Eigen::Vector3d c = mesh.V.row(mesh.F(f, 2));
    six_v += a.dot(b.cross(c));
  }
  return six_v / 6.0;
}

bool is_closed_manifold(const TriangleMesh& mesh) {
  if (mesh.empty()) return false;
  // each directed edge must appear once, and its reverse once
  std::map<std::pair<int, int>, int> directed;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.F(f, k);
      const int b = mesh.F(f, (k + 1) % 3);
      if (a == b || a < 0 || b < 0 || a >= mesh.V.rows() || b >= mesh.V.rows()) return false;
      if (++directed[{a, b}] > 1) return false;
    }
  }
  for (const auto& [edge, count] : directed) {
    if (!directed.contains({edge.second, edge.first})) return false;
  }
  return true;
}

namespace {

// A surface of revolution around z from a profile of (radius, z) points
// running from the bottom pole (radius 0) to the top pole (radius 0).
TriangleMesh revolve(const std::vector<std::pair<double, double>>& profile, int segments) {
  REPOSE_DEMAND(segments >= 3 && profile.size() >= 3);
  const int rings = static_cast<int>(profile.size()) - 2;  // interior profile points
  TriangleMesh m;
  m.V.resize(2 + rings * segments, 3);
  m.V.row(0) << 0, 0, profile.front().second;
  m.V.row(1) << 0, 0, profile.back().second;
  for (int r = 0; r < rings; ++r) {
    const auto [rad, z] = profile[r + 1];
    for (int s = 0; s < segments; ++s) {
      const double phi = 2.0 * std::numbers::pi * s / segments;
      m.V.row(2 + r * segments + s) << rad * std::cos(phi), rad * std::sin(phi), z;
    }
  }
  auto idx = [&](int r, int s) { return 2 + r * segments + (s % segments); };
  std::vector<Eigen::Vector3i> faces;
  for (int s = 0; s < segments; ++s) faces.emplace_back(0, idx(0, s + 1), idx(0, s));
  for (int r = 0; r + 1 < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      faces.emplace_back(idx(r, s), idx(r, s + 1), idx(r + 1, s + 1));
      faces.emplace_back(idx(r, s), idx(r + 1, s + 1), idx(r + 1, s));
    }
  }
  for (int s = 0; s < segments; ++s) faces.emplace_back(1, idx(rings - 1, s), idx(rings - 1, s + 1));
  m.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) m.F.row(static_cast<Eigen::Index>(f)) = faces[f].transpose();
  return m;
}

// Hemispherical caps of radius r around z = +-half_height joined by a side.
std::vector<std::pair<double, double>> capsule_profile(double r, double half_height, int segments) {
  const int cap_steps = std::max(2, segments / 4);
  std::vector<std::pair<double, double>> p;
  for (int k = 0; k <= cap_steps; ++k) {  // bottom cap, pole to equator
    const double a = -std::numbers::pi / 2 + (std::numbers::pi / 2) * k / cap_steps;
    p.emplace_back(r * std::cos(a), -half_height + r * std::sin(a));
  }
  for (int k = 0; k <= cap_steps; ++k) {  // top cap, equator to pole
    const double a = (std::numbers::pi / 2) * k / cap_steps;
    p.emplace_back(r * std::cos(a), half_height + r * std::sin(a));
  }
  if (half_height == 0.0) p.erase(p.begin() + cap_steps + 1);  // sphere: one equator
  p.front().first = 0.0;
  p.back().first = 0.0;
  return p;
}

}  // namespace

TriangleMesh make_sphere(double radius_m, int segments) {
  return revolve(capsule_profile(radius_m, 0.0, 2 * segments), segments);
}

TriangleMesh make_capsule(double radius_m, double half_height_m, int segments) {
  return revolve(capsule_profile(radius_m, half_height_m, 2 * segments), segments);
}

TriangleMesh make_cylinder(double radius_m, double half_height_m, int segments) {
  return revolve({{0.0, -half_height_m}, {radius_m, -half_height_m}, {radius_m, half_height_m}, {0.0, half_height_m}},
                 segments);
}

TriangleMesh make_box(const Eigen::Vector3d& e) {
  TriangleMesh m;
  m.V.resize(8, 3);
  for (int k = 0; k < 8; ++k) {
    m.V.row(k) << ((k & 1) ? e.x() : -e.x()), ((k & 2) ? e.y() : -e.y()), ((k & 4) ? e.z() : -e.z());
  }
  m.F.resize(12, 3);
  m.F << 0, 2, 3, 0, 3, 1,  // z-
      4, 5, 7, 4, 7, 6,     // z+
      0, 1, 5, 0, 5, 4,     // y-
      2, 6, 7, 2, 7, 3,     // y+
      0, 4, 6, 0, 6, 2,     // x-
      1, 3, 7, 1, 7, 5;     // x+
  return m;
}

}  // namespace repose
