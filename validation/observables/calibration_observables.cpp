#include "validation/observables/calibration_observables.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/observables/heap_flank.h"
#include "validation/particles/particle_observables.h"

namespace repose {

namespace {

std::vector<double> cell_values(const HeightField& h, const std::vector<std::size_t>& cells) {
  std::vector<double> out;
  out.reserve(cells.size());
  for (const std::size_t c : cells) out.push_back(h.heights().data()[c]);
  return out;
}

double mean(const std::vector<double>& v) {
  double s = 0.0;
  for (const double x : v) s += x;
  return s / static_cast<double>(v.size());
}

// Points spread evenly from `from` to `to`, both ends included.
std::vector<Eigen::Vector2d> line_points(const ObservableSpec& o) {
  std::vector<Eigen::Vector2d> points;
  for (int k = 0; k < o.samples; ++k) {
    const double t = static_cast<double>(k) / (o.samples - 1);
    points.push_back(o.from_m + t * (o.to_m - o.from_m));
  }
  return points;
}

double pile_angle_rad(const HeightField& h, const Eigen::Vector2d& centre) {
  try {
    return pile_flank_angles(h, centre).mean_rad;
  } catch (const InputError&) {
    return 0.0;  // no flank on any ray: a flat surface, angle 0
  }
}

// The entry `name` of a run's series or measures, or InputError naming what the run has.
template <typename Map>
const typename Map::mapped_type& named_entry(const Map& entries, const std::string& name, const char* kind) {
  const auto it = entries.find(name);
  if (it == entries.end()) {
    std::string names;
    for (const auto& entry : entries) names += (names.empty() ? "" : ", ") + entry.first;
    throw InputError(fmt::format("{} observable: the run has no {} '{}' (it has: {})", kind, kind, name,
                                 names.empty() ? "none" : names));
  }
  return it->second;
}

std::vector<double> series_values(const ObservableSpec& o, const SeriesByName& series) {
  const TimeSeries& s = named_entry(series, o.series, "series");
  std::vector<double> out;
  for (const double t : o.times_s) out.push_back(s.at(t));
  return out;
}

double heap_flank_rad(const ObservableSpec& o, const HeightField& initial, const HeightField& final_height) {
  HeapFlankOptions options;
  options.base_height_m = o.base_height_m ? *o.base_height_m : initial.heights().mean();
  options.peak_region = o.region;
  options.reach_m = o.reach_m;
  return heap_flank(final_height, options).mean_rad;
}

std::vector<double> measure_value(const ObservableSpec& o, const MeasureByName& measures) {
  return {named_entry(measures, o.measure, "measure")};
}

}  // namespace

std::vector<std::size_t> cells_in(const std::optional<CalibrationRegion>& region, const Grid& grid) {
  std::vector<std::size_t> cells;
  for (int j = 0; j < grid.ny; ++j) {
    for (int i = 0; i < grid.nx; ++i) {
      if (!region || region->contains(grid.centre_x(i), grid.centre_y(j))) {
        cells.push_back(static_cast<std::size_t>(j) * static_cast<std::size_t>(grid.nx) + static_cast<std::size_t>(i));
      }
    }
  }
  if (cells.empty()) {
    throw InputError(fmt::format("calibration region x [{}, {}] m, y [{}, {}] m holds no cell centre of the scene's grid",
                                 region->x_min_m, region->x_max_m, region->y_min_m, region->y_max_m));
  }
  return cells;
}

std::vector<double> observe(const ObservableSpec& o, const HeightField& initial, const HeightField& final_height,
                            const SeriesByName& series, const MeasureByName& measures) {
  using K = ObservableSpec::Kind;
  switch (o.kind) {
    case K::kHeightField:
      return cell_values(final_height, cells_in(o.region, final_height.grid()));
    case K::kTransect: {
      std::vector<double> out;
      for (const Eigen::Vector2d& p : line_points(o)) out.push_back(final_height.sample(p.x(), p.y()));
      return out;
    }
    case K::kCraterDepth: {
      const auto cells = cells_in(o.region, final_height.grid());
      const auto after = cell_values(final_height, cells);
      return {mean(cell_values(initial, cells)) - *std::min_element(after.begin(), after.end())};
    }
    case K::kRimHeight: {
      const auto cells = cells_in(o.region, final_height.grid());
      const auto after = cell_values(final_height, cells);
      return {*std::max_element(after.begin(), after.end()) - mean(cell_values(initial, cells))};
    }
    case K::kPileAngle:
      return {pile_angle_rad(final_height, o.centre_m)};
    case K::kFurrowArea: {
      // trapezoid rule over the depth below the initial surface
      const auto points = line_points(o);
      const double ds = (o.to_m - o.from_m).norm() / (o.samples - 1);
      double area = 0.0;
      for (std::size_t k = 0; k < points.size(); ++k) {
        const double depth = std::max(0.0, initial.sample(points[k].x(), points[k].y()) -
                                               final_height.sample(points[k].x(), points[k].y()));
        area += (k == 0 || k + 1 == points.size() ? 0.5 : 1.0) * depth * ds;
      }
      return {area};
    }
    case K::kSeries:
      return series_values(o, series);
    case K::kMeasure:
      return measure_value(o, measures);
    case K::kHeapFlank:
      return {heap_flank_rad(o, initial, final_height)};
  }
  REPOSE_DEMAND(false);
  return {};
}

double surface_rmse_m(const HeightField& a, const HeightField& b, const std::optional<CalibrationRegion>& region) {
  REPOSE_DEMAND(a.grid() == b.grid());
  const auto cells = cells_in(region, a.grid());
  double sum = 0.0;
  for (const std::size_t c : cells) {
    const double d = a.heights().data()[c] - b.heights().data()[c];
    sum += d * d;
  }
  return std::sqrt(sum / static_cast<double>(cells.size()));
}

}  // namespace repose
