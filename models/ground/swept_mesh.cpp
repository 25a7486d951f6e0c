#include "models/ground/swept_mesh.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace repose {

namespace {

std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

TriangleMesh swept_mesh(const TriangleMesh& body, const Pose& from, const Pose& to) {
  const Eigen::Vector3d d = to.position_m - from.position_m;
  Pose at_to = to;
  if (d.squaredNorm() == 0.0) return transformed(body, at_to);
  Pose at_from = to;
  at_from.position_m = from.position_m;
  const TriangleMesh m0 = transformed(body, at_from);
  const TriangleMesh m1 = transformed(body, at_to);
  const int nv = static_cast<int>(body.V.rows());
  const int nf = static_cast<int>(body.F.rows());

  // front faces (normal . d > 0) go to the later pose
  std::vector<char> front(nf);
  std::unordered_map<std::uint64_t, int> face_of_edge;
  face_of_edge.reserve(3 * nf);
  for (int f = 0; f < nf; ++f) {
    const Eigen::Vector3d a = m1.V.row(body.F(f, 0)), b = m1.V.row(body.F(f, 1)), c = m1.V.row(body.F(f, 2));
    front[f] = (b - a).cross(c - a).dot(d) > 0.0;
    for (int k = 0; k < 3; ++k) face_of_edge[edge_key(body.F(f, k), body.F(f, (k + 1) % 3))] = f;
  }

  std::vector<Eigen::Vector3i> faces;
  faces.reserve(2 * nf);
  for (int f = 0; f < nf; ++f) {
    const int offset = front[f] ? nv : 0;
    faces.emplace_back(body.F(f, 0) + offset, body.F(f, 1) + offset, body.F(f, 2) + offset);
  }
  // silhouette and open edges: a quad joining the edge at both poses, wound
  // so that it uses each of its edges opposite to its neighbours
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int a = body.F(f, k), b = body.F(f, (k + 1) % 3);
      const auto twin = face_of_edge.find(edge_key(b, a));
      const bool open = twin == face_of_edge.end();
      if (!open && !(front[f] && !front[twin->second])) continue;  // each silhouette edge once, from its front face
      if (open && !front[f]) {
        // open edge of a back face, which uses a0 -> b0: the quad uses b0 -> a0
        faces.emplace_back(b, a, a + nv);
        faces.emplace_back(b, a + nv, b + nv);
        continue;
      }
      // front face uses a1 -> b1, so the quad uses b1 -> a1 and a0 -> b0
      faces.emplace_back(b + nv, a + nv, a);
      faces.emplace_back(b + nv, a, b);
    }
  }

  TriangleMesh out;
  out.V.resize(2 * nv, 3);
  out.V.topRows(nv) = m0.V;
  out.V.bottomRows(nv) = m1.V;
  out.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t k = 0; k < faces.size(); ++k) out.F.row(static_cast<Eigen::Index>(k)) = faces[k].transpose();
  return out;
}

}  // namespace repose
