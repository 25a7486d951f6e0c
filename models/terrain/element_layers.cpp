#include "models/terrain/element_layers.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

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
  if (!(radius_spread >= 0.0 && radius_spread < 1.0)) {
    throw InputError(fmt::format("terrain: elements: radius_spread = {} must lie in [0, 1)", radius_spread));
  }
  if (!(position_jitter >= 0.0 && position_jitter <= 1.0)) {
    throw InputError(fmt::format("terrain: elements: position_jitter = {} must lie in [0, 1]", position_jitter));
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
    if (!(std::isfinite(l.rolling_friction) && l.rolling_friction >= 0.0)) {
      throw InputError(fmt::format("{}: rolling_friction = {} must be >= 0", label, l.rolling_friction));
    }
    if (!(std::isfinite(l.density_kg_m3) && l.density_kg_m3 > 0.0)) {
      throw InputError(fmt::format("{}: density_kg_m3 = {} must be > 0", label, l.density_kg_m3));
    }
  }
}

namespace {

// The placed elements bucketed on a horizontal grid of cells at least one
// contact distance wide, so a new sphere is tested against the 3 x 3 cells
// around it instead of every element.
class ElementGrid {
 public:
  ElementGrid(const Eigen::AlignedBox2d& box, double cell_m) : lo_(box.min()), cell_m_(cell_m) {
    nx_ = std::max(1, static_cast<int>(std::ceil(box.sizes().x() / cell_m)) + 1);
    ny_ = std::max(1, static_cast<int>(std::ceil(box.sizes().y() / cell_m)) + 1);
    cells_.assign(static_cast<std::size_t>(nx_) * ny_, {});
  }
  void add(int index, const Point2& xy) { cells_[cell(xy)].push_back(index); }
  template <typename Visit>
  void near(const Point2& xy, Visit visit) const {
    const int ci = column(xy.x()), cj = row(xy.y());
    for (int j = std::max(0, cj - 1); j <= std::min(ny_ - 1, cj + 1); ++j) {
      for (int i = std::max(0, ci - 1); i <= std::min(nx_ - 1, ci + 1); ++i) {
        for (int e : cells_[static_cast<std::size_t>(j) * nx_ + i]) visit(e);
      }
    }
  }

 private:
  int column(double x) const { return std::clamp(static_cast<int>(std::floor((x - lo_.x()) / cell_m_)), 0, nx_ - 1); }
  int row(double y) const { return std::clamp(static_cast<int>(std::floor((y - lo_.y()) / cell_m_)), 0, ny_ - 1); }
  std::size_t cell(const Point2& xy) const { return static_cast<std::size_t>(row(xy.y())) * nx_ + column(xy.x()); }

  Point2 lo_;
  double cell_m_;
  int nx_ = 1, ny_ = 1;
  std::vector<std::vector<int>> cells_;
};

// Lowest centre height at xy that clears the terrain and every element placed in earlier rows.
std::optional<double> rest_height_m(const TerrainSurface& surface, const std::vector<PlacedElement>& placed,
                                    std::size_t earlier_rows, const ElementGrid& grid, const Point2& xy,
                                    double radius_m, double gap_fraction) {
  std::optional<double> z = sphere_rest_height_m(surface, xy, radius_m);
  if (!z) return std::nullopt;
  grid.near(xy, [&](int index) {
    if (static_cast<std::size_t>(index) >= earlier_rows) return;
    const PlacedElement& e = placed[static_cast<std::size_t>(index)];
    const double gap_m = gap_fraction * std::min(radius_m, e.radius_m);
    const std::optional<double> over = sphere_on_sphere_height_m(xy, radius_m, e.centre_m, e.radius_m, gap_m);
    if (over) z = std::max(*z, *over);
  });
  return z;
}

// One lattice point's sphere in a random bed (element_layers.h): its radius
// and its centre moved within its room. Always draws three numbers, so a
// point's draw does not depend on whether earlier points were kept.
struct BedDraw {
  double radius_m;
  Point2 xy;
};

BedDraw draw_bed(std::mt19937_64& rng, const ElementSource& source, double layer_radius_m, const Point2& lattice) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double u_radius = unit(rng), u_distance = unit(rng), u_angle = unit(rng);
  const double r = layer_radius_m * (1.0 - source.radius_spread * u_radius);
  const double room_m = (layer_radius_m - r) + 0.5 * source.gap_fraction * layer_radius_m;
  // uniform over the disc of radius jitter * room
  const double d = source.position_jitter * room_m * std::sqrt(u_distance);
  const double a = 2.0 * std::numbers::pi * u_angle;
  return {r, lattice + d * Point2(std::cos(a), std::sin(a))};
}

}  // namespace

ElementLayout place_element_layers(const TerrainSurface& surface, const ElementSource& source) {
  source.validate();
  Eigen::AlignedBox2d box;
  for (const Point2& p : source.region_m) box.extend(p);
  double largest_m = 0.0;
  for (const ElementLayer& l : source.layers) largest_m = std::max(largest_m, l.radius_m);
  // two spheres closer than a cell horizontally are the only ones that can touch
  ElementGrid grid(box, 2.0 * largest_m * (1.0 + source.gap_fraction));
  ElementLayout layout;
  std::mt19937_64 rng(source.seed);
  int row_index = 0;
  for (std::size_t l = 0; l < source.layers.size(); ++l) {
    const ElementLayer& layer = source.layers[l];
    const double spacing_m = 2.0 * layer.radius_m * (1.0 + source.gap_fraction);
    for (int row = 0; row < layer.rows; ++row, ++row_index) {
      const double shift = (row_index % 2 == 0) ? 0.5 * spacing_m : spacing_m;
      // the earlier rows only: a row's own spheres are a lattice spacing apart
      const std::size_t earlier_rows = layout.elements.size();
      for (double y = box.min().y() + shift; y <= box.max().y(); y += spacing_m) {
        for (double x = box.min().x() + shift; x <= box.max().x(); x += spacing_m) {
          const BedDraw bed = draw_bed(rng, source, layer.radius_m, Point2(x, y));
          const Point2& xy = bed.xy;
          if (!contains_point(source.region_m, xy)) continue;
          const std::optional<double> z = rest_height_m(surface, layout.elements, earlier_rows, grid, xy,
                                                        bed.radius_m, source.gap_fraction);
          if (!z) {
            ++layout.skipped_off_terrain;
            continue;
          }
          grid.add(static_cast<int>(layout.elements.size()), xy);
          layout.elements.push_back({Eigen::Vector3d(xy.x(), xy.y(), *z), bed.radius_m, static_cast<int>(l)});
        }
      }
    }
  }
  return layout;
}

}  // namespace repose
