#pragma once
// The mirror image of a ground scene, for symmetry tests: the ground model
// has no preferred side, so the mirror image of a scene must give the mirror
// image of its heights (to round-off). Mirrors: x -> -x and y -> -y about the
// grid's centre lines, and the swap of x and y (the diagonal).

#include <algorithm>
#include <utility>

#include "models/core/config/scene.h"
#include "models/core/geometry/height_field.h"

namespace repose::testing {

enum class Mirror { kX, kY, kDiagonal };

inline Eigen::Matrix3d mirror_matrix(Mirror m) {
  Eigen::Matrix3d p = Eigen::Matrix3d::Identity();
  if (m == Mirror::kX) p(0, 0) = -1;
  if (m == Mirror::kY) p(1, 1) = -1;
  if (m == Mirror::kDiagonal) p << 0, 1, 0, 1, 0, 0, 0, 0, 1;
  return p;
}

// A body mirrored in its own frame: vertices reflected, faces turned so
// that they still face outwards.
inline TriangleMesh mirrored(const TriangleMesh& body, Mirror m) {
  TriangleMesh out = body;
  out.V = body.V * mirror_matrix(m).transpose();
  out.F.col(1).swap(out.F.col(2));
  return out;
}

// The reflection of a rotation, p R p, as a quaternion: (w, -p v), exact.
inline Eigen::Quaterniond mirrored(const Eigen::Quaterniond& q, Mirror m) {
  const Eigen::Vector3d v = -(mirror_matrix(m) * q.vec());
  return Eigen::Quaterniond(q.w(), v.x(), v.y(), v.z());
}

// The scene reflected by x -> -x, y -> -y or the swap of x and y, with the
// grid reflected too (its origin moves; for the swap nx and ny swap): cell
// (i, j) of the scene corresponds to (nx - 1 - i, j), (i, ny - 1 - j) or (j, i).
inline Scene mirrored(const Scene& scene, Mirror m) {
  Scene s = scene;
  Grid& g = s.ground.grid;
  const Eigen::Matrix3d p = mirror_matrix(m);
  if (m == Mirror::kX) g.origin_x_m = -(g.origin_x_m + g.extent_x_m());
  if (m == Mirror::kY) g.origin_y_m = -(g.origin_y_m + g.extent_y_m());
  if (m == Mirror::kDiagonal) {
    std::swap(g.nx, g.ny);
    std::swap(g.origin_x_m, g.origin_y_m);
  }
  for (MaterialRegion& r : s.ground.regions) {
    const Eigen::Vector3d a = p * Eigen::Vector3d(r.x_min_m, r.y_min_m, 0);
    const Eigen::Vector3d b = p * Eigen::Vector3d(r.x_max_m, r.y_max_m, 0);
    r.x_min_m = std::min(a.x(), b.x()), r.x_max_m = std::max(a.x(), b.x());
    r.y_min_m = std::min(a.y(), b.y()), r.y_max_m = std::max(a.y(), b.y());
  }
  for (ObjectSpec& o : s.objects) {
    o.body = mirrored(o.body, m);
    for (Keyframe& k : o.keyframes) {
      k.pose.position_m = p * k.pose.position_m;
      k.pose.orientation = mirrored(k.pose.orientation, m);
    }
  }
  return s;
}

// The heights of the mirrored scene mapped back onto the original's cells.
inline double largest_mirror_difference(const HeightField& original, const HeightField& twin, Mirror m) {
  double worst = 0.0;
  const int nx = original.nx(), ny = original.ny();
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const double t = m == Mirror::kX   ? twin.at(nx - 1 - i, j)
                       : m == Mirror::kY ? twin.at(i, ny - 1 - j)
                                         : twin.at(j, i);
      worst = std::max(worst, std::abs(original.at(i, j) - t));
    }
  }
  return worst;
}

}  // namespace repose::testing
