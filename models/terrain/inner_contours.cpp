#include "models/terrain/inner_contours.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/core/base/error.h"
#include "models/terrain/bspline_contour.h"
#include "models/terrain/polygon_union.h"
#include "models/terrain/straight_skeleton.h"

namespace repose {

namespace {

// a skeleton node this close to a contour adds nothing but a sliver
constexpr double kNodeMergeFraction = 1e-6;
// summit points closer than this fraction of the sample spacing are one
constexpr double kSummitMergeFraction = 0.1;

struct Child {
  const KeyContour* key = nullptr;
  ExteriorSkeleton skirt;
  double skirt_slope = 0.0;  // tan of the slope falling outward from the child
};

struct Region {
  const KeyContour* key = nullptr;
  std::vector<Child> children;
  double roof_slope = 0.0;       // tan of the slope rising inward from the key
  double level_spacing_m = 0.0;  // the least distance between neighbouring levels
};

struct Loop {
  Polygon2 raw;  // before smoothing
  double level_m = 0.0;
};

double first_level_above(double height_m, double interval_m) {
  double level = std::ceil(height_m / interval_m) * interval_m;
  if (level <= height_m + 1e-9 * interval_m) level += interval_m;
  return level;
}

// The loops of one level: the parent's shrunk pieces joined with the skirts
// of the children higher than the level (the ground is the higher of the two).
std::vector<Polygon2> level_loops(const StraightSkeleton& skeleton, const Region& region, double level_m) {
  std::vector<Polygon2> polygons;
  const double shrink_m = (level_m - region.key->height_m) / region.roof_slope;
  if (shrink_m < skeleton.vanish_time_m()) {
    for (Polygon2& piece : skeleton.offset(shrink_m)) {
      // a piece inside a lower child is that child's own ground
      bool inside_child = false;
      for (const Child& c : region.children) {
        inside_child = inside_child || (c.key->height_m <= level_m && nested_inside(piece, c.key->polygon_m));
      }
      if (inside_child) continue;
      // the roof slope keeps the roof under every child (choose_roof_slope)
      for (const Child& c : region.children) {
        REPOSE_DEMAND(c.key->height_m > level_m || !boundaries_cross(piece, c.key->polygon_m));
      }
      polygons.push_back(std::move(piece));
    }
  }
  for (const Child& c : region.children) {
    if (c.key->height_m <= level_m) continue;
    // the skirt slope keeps it inside the parent (choose_skirt_slope)
    polygons.push_back(c.skirt.offset((c.key->height_m - level_m) / c.skirt_slope));
  }
  if (polygons.size() <= 1) return polygons;
  return union_boundaries(polygons);
}

// A node of the parent's skeleton lies on the ground when no child holds it
// and no child's skirt rises above the roof there.
bool node_on_ground(const SkeletonNode& node, const Region& region) {
  const double z = region.key->height_m + region.roof_slope * node.time_m;
  for (const Child& c : region.children) {
    if (contains_point(c.key->polygon_m, node.point_m)) return false;
    if (c.key->height_m > z && contains_point(c.skirt.offset((c.key->height_m - z) / c.skirt_slope), node.point_m)) {
      return false;
    }
  }
  return true;
}

double distance_to_boundary_m(const Point2& p, const Polygon2& polygon) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    best = std::min(best, point_segment_distance_m(p, polygon[i], polygon[(i + 1) % polygon.size()]));
  }
  return best;
}

// The largest smoothing tolerance that keeps loop i clear of its neighbours:
// the ground rises at most tan(slope) per metre, so loops one level apart are
// at least a level spacing apart; same-level loops, the key contours and
// the summit points are measured.
double safe_tolerance_m(std::size_t i, const std::vector<Loop>& loops, const Region& region,
                        const std::vector<SummitPoint>& summits, double tolerance_m) {
  const Loop& loop = loops[i];
  double gap = std::min(region.level_spacing_m, boundary_distance_m(loop.raw, region.key->polygon_m));
  for (std::size_t j = 0; j < loops.size(); ++j) {
    if (j != i && loops[j].level_m == loop.level_m) gap = std::min(gap, boundary_distance_m(loop.raw, loops[j].raw));
  }
  for (const Child& c : region.children) gap = std::min(gap, boundary_distance_m(loop.raw, c.key->polygon_m));
  for (const SummitPoint& s : summits) gap = std::min(gap, distance_to_boundary_m(s.point_m, loop.raw));
  // 0.4: the sampled contour lies within 1.2 tolerances of its loop (bspline_contour.h)
  return std::min(tolerance_m, 0.4 * gap);
}

// The roof may rise no faster than the lowest child allows: on a child's
// outline the roof must stay below the child's height, so the roof slope is
// at most (h_child - h_key) / (largest roof time on the child's outline).
// The roof is 1-Lipschitz, so sampling the outline every `step` and adding
// half a step bounds that largest time from above.
double choose_roof_slope(const StraightSkeleton& skeleton, const KeyContour& key,
                         const std::vector<const KeyContour*>& children, double tan_slope, double step_m) {
  double slope = tan_slope;
  for (const KeyContour* c : children) {
    double highest_m = 0.0;
    for (const Point2& p : densified(c->polygon_m, step_m)) highest_m = std::max(highest_m, skeleton.roof_time_m(p));
    slope = std::min(slope, 0.999 * (c->height_m - key.height_m) / (highest_m + 0.5 * step_m));
  }
  return slope;
}

// The skirt may fall no slower than the room around the child allows: grown
// down to the parent's height it must stay inside the parent and off every
// sibling. Starts at the terrain's slope and steepens by 1.25 until it fits.
double choose_skirt_slope(const ExteriorSkeleton& skirt, const KeyContour& child, const KeyContour& key,
                          const std::vector<const KeyContour*>& siblings, double tan_slope) {
  const double rise_m = child.height_m - key.height_m;
  for (double slope = tan_slope; slope < 1e6 * tan_slope; slope *= 1.25) {
    const Polygon2 foot = skirt.offset(rise_m / slope);
    bool fits = !boundaries_cross(foot, key.polygon_m) && contains_point(key.polygon_m, foot.front());
    for (const KeyContour* other : siblings) {
      if (other == &child) continue;
      fits = fits && !boundaries_cross(foot, other->polygon_m) && !contains_point(foot, other->polygon_m.front());
    }
    if (fits) return slope;
  }
  REPOSE_DEMAND(false);  // nested, non-touching contours always leave room
  return tan_slope;
}

// Skeleton nodes crowd (a regular polygon's nodes all meet at its centre,
// to round-off): of nodes closer than merge_m keep the highest, which is
// the summit (ties: the lower x, then y, so the choice is symmetric).
std::vector<SummitPoint> merged_summits(std::vector<SummitPoint> points, double merge_m) {
  std::sort(points.begin(), points.end(), [](const SummitPoint& a, const SummitPoint& b) {
    if (a.height_m != b.height_m) return a.height_m > b.height_m;
    if (a.point_m.x() != b.point_m.x()) return a.point_m.x() < b.point_m.x();
    return a.point_m.y() < b.point_m.y();
  });
  std::vector<SummitPoint> kept;
  for (const SummitPoint& p : points) {
    bool near = false;
    for (const SummitPoint& k : kept) near = near || (k.point_m - p.point_m).norm() < merge_m;
    if (!near) kept.push_back(p);
  }
  return kept;
}

Region make_region(const std::vector<KeyContour>& keys, const ContourNesting& nesting, int k,
                   const StraightSkeleton& skeleton, const TerrainOptions& options) {
  Region region;
  region.key = &keys[k];
  const double tan_slope = std::tan(options.slope_rad);
  std::vector<const KeyContour*> children;
  for (int c : nesting.children[k]) children.push_back(&keys[c]);
  const double step_m = 0.05 * options.contour_interval_m / tan_slope;
  region.roof_slope = choose_roof_slope(skeleton, keys[k], children, tan_slope, step_m);
  double steepest = region.roof_slope;
  for (const KeyContour* c : children) {
    // skirts are never gentler than the terrain's slope: this reach suffices
    ExteriorSkeleton skirt(c->polygon_m, 1.01 * (c->height_m - keys[k].height_m) / tan_slope);
    const double skirt_slope = choose_skirt_slope(skirt, *c, keys[k], children, tan_slope);
    steepest = std::max(steepest, skirt_slope);
    region.children.push_back({c, std::move(skirt), skirt_slope});
  }
  // the ground is the higher of slopes at most `steepest`: levels one
  // interval apart are at least interval / steepest apart
  region.level_spacing_m = options.contour_interval_m / steepest;
  return region;
}

void add_region(const std::vector<KeyContour>& keys, const ContourNesting& nesting, int k,
                const TerrainOptions& options, ContourSet* out) {
  const StraightSkeleton skeleton(keys[k].polygon_m);
  const Region region = make_region(keys, nesting, k, skeleton, options);
  double top_m = region.key->height_m + region.roof_slope * skeleton.vanish_time_m();
  for (const Child& c : region.children) top_m = std::max(top_m, c.key->height_m);
  std::vector<Loop> loops;
  for (double level = first_level_above(region.key->height_m, options.contour_interval_m); level < top_m;
       level += options.contour_interval_m) {
    for (Polygon2& loop : level_loops(skeleton, region, level)) loops.push_back({std::move(loop), level});
  }
  std::vector<SummitPoint> summits;
  const double merge_m = kNodeMergeFraction * region.level_spacing_m;
  for (const SkeletonNode& node : skeleton.nodes()) {
    if (!node_on_ground(node, region)) continue;
    bool on_contour = false;
    for (const Loop& l : loops) on_contour = on_contour || distance_to_boundary_m(node.point_m, l.raw) < merge_m;
    if (!on_contour) summits.push_back({node.point_m, region.key->height_m + region.roof_slope * node.time_m});
  }
  summits = merged_summits(std::move(summits), kSummitMergeFraction * options.sample_spacing_m);
  out->contours.push_back({densified(region.key->polygon_m, options.sample_spacing_m), region.key->height_m, k, true, 0.0});
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const double tolerance_m = safe_tolerance_m(i, loops, region, summits, options.smoothing_tolerance_m);
    Polygon2 sampled = tolerance_m > merge_m ? smoothed_contour(loops[i].raw, tolerance_m, options.sample_spacing_m)
                                             : densified(loops[i].raw, options.sample_spacing_m);
    out->contours.push_back({std::move(sampled), loops[i].level_m, k, false, tolerance_m});
  }
  out->summits.insert(out->summits.end(), summits.begin(), summits.end());
}

}  // namespace

ContourSet generate_contours(const std::vector<KeyContour>& keys, const ContourNesting& nesting,
                             const TerrainOptions& options) {
  options.validate();
  REPOSE_DEMAND(nesting.parent.size() == keys.size());
  ContourSet out;
  for (int k = 0; k < static_cast<int>(keys.size()); ++k) add_region(keys, nesting, k, options, &out);
  return out;
}

}  // namespace repose
