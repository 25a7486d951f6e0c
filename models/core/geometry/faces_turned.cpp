#include "models/core/geometry/faces_turned.h"

namespace repose {

TriangleMesh faces_turned(const TriangleMesh& mesh, bool turned_down) {
  TriangleMesh out;
  out.V = mesh.V;
  out.F.resize(mesh.F.rows(), 3);
  Eigen::Index n = 0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    if (is_turned(a, b, c, turned_down)) out.F.row(n++) = mesh.F.row(f);
  }
  out.F.conservativeResize(n, 3);
  return out;
}

}  // namespace repose
