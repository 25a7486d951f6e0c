#include "models/terrain/key_contour.h"

#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

void check_one(const KeyContour& c, std::size_t index) {
  const std::string label = fmt::format("terrain: key contour {} ('{}')", index, c.name);
  if (c.polygon_m.size() < 3) {
    throw InputError(fmt::format("{}: has {} vertices, a closed contour needs at least 3", label, c.polygon_m.size()));
  }
  if (!std::isfinite(c.height_m)) throw InputError(fmt::format("{}: height_m is not finite", label));
  for (const Point2& p : c.polygon_m) {
    if (!p.allFinite()) throw InputError(fmt::format("{}: a vertex coordinate is not finite", label));
  }
  if (!is_simple(c.polygon_m)) {
    throw InputError(fmt::format("{}: the polygon intersects itself or repeats a vertex", label));
  }
  if (std::abs(signed_area_m2(c.polygon_m)) <= 0.0) throw InputError(fmt::format("{}: the polygon has no area", label));
}

}  // namespace

ContourNesting validate_key_contours(std::vector<KeyContour>* contours) {
  REPOSE_DEMAND(contours != nullptr);
  std::vector<KeyContour>& cs = *contours;
  if (cs.empty()) throw InputError("terrain: no key contours given (key_contours needs at least one)");
  for (std::size_t i = 0; i < cs.size(); ++i) {
    check_one(cs[i], i);
    cs[i].polygon_m = counter_clockwise(std::move(cs[i].polygon_m));
  }
  const int n = static_cast<int>(cs.size());
  ContourNesting nesting;
  nesting.parent.assign(n, -1);
  nesting.children.assign(n, {});
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      if (boundaries_cross(cs[i].polygon_m, cs[j].polygon_m)) {
        throw InputError(fmt::format("terrain: key contours {} ('{}') and {} ('{}') cross or touch: contours must nest",
                                     i, cs[i].name, j, cs[j].name));
      }
    }
  }
  // the parent is the containing contour of smallest area
  for (int i = 0; i < n; ++i) {
    double best_area = INFINITY;
    for (int j = 0; j < n; ++j) {
      if (j == i || !contains_point(cs[j].polygon_m, cs[i].polygon_m.front())) continue;
      const double area = signed_area_m2(cs[j].polygon_m);
      if (area < best_area) {
        best_area = area;
        nesting.parent[i] = j;
      }
    }
  }
  for (int i = 0; i < n; ++i) {
    const int p = nesting.parent[i];
    if (p < 0) {
      nesting.roots.push_back(i);
      continue;
    }
    if (!(cs[i].height_m > cs[p].height_m)) {
      throw InputError(fmt::format(
          "terrain: key contour {} ('{}') at {} m lies inside key contour {} ('{}') at {} m: heights must increase "
          "inward",
          i, cs[i].name, cs[i].height_m, p, cs[p].name, cs[p].height_m));
    }
    nesting.children[p].push_back(i);
  }
  return nesting;
}

}  // namespace repose
