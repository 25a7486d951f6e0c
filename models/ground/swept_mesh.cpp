#include "models/ground/swept_mesh.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <unordered_map>
#include <vector>

#include "models/core/base/error.h"
#include "models/core/geometry/faces_turned.h"

namespace repose {

namespace {

std::uint64_t edge_key(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) | static_cast<std::uint32_t>(b);
}

}  // namespace

SweptBody make_swept_body(const TriangleMesh& body) {
  const int nf = static_cast<int>(body.F.rows());
  SweptBody swept;
  std::unordered_map<std::uint64_t, int> face_of_edge;
  face_of_edge.reserve(3 * static_cast<std::size_t>(nf));
  swept.face_normal.reserve(static_cast<std::size_t>(nf));
  for (int f = 0; f < nf; ++f) {
    const Eigen::Vector3d a = body.V.row(body.F(f, 0)), b = body.V.row(body.F(f, 1)), c = body.V.row(body.F(f, 2));
    swept.face_normal.push_back((b - a).cross(c - a));
    for (int k = 0; k < 3; ++k) face_of_edge[edge_key(body.F(f, k), body.F(f, (k + 1) % 3))] = f;
  }
  swept.twin_face.assign(3 * static_cast<std::size_t>(nf), -1);
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const auto twin = face_of_edge.find(edge_key(body.F(f, (k + 1) % 3), body.F(f, k)));
      if (twin != face_of_edge.end()) swept.twin_face[3 * static_cast<std::size_t>(f) + k] = twin->second;
    }
  }
  return swept;
}

namespace {

// A front face (normal . d > 0) goes to the later pose; the test is made in
// body coordinates, where the normals are fixed.
bool is_front(const SweptBody& swept, std::size_t face, const Eigen::Vector3d& d_body) {
  return swept.face_normal[face].dot(d_body) > 0.0;
}

std::vector<char> front_faces(const SweptBody& swept, const Pose& to, const Eigen::Vector3d& d) {
  const Eigen::Vector3d d_body = to.orientation.conjugate() * d;
  std::vector<char> front(swept.face_normal.size());
  for (std::size_t f = 0; f < front.size(); ++f) front[f] = is_front(swept, f, d_body);
  return front;
}

// The body at both poses: rows [0, nv) at the earlier, [nv, 2 nv) at the later.
MatrixX3dR vertices_at_both_poses(const TriangleMesh& body, const Pose& to, const Eigen::Vector3d& d) {
  const Eigen::Index nv = body.V.rows();
  MatrixX3dR V(2 * nv, 3);
  V.bottomRows(nv) = transformed_vertices(body.V, to);
  V.topRows(nv) = V.bottomRows(nv).rowwise() - d.transpose();
  return V;
}

}  // namespace

TriangleMesh swept_mesh(const TriangleMesh& body, const SweptBody& swept, const Pose& from, const Pose& to) {
  const int nv = static_cast<int>(body.V.rows());
  const int nf = static_cast<int>(body.F.rows());
  REPOSE_DEMAND(swept.face_normal.size() == static_cast<std::size_t>(nf));
  const Eigen::Vector3d d = to.position_m - from.position_m;
  if (d.squaredNorm() == 0.0) return transformed(body, to);
  const std::vector<char> front = front_faces(swept, to, d);

  // faces, then per silhouette or open edge a quad: at most 2 * 3 per face,
  // counted first so the face array is filled once
  int quads = 0;
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int twin = swept.twin_face[3 * static_cast<std::size_t>(f) + k];
      quads += twin < 0 || (front[f] && !front[twin]);
    }
  }
  TriangleMesh out;
  out.V = vertices_at_both_poses(body, to, d);
  out.F.resize(nf + 2 * quads, 3);
  Eigen::Index row = 0;
  auto add = [&](int a, int b, int c) { out.F.row(row++) << a, b, c; };
  for (int f = 0; f < nf; ++f) {
    const int offset = front[f] ? nv : 0;
    add(body.F(f, 0) + offset, body.F(f, 1) + offset, body.F(f, 2) + offset);
  }
  // silhouette and open edges: a quad joining the edge at both poses, wound
  // so that it uses each of its edges opposite to its neighbours
  for (int f = 0; f < nf; ++f) {
    for (int k = 0; k < 3; ++k) {
      const int twin = swept.twin_face[3 * static_cast<std::size_t>(f) + k];
      const bool open = twin < 0;
      if (!open && !(front[f] && !front[twin])) continue;  // each silhouette edge once, from its front face
      const int a = body.F(f, k), b = body.F(f, (k + 1) % 3);
      if (open && !front[f]) {
        // open edge of a back face, which uses a0 -> b0: the quad uses b0 -> a0
        add(b, a, a + nv);
        add(b, a + nv, b + nv);
        continue;
      }
      // front face uses a1 -> b1, so the quad uses b1 -> a1 and a0 -> b0
      add(b + nv, a + nv, a);
      add(b + nv, a, b);
    }
  }
  REPOSE_DEMAND(row == out.F.rows());
  return out;
}

bool is_vertical(const Eigen::Vector3d& d) { return d.x() == 0.0 && d.y() == 0.0; }

namespace {

// The box of the body at both poses from its box at the later one: d has
// no x or y, and rounding keeps the order of z - dz, so the lowest and
// highest vertex at the earlier pose are those at the later one, shifted.
Aabb box_at_both_poses(const Aabb& later, const Eigen::Vector3d& d) {
  Aabb box = later;
  box.min.z() = std::min(later.min.z(), later.min.z() - d.z());
  box.max.z() = std::max(later.max.z(), later.max.z() - d.z());
  return box;
}

bool same_bits(const void* a, const void* b, std::size_t n) { return std::memcmp(a, b, n) == 0; }

// The body placed at `to`'s orientation and x, y at height 0, its box and
// its faces turned down, kept while these stay the same bit for bit.
void update_level(const TriangleMesh& body, const Pose& to, VerticalSweepCache* cache) {
  const Eigen::Quaterniond& q = to.orientation;
  if (cache->valid && same_bits(q.coeffs().data(), cache->orientation.coeffs().data(), 4 * sizeof(double)) &&
      same_bits(&to.position_m.x(), &cache->x_m, sizeof(double)) &&
      same_bits(&to.position_m.y(), &cache->y_m, sizeof(double))) {
    return;
  }
  cache->valid = true;
  cache->orientation = q;
  cache->x_m = to.position_m.x();
  cache->y_m = to.position_m.y();
  Pose level = to;
  level.position_m.z() = 0.0;
  cache->level = transformed_vertices(body.V, level);
  cache->level_box = bounding_box(cache->level);
  cache->turned.clear();
  cache->front.clear();
  const MatrixX3dR& V = cache->level;
  for (Eigen::Index f = 0; f < body.F.rows(); ++f) {
    const int a = body.F(f, 0), b = body.F(f, 1), c = body.F(f, 2);
    // turned as at any height: the test reads x and y alone
    if (is_turned(V.row(a), V.row(b), V.row(c), true)) cache->turned.push_back(static_cast<int>(f));
  }
}

// The faces on the vertices they use, numbered as first used, for these front faces.
void update_faces(const TriangleMesh& body, const std::vector<char>& front, VerticalSweepCache* cache) {
  if (front == cache->front && cache->faces.rows() == static_cast<Eigen::Index>(cache->turned.size())) return;
  cache->front = front;
  const Eigen::Index nv = body.V.rows();
  std::vector<int> slot(2 * static_cast<std::size_t>(nv), -1);  // its row in the output, -1 until used
  cache->used.clear();
  cache->faces.resize(static_cast<Eigen::Index>(cache->turned.size()), 3);
  for (std::size_t t = 0; t < cache->turned.size(); ++t) {
    const int offset = front[t] ? static_cast<int>(nv) : 0;
    for (int k = 0; k < 3; ++k) {
      const int v = body.F(cache->turned[t], k) + offset;
      int& s = slot[static_cast<std::size_t>(v)];
      if (s < 0) {
        s = static_cast<int>(cache->used.size());
        cache->used.push_back(v);
      }
      cache->faces(static_cast<Eigen::Index>(t), k) = s;
    }
  }
}

}  // namespace

FacesDown vertical_sweep_faces_down(const TriangleMesh& body, const SweptBody& swept, const Pose& from,
                                    const Pose& to, VerticalSweepCache* cache) {
  const Eigen::Index nv = body.V.rows(), nf = body.F.rows();
  REPOSE_DEMAND(swept.face_normal.size() == static_cast<std::size_t>(nf));
  const Eigen::Vector3d d = to.position_m - from.position_m;
  REPOSE_DEMAND(is_vertical(d));
  if (d.squaredNorm() == 0.0) return faces_down_of(transformed(body, to));
  update_level(body, to, cache);
  // the body at `to`: lifted from height 0, bit for bit as placed
  // (VerticalSweepCache) unless it lies at height 0, where it is placed afresh
  const double lift = to.position_m.z();
  const MatrixX3dR placed = lift == 0.0 ? transformed_vertices(body.V, to) : MatrixX3dR();
  auto later = [&](int v) -> Eigen::RowVector3d {
    if (lift == 0.0) return placed.row(v);
    return Eigen::RowVector3d(cache->level(v, 0), cache->level(v, 1), cache->level(v, 2) + lift);
  };
  Aabb later_box = cache->level_box;
  if (lift == 0.0) {
    later_box = bounding_box(placed);
  } else {
    later_box.min.z() += lift;
    later_box.max.z() += lift;
  }
  FacesDown out;
  out.box = box_at_both_poses(later_box, d);
  // as swept_mesh: a face is at the later pose when it faces the motion
  const Eigen::Vector3d d_body = to.orientation.conjugate() * d;
  std::vector<char> front(cache->turned.size());
  for (std::size_t t = 0; t < front.size(); ++t) {
    front[t] = is_front(swept, static_cast<std::size_t>(cache->turned[t]), d_body);
  }
  update_faces(body, front, cache);
  out.mesh.F = cache->faces;
  out.mesh.V.resize(static_cast<Eigen::Index>(cache->used.size()), 3);
  for (std::size_t r = 0; r < cache->used.size(); ++r) {
    const Eigen::Index row = static_cast<Eigen::Index>(r);
    const int v = cache->used[r];
    if (v >= nv) {
      out.mesh.V.row(row) = later(v - static_cast<int>(nv));
    } else {
      out.mesh.V.row(row) = later(v) - d.transpose();  // as vertices_at_both_poses
    }
  }
  return out;
}

FacesDown vertical_sweep_faces_down(const TriangleMesh& body, const SweptBody& swept, const Pose& from,
                                    const Pose& to) {
  VerticalSweepCache cache;
  return vertical_sweep_faces_down(body, swept, from, to, &cache);
}

TriangleMesh swept_mesh(const TriangleMesh& body, const Pose& from, const Pose& to) {
  return swept_mesh(body, make_swept_body(body), from, to);
}

}  // namespace repose
