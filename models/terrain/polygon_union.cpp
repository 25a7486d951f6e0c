// CGAL's Boolean set operations (exact constructions), kept out of the other files.
#include "models/terrain/polygon_union.h"

#include <CGAL/Boolean_set_operations_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_set_2.h>

#include <iterator>
#include <list>

#include "models/core/base/error.h"

namespace repose {

namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPolygon = CGAL::Polygon_2<Kernel>;
using ExactPolygonWithHoles = CGAL::Polygon_with_holes_2<Kernel>;

Polygon2 to_double(const ExactPolygon& p) {
  Polygon2 out;
  for (auto v = p.vertices_begin(); v != p.vertices_end(); ++v) {
    out.emplace_back(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
  }
  return counter_clockwise(std::move(out));
}

}  // namespace

std::vector<Polygon2> union_boundaries(const std::vector<Polygon2>& polygons) {
  CGAL::Polygon_set_2<Kernel> set;
  for (const Polygon2& polygon : polygons) {
    REPOSE_DEMAND(polygon.size() >= 3 && signed_area_m2(polygon) > 0.0);
    ExactPolygon exact;
    for (const Point2& p : polygon) exact.push_back(Kernel::Point_2(p.x(), p.y()));
    REPOSE_DEMAND(exact.is_simple());
    set.join(exact);
  }
  std::list<ExactPolygonWithHoles> parts;
  set.polygons_with_holes(std::back_inserter(parts));
  std::vector<Polygon2> loops;
  for (const ExactPolygonWithHoles& part : parts) {
    loops.push_back(to_double(part.outer_boundary()));
    for (auto h = part.holes_begin(); h != part.holes_end(); ++h) loops.push_back(to_double(*h));
  }
  return loops;
}

}  // namespace repose
