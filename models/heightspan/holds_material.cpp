#include "models/heightspan/holds_material.h"

#include "models/heightspan/heightspan_section.h"

namespace repose {

bool is_convex(const TriangleMesh& mesh) {
  if (mesh.empty()) return true;
  const Aabb box = bounding_box(mesh);
  const double tolerance_m = 1e-9 * (box.max - box.min).norm();
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    const Eigen::Vector3d n = (b - a).cross(c - a);
    const double norm = n.norm();
    if (norm == 0.0) continue;
    const Eigen::VectorXd side = (mesh.V.rowwise() - a.transpose()) * (n / norm);
    if (side.maxCoeff() > tolerance_m) return false;
  }
  return true;
}

bool holds_material(const Scene& scene, const ObjectSpec& object) {
  const HeightSpanSection& section = heightspan_section(scene);
  const auto it = section.holds_material.find(object.name);
  if (it != section.holds_material.end()) return it->second;
  return !is_convex(object.body);
}

}  // namespace repose
