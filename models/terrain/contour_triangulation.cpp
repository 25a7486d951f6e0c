// CGAL's constrained Delaunay triangulation, kept out of the other files.
#include "models/terrain/contour_triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <cmath>
#include <deque>
#include <unordered_map>
#include <vector>

#include "models/core/base/error.h"

namespace repose {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
// contours never cross, so a crossing that needs a new point is a bug
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds,
                                                        CGAL::No_constraint_intersection_requiring_constructions_tag>;

struct LiftedPoints {
  std::vector<Point2> xy;
  std::vector<double> z;
};

Cdt::Vertex_handle insert_point(Cdt* cdt, const Point2& p, double z, LiftedPoints* points) {
  const std::size_t before = cdt->number_of_vertices();
  Cdt::Vertex_handle v = cdt->insert(Kernel::Point_2(p.x(), p.y()));
  if (cdt->number_of_vertices() > before) {  // a new vertex (info is not initialised)
    v->info() = static_cast<int>(points->xy.size());
    points->xy.push_back(p);
    points->z.push_back(z);
  } else {
    // the same point twice must carry the same height (key contours apart)
    REPOSE_DEMAND(std::abs(points->z[v->info()] - z) <= 1e-9 * (1.0 + std::abs(z)));
  }
  return v;
}

void insert_contours(const ContourSet& contours, Cdt* cdt, LiftedPoints* points) {
  for (const TerrainContour& c : contours.contours) {
    std::vector<Cdt::Vertex_handle> handles;
    for (const Point2& p : c.polygon_m) handles.push_back(insert_point(cdt, p, c.height_m, points));
    for (std::size_t i = 0; i < handles.size(); ++i) {
      const auto& a = handles[i];
      const auto& b = handles[(i + 1) % handles.size()];
      if (a != b) cdt->insert_constraint(a, b);
    }
  }
  for (const SummitPoint& s : contours.summits) insert_point(cdt, s.point_m, s.height_m, points);
}

// How many contours enclose each face: a flood from the infinite face that
// counts the constrained edges it crosses (CGAL's polygon-triangulation
// example). Exact, unlike a point-in-polygon test on a sliver's centroid.
std::unordered_map<Cdt::Face_handle, int> enclosing_contours(const Cdt& cdt) {
  std::unordered_map<Cdt::Face_handle, int> level;
  std::deque<std::pair<Cdt::Face_handle, int>> seeds = {{cdt.infinite_face(), 0}};
  while (!seeds.empty()) {
    const auto [seed, seed_level] = seeds.front();
    seeds.pop_front();
    if (level.count(seed) != 0) continue;
    std::deque<Cdt::Face_handle> queue = {seed};
    level[seed] = seed_level;
    while (!queue.empty()) {
      const Cdt::Face_handle f = queue.front();
      queue.pop_front();
      for (int i = 0; i < 3; ++i) {
        const Cdt::Face_handle n = f->neighbor(i);
        if (level.count(n) != 0) continue;
        if (cdt.is_constrained(Cdt::Edge(f, i))) {
          seeds.emplace_back(n, seed_level + 1);
        } else {
          level[n] = seed_level;
          queue.push_back(n);
        }
      }
    }
  }
  return level;
}

}  // namespace

TriangleMesh triangulate_contours(const ContourSet& contours) {
  Cdt cdt;
  LiftedPoints points;
  try {
    insert_contours(contours, &cdt, &points);
  } catch (const Cdt::Intersection_of_constraints_exception&) {
    invariant_failed("generated contours do not cross", __FILE__, __LINE__);
  }
  const std::unordered_map<Cdt::Face_handle, int> level = enclosing_contours(cdt);
  std::vector<int> new_index(points.xy.size(), -1);
  std::vector<Eigen::Vector3i> faces;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (level.at(f) == 0) continue;  // outside the outermost key contours
    const int a = f->vertex(0)->info();
    const int b = f->vertex(1)->info();
    const int c = f->vertex(2)->info();
    faces.emplace_back(a, b, c);  // CGAL faces are counter-clockwise
    for (int v : {a, b, c}) new_index[v] = 0;
  }
  TriangleMesh mesh;
  int count = 0;
  for (int& idx : new_index) idx = idx < 0 ? -1 : count++;
  mesh.V.resize(count, 3);
  for (std::size_t i = 0; i < points.xy.size(); ++i) {
    if (new_index[i] >= 0) mesh.V.row(new_index[i]) << points.xy[i].x(), points.xy[i].y(), points.z[i];
  }
  mesh.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) {
    mesh.F.row(static_cast<Eigen::Index>(f)) << new_index[faces[f][0]], new_index[faces[f][1]], new_index[faces[f][2]];
  }
  return mesh;
}

}  // namespace repose
