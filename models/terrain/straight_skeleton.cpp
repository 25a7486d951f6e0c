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
  auto xy = [](const Kernel::Point_2& p) { return Point2(CGAL::to_double(p.x()), CGAL::to_double(p.y())); };
  for (auto f = impl_->skeleton->faces_begin(); f != impl_->skeleton->faces_end(); ++f) {
    Face face;
    // a face's first halfedge is its polygon edge
    face.edge_from = xy(f->halfedge()->opposite()->vertex()->point());
    face.edge_to = xy(f->halfedge()->vertex()->point());
    auto h = f->halfedge();
    do {
      face.outline.push_back(xy(h->vertex()->point()));
      h = h->next();
    } while (h != f->halfedge());
    faces_.push_back(std::move(face));
  }
}

double StraightSkeleton::roof_time_m(const Point2& p) const {
  for (const Face& f : faces_) {
    if (!contains_point(f.outline, p)) continue;
    const Point2 d = f.edge_to - f.edge_from;
    return std::abs(d.x() * (p.y() - f.edge_from.y()) - d.y() * (p.x() - f.edge_from.x())) / d.norm();
  }
  return 0.0;
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

struct ExteriorSkeleton::Impl {
  boost::shared_ptr<Skeleton> skeleton;
  Point2 inside;  // a vertex of the polygon: the grown polygon holds it
};

ExteriorSkeleton::ExteriorSkeleton(const Polygon2& polygon, double max_distance_m)
    : impl_(std::make_unique<Impl>()), max_distance_m_(max_distance_m) {
  REPOSE_DEMAND(polygon.size() >= 3 && signed_area_m2(polygon) > 0.0 && max_distance_m > 0.0);
  CgalPolygon cgal;
  for (const Point2& p : polygon) cgal.push_back(Kernel::Point_2(p.x(), p.y()));
  impl_->skeleton =
      CGAL::create_exterior_straight_skeleton_2(max_distance_m, cgal.vertices_begin(), cgal.vertices_end(), Kernel());
  if (!impl_->skeleton) throw InputError("terrain: CGAL could not build the exterior skeleton of a contour");
  impl_->inside = polygon.front();
}

ExteriorSkeleton::~ExteriorSkeleton() = default;
ExteriorSkeleton::ExteriorSkeleton(ExteriorSkeleton&&) noexcept = default;
ExteriorSkeleton& ExteriorSkeleton::operator=(ExteriorSkeleton&&) noexcept = default;

Polygon2 ExteriorSkeleton::offset(double distance_m) const {
  REPOSE_DEMAND(distance_m > 0.0 && distance_m < max_distance_m_);
  const auto pieces = CGAL::create_offset_polygons_2<CgalPolygon>(distance_m, *impl_->skeleton, Kernel());
  // the pieces are the offset frame (largest), the grown polygon, and any
  // enclosed pockets: the grown polygon is the largest piece after the frame
  std::vector<Polygon2> loops;
  for (const auto& piece : pieces) {
    Polygon2 polygon;
    for (auto v = piece->vertices_begin(); v != piece->vertices_end(); ++v) {
      polygon.emplace_back(CGAL::to_double(v->x()), CGAL::to_double(v->y()));
    }
    loops.push_back(counter_clockwise(std::move(polygon)));
  }
  std::sort(loops.begin(), loops.end(),
            [](const Polygon2& a, const Polygon2& b) { return signed_area_m2(a) > signed_area_m2(b); });
  REPOSE_DEMAND(loops.size() >= 2 && contains_point(loops[1], impl_->inside));
  return loops[1];
}

}  // namespace repose
