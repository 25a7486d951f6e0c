#pragma once
// Invariant checks on a built terrain, shared by the terrain tests.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>
#include <string>

#include "models/terrain/terrain.h"

namespace repose::test {

// Names the first pair of contours whose boundaries meet (or a contour that
// is not simple); "" when none.
inline std::string first_contour_crossing(const ContourSet& set) {
  const auto& cs = set.contours;
  std::vector<Eigen::AlignedBox2d> boxes;
  for (const TerrainContour& c : cs) {
    Eigen::AlignedBox2d box;
    for (const Point2& p : c.polygon_m) box.extend(p);
    boxes.push_back(box);
  }
  for (std::size_t i = 0; i < cs.size(); ++i) {
    if (!is_simple(cs[i].polygon_m)) return "contour " + std::to_string(i) + " is not simple";
    for (std::size_t j = i + 1; j < cs.size(); ++j) {
      if (!boxes[i].intersects(boxes[j])) continue;
      if (boundaries_cross(cs[i].polygon_m, cs[j].polygon_m)) {
        return "contours " + std::to_string(i) + " and " + std::to_string(j) + " cross";
      }
    }
  }
  return "";
}

inline double xy_area_m2(const TriangleMesh& mesh, int f) {
  const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
  return 0.5 * ((b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y()));
}

// How many faces' xy projections hold p strictly inside.
inline int faces_over(const TriangleMesh& mesh, const Point2& p) {
  int count = 0;
  for (int f = 0; f < mesh.F.rows(); ++f) {
    bool left_of_all = true, right_of_all = true;
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d a = mesh.V.row(mesh.F(f, k)), b = mesh.V.row(mesh.F(f, (k + 1) % 3));
      const double side = (b.x() - a.x()) * (p.y() - a.y()) - (b.y() - a.y()) * (p.x() - a.x());
      left_of_all = left_of_all && side > 0.0;
      right_of_all = right_of_all && side < 0.0;
    }
    // either orientation counts: a folded face would be seen too
    if (left_of_all || right_of_all) ++count;
  }
  return count;
}

}  // namespace repose::test
