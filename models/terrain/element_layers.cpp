#include "models/terrain/element_layers.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/terrain/sphere_rest_height.h"

namespace repose {

void ElementSource::validate() const {
  if (region_m.size() < 3 || !is_simple(region_m)) {
    throw InputError("terrain: elements: region_m must be a simple polygon of at least 3 vertices");
  }
  if (layers.empty()) throw InputError("terrain: elements: layers needs at least one layer");
  if (!(gap_fraction >= 0.0 && gap_fraction < 1.0)) {
    throw InputError(fmt::format("terrain: elements: gap_fraction = {} must lie in [0, 1)", gap_fraction));
  }
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const ElementLayer& l = layers[i];
    const std::string label = fmt::format("terrain: elements: layers[{}] ('{}')", i, l.name);
    if (!(std::isfinite(l.radius_m) && l.radius_m > 0.0)) {
      throw InputError(fmt::format("{}: radius_m = {} must be > 0", label, l.radius_m));
    }
    if (l.rows < 1) throw InputError(fmt::format("{}: rows = {} must be >= 1", label, l.rows));
    if (!(std::isfinite(l.friction) && l.friction >= 0.0)) {
      throw InputError(fmt::format("{}: friction = {} must be >= 0", label, l.friction));
    }
    if (!(l.restitution >= 0.0 && l.restitution <= 1.0)) {
      throw InputError(fmt::format("{}: restitution = {} must lie in [0, 1]", label, l.restitution));
    }
  }
}

namespace {

// Lowest centre height at xy that clears the terrain and every placed element.
std::optional<double> rest_height_m(const TerrainSurface& surface, const std::vector<PlacedElement>& placed,
                                    const Point2& xy, double radius_m, double gap_fraction) {
  std::optional<double> z = sphere_rest_height_m(surface, xy, radius_m);
  if (!z) return std::nullopt;
  for (const PlacedElement& e : placed) {
    const double gap_m = gap_fraction * std::min(radius_m, e.radius_m);
    const std::optional<double> over = sphere_on_sphere_height_m(xy, radius_m, e.centre_m, e.radius_m, gap_m);
    if (over) z = std::max(*z, *over);
  }
  return z;
}

}  // namespace

ElementLayout place_element_layers(const TerrainSurface& surface, const ElementSource& source) {
  source.validate();
  Eigen::AlignedBox2d box;
  for (const Point2& p : source.region_m) box.extend(p);
  ElementLayout layout;
  int row_index = 0;
  for (std::size_t l = 0; l < source.layers.size(); ++l) {
    const ElementLayer& layer = source.layers[l];
    const double spacing_m = 2.0 * layer.radius_m * (1.0 + source.gap_fraction);
    for (int row = 0; row < layer.rows; ++row, ++row_index) {
      const double shift = (row_index % 2 == 0) ? 0.5 * spacing_m : spacing_m;
      // the earlier rows only: a row's own spheres are a lattice spacing apart
      const std::vector<PlacedElement> below = layout.elements;
      for (double y = box.min().y() + shift; y <= box.max().y(); y += spacing_m) {
        for (double x = box.min().x() + shift; x <= box.max().x(); x += spacing_m) {
          const Point2 xy(x, y);
          if (!contains_point(source.region_m, xy)) continue;
          const std::optional<double> z = rest_height_m(surface, below, xy, layer.radius_m, source.gap_fraction);
          if (!z) {
            ++layout.skipped_off_terrain;
            continue;
          }
          layout.elements.push_back({Eigen::Vector3d(x, y, *z), layer.radius_m, static_cast<int>(l)});
        }
      }
    }
  }
  return layout;
}

}  // namespace repose
