#pragma once
// A triangle mesh as two arrays, libigl style:
//   V: #V by 3 vertex positions (m)
//   F: #F by 3 vertex indices, counter-clockwise seen from outside
// plus the primitive shapes objects are made of, tessellated.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>

namespace repose {

using MatrixX3dR = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
using MatrixX3iR = Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>;

struct TriangleMesh {
  MatrixX3dR V;
  MatrixX3iR F;

  bool empty() const { return F.rows() == 0; }
};

// A rigid placement: x_world = orientation * x_body + position.
struct Pose {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();
};

struct Aabb {
  Eigen::Vector3d min = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector3d max = Eigen::Vector3d::Constant(-std::numeric_limits<double>::infinity());
  bool empty() const { return (min.array() > max.array()).any(); }
  void extend(const Eigen::Vector3d& p) {
    min = min.cwiseMin(p);
    max = max.cwiseMax(p);
  }
};

Aabb bounding_box(const TriangleMesh& mesh);
// The same over vertices alone (#V by 3).
Aabb bounding_box(const MatrixX3dR& V);
TriangleMesh transformed(const TriangleMesh& mesh, const Pose& pose);
// The vertices alone (#V by 3), as transformed() places them.
MatrixX3dR transformed_vertices(const MatrixX3dR& V, const Pose& pose);
TriangleMesh scaled(const TriangleMesh& mesh, const Eigen::Vector3d& scale);
// Concatenate meshes (indices of b offset by a's vertex count).
TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b);

// Signed volume (m^3), positive for an outward-oriented closed mesh.
double signed_volume_m3(const TriangleMesh& mesh);
// True when every edge is shared by exactly two faces with opposite
// directions (closed, oriented 2-manifold) and no face is degenerate.
bool is_closed_manifold(const TriangleMesh& mesh);

// Primitives centred on the body origin, axis along body z where there is one.
// `segments` is the number of divisions around the axis (>= 3).
TriangleMesh make_sphere(double radius_m, int segments = 32);
TriangleMesh make_box(const Eigen::Vector3d& half_extents_m);
TriangleMesh make_cylinder(double radius_m, double half_height_m, int segments = 32);
TriangleMesh make_capsule(double radius_m, double half_height_m, int segments = 32);

}  // namespace repose
