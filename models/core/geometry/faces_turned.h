#pragma once
// The faces of a mesh that a view straight down or straight up sees from
// behind: the ground's underside renderer needs only the faces turned down,
// the height-span peeling the two halves separately.

#include <Eigen/Geometry>

#include "models/core/geometry/triangle_mesh.h"

namespace repose {

// The faces whose normal points down (turned_down) or up, on the same
// vertices; vertical faces are in neither (seen edge-on from above or below).
TriangleMesh faces_turned(const TriangleMesh& mesh, bool turned_down);

// The test faces_turned makes of triangle (a, b, c): the z of its normal
// (b - a) x (c - a) is negative (turned_down) or positive. It reads x and
// y alone, so a face shifted along z is turned as it was.
inline bool is_turned(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, bool turned_down) {
  const double nz = (b - a).cross(c - a).z();
  return turned_down ? nz < 0.0 : nz > 0.0;
}

}  // namespace repose
