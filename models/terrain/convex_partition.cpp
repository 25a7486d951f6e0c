// CGAL's 2-D partitioning, kept out of the other files.
#include "models/terrain/convex_partition.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/partition_2.h>

#include <iterator>
#include <list>

#include "models/core/base/error.h"

namespace repose {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Traits = CGAL::Partition_traits_2<Kernel>;
}  // namespace

std::vector<Polygon2> convex_partition(const Polygon2& polygon) {
  REPOSE_DEMAND(polygon.size() >= 3 && signed_area_m2(polygon) > 0.0);
  std::vector<Traits::Point_2> points;
  for (const Point2& p : polygon) points.emplace_back(p.x(), p.y());
  std::list<Traits::Polygon_2> pieces;
  if (polygon.size() <= kOptimalPartitionMaxVertices) {
    CGAL::optimal_convex_partition_2(points.begin(), points.end(), std::back_inserter(pieces));
  } else {
    CGAL::approx_convex_partition_2(points.begin(), points.end(), std::back_inserter(pieces));
  }
  std::vector<Polygon2> out;
  for (const Traits::Polygon_2& piece : pieces) {
    Polygon2 p;
    for (auto v = piece.vertices_begin(); v != piece.vertices_end(); ++v) p.emplace_back(v->x(), v->y());
    out.push_back(counter_clockwise(std::move(p)));
  }
  return out;
}

}  // namespace repose
