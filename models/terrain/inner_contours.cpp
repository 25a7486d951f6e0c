#include "models/terrain/inner_contours.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "models/core/base/error.h"
#include "models/terrain/bspline_contour.h"
#include "models/terrain/straight_skeleton.h"

namespace repose {

namespace {

// a skeleton node this close to a contour adds nothing but a sliver
constexpr double kNodeMergeFraction = 1e-6;

struct Piece {
  Polygon2 raw;  // shrunk polygon, before smoothing
  double level_m = 0.0;
  double distance_m = 0.0;  // shrink distance
  bool kept = true;
};

struct Region {
  const KeyContour* key = nullptr;
  std::vector<const KeyContour*> children;
  double tan_slope = 0.0;
  double level_spacing_m = 0.0;  // shrink distance between levels
};

double first_level_above(double height_m, double interval_m) {
  double level = std::ceil(height_m / interval_m) * interval_m;
  if (level <= height_m + 1e-9 * interval_m) level += interval_m;
  return level;
}

enum class PieceFate { kKept, kInsideChild, kDropped };

PieceFate piece_fate(const Piece& piece, const Region& region, const std::vector<Piece>& lower) {
  for (const KeyContour* child : region.children) {
    // the child's own contours take over there
    if (nested_inside(piece.raw, child->polygon_m)) return PieceFate::kInsideChild;
  }
  for (const Piece& earlier : lower) {
    if (!earlier.kept && contains_point(earlier.raw, piece.raw.front())) return PieceFate::kDropped;
  }
  const double clearance_m = 0.25 * region.level_spacing_m;
  for (const KeyContour* child : region.children) {
    if (boundary_distance_m(piece.raw, child->polygon_m) < clearance_m) return PieceFate::kDropped;
    if (contains_point(piece.raw, child->polygon_m.front()) && piece.level_m >= child->height_m) {
      return PieceFate::kDropped;
    }
  }
  return PieceFate::kKept;
}

std::vector<Piece> shrink_levels(const StraightSkeleton& skeleton, const Region& region,
                                 const TerrainOptions& options, int* dropped) {
  std::vector<Piece> pieces;
  const double h0 = region.key->height_m;
  for (double level = first_level_above(h0, options.contour_interval_m);; level += options.contour_interval_m) {
    const double d = (level - h0) / region.tan_slope;
    if (d >= skeleton.vanish_time_m()) break;
    const std::size_t before = pieces.size();
    for (Polygon2& polygon : skeleton.offset(d)) pieces.push_back({std::move(polygon), level, d, true});
    for (std::size_t i = before; i < pieces.size(); ++i) {
      const std::vector<Piece> lower(pieces.begin(), pieces.begin() + static_cast<std::ptrdiff_t>(before));
      const PieceFate fate = piece_fate(pieces[i], region, lower);
      pieces[i].kept = fate == PieceFate::kKept;
      if (fate == PieceFate::kDropped) ++*dropped;
    }
  }
  return pieces;
}

// the innermost kept piece holding p encloses no child, and no dropped piece holds p
bool node_belongs_to_roof(const Point2& p, const Region& region, const std::vector<Piece>& pieces) {
  const Piece* innermost = nullptr;
  for (const Piece& piece : pieces) {
    if (!contains_point(piece.raw, p)) continue;
    if (!piece.kept) return false;
    if (innermost == nullptr || piece.level_m > innermost->level_m) innermost = &piece;
  }
  const double clearance_m = 0.25 * region.level_spacing_m;
  for (const KeyContour* child : region.children) {
    if (contains_point(child->polygon_m, p)) return false;
    double gap = std::numeric_limits<double>::infinity();
    const Polygon2& c = child->polygon_m;
    for (std::size_t i = 0; i < c.size(); ++i) gap = std::min(gap, point_segment_distance_m(p, c[i], c[(i + 1) % c.size()]));
    if (gap < clearance_m) return false;
    const Polygon2& enclosing = innermost != nullptr ? innermost->raw : region.key->polygon_m;
    if (contains_point(enclosing, c.front())) return false;
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

// The largest smoothing tolerance that keeps piece i clear of its neighbours.
double safe_tolerance_m(std::size_t i, const std::vector<Piece>& kept, const Region& region,
                        const std::vector<SummitPoint>& summits, double tolerance_m) {
  const Piece& piece = kept[i];
  // levels one spacing apart are at least one spacing apart (1-Lipschitz roof);
  // the key contour itself is piece.distance_m away
  double gap = std::min(region.level_spacing_m, piece.distance_m);
  for (std::size_t j = 0; j < kept.size(); ++j) {
    if (j != i && kept[j].level_m == piece.level_m) gap = std::min(gap, boundary_distance_m(piece.raw, kept[j].raw));
  }
  for (const KeyContour* child : region.children) gap = std::min(gap, boundary_distance_m(piece.raw, child->polygon_m));
  for (const SummitPoint& s : summits) gap = std::min(gap, distance_to_boundary_m(s.point_m, piece.raw));
  return std::min(tolerance_m, 0.45 * gap);
}

void add_region(const std::vector<KeyContour>& keys, const ContourNesting& nesting, int k,
                const TerrainOptions& options, ContourSet* out) {
  Region region;
  region.key = &keys[k];
  for (int c : nesting.children[k]) region.children.push_back(&keys[c]);
  region.tan_slope = std::tan(options.slope_rad);
  region.level_spacing_m = options.contour_interval_m / region.tan_slope;

  const StraightSkeleton skeleton(region.key->polygon_m);
  std::vector<Piece> pieces = shrink_levels(skeleton, region, options, &out->dropped_pieces);
  std::vector<Piece> kept;
  for (Piece& p : pieces) {
    if (p.kept) kept.push_back(p);
  }
  std::vector<SummitPoint> summits;
  const double merge_m = kNodeMergeFraction * region.level_spacing_m;
  for (const SkeletonNode& node : skeleton.nodes()) {
    if (!node_belongs_to_roof(node.point_m, region, pieces)) continue;
    bool on_contour = false;
    for (const Piece& p : kept) on_contour = on_contour || distance_to_boundary_m(node.point_m, p.raw) < merge_m;
    if (!on_contour) summits.push_back({node.point_m, region.key->height_m + region.tan_slope * node.time_m});
  }
  out->contours.push_back({densified(region.key->polygon_m, options.sample_spacing_m), region.key->height_m, k, true, 0.0});
  for (std::size_t i = 0; i < kept.size(); ++i) {
    const double tolerance_m = safe_tolerance_m(i, kept, region, summits, options.smoothing_tolerance_m);
    Polygon2 sampled = tolerance_m > merge_m ? smoothed_contour(kept[i].raw, tolerance_m, options.sample_spacing_m)
                                             : densified(kept[i].raw, options.sample_spacing_m);
    out->contours.push_back({std::move(sampled), kept[i].level_m, k, false, tolerance_m});
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
