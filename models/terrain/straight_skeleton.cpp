// The only translation unit that includes CGAL's straight skeleton (~25 s and
// ~1.1 GB to compile).
#include "models/terrain/straight_skeleton.h"

#include <algorithm>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/create_offset_polygons_2.h>
#include <CGAL/create_straight_skeleton_2.h>

#include "models/core/base/error.h"

namespace repose {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using CgalPolygon = CGAL::Polygon_2<Kernel>;
using Skeleton = CGAL::Straight_skeleton_2<Kernel>;
}  // namespace

struct StraightSkeleton::Impl {
  boost::shared_ptr<Skeleton> skeleton;  // CGAL 5.5 returns boost::shared_ptr
};

StraightSkeleton::StraightSkeleton(const Polygon2& polygon) : impl_(std::make_unique<Impl>()) {
  REPOSE_DEMAND(polygon.size() >= 3 && signed_area_m2(polygon) > 0.0);
  CgalPolygon cgal;
  for (const Point2& p : polygon) cgal.push_back(Kernel::Point_2(p.x(), p.y()));
  impl_->skeleton = CGAL::create_interior_straight_skeleton_2(cgal.vertices_begin(), cgal.vertices_end(), Kernel());
  if (!impl_->skeleton) throw InputError("terrain: CGAL could not build the straight skeleton of a contour");
  for (auto v = impl_->skeleton->vertices_begin(); v != impl_->skeleton->vertices_end(); ++v) {
    if (!v->is_skeleton()) continue;
    nodes_.push_back({Point2(CGAL::to_double(v->point().x()), CGAL::to_double(v->point().y())),
                      CGAL::to_double(v->time())});
    vanish_time_m_ = std::max(vanish_time_m_, nodes_.back().time_m);
  }
}

StraightSkeleton::~StraightSkeleton() = default;
StraightSkeleton::StraightSkeleton(StraightSkeleton&&) noexcept = default;
StraightSkeleton& StraightSkeleton::operator=(StraightSkeleton&&) noexcept = default;

std::vector<Polygon2> StraightSkeleton::offset(double distance_m) const {
  REPOSE_DEMAND(distance_m > 0.0);
  std::vector<Polygon2> out;
  if (distance_m >= vanish_time_m_) return out;
  const auto pieces = CGAL::create_offset_polygons_2<CgalPolygon>(distance_m, *impl_->skeleton, Kernel());
  for (const auto& piece : pieces) {
    Polygon2 polygon;
    for (auto v = piece->vertices_begin(); v != piece->vertices_end(); ++v) {
      polygon.emplace_back(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
    }
    if (polygon.size() >= 3 && std::abs(signed_area_m2(polygon)) > 0.0) out.push_back(counter_clockwise(polygon));
  }
  return out;
}

}  // namespace repose
