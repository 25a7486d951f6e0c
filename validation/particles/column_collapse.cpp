#include "validation/particles/column_collapse.h"

#include <numbers>

#include <fstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/particles/particle_observables.h"

namespace repose {

double column_front_m(const ColumnGeometry& geometry, const GrainSet& grains, double max_gap_m, int sector_count,
                      double* spread_m) {
  if (geometry.shape == DemSpec::ColumnShape::kSlot) {
    if (spread_m) *spread_m = 0.0;
    return deposit_front_m(grains, Eigen::Vector3d(geometry.back_wall_x_m, 0.0, 0.0), Eigen::Vector3d::UnitX(),
                           max_gap_m);
  }
  const RadialFront f = radial_deposit_front(grains, geometry.axis_xy_m, max_gap_m, sector_count,
                                             {geometry.azimuth_begin_rad, geometry.azimuth_span_rad});
  if (spread_m) *spread_m = f.std_m;
  return f.mean_m;
}

ColumnCollapse measure_column_collapse(const ColumnGeometry& geometry, const GrainSet& initial,
                                       const std::vector<GrainSet>& frames, const std::vector<double>& frame_time_s,
                                       double grain_diameter_m, const ColumnCollapseOptions& options) {
  if (frames.empty()) throw InputError("column collapse: no frames");
  REPOSE_DEMAND(frames.size() == frame_time_s.size());
  REPOSE_DEMAND(geometry.width_m > 0.0 && grain_diameter_m > 0.0);
  const double gap = options.max_gap_grain_diameters * grain_diameter_m;
  ColumnCollapse c;
  c.geometry = geometry;
  c.height_initial_m = grain_top_m(initial);
  c.aspect_ratio = c.height_initial_m / geometry.width_m;
  c.front_initial_m = column_front_m(geometry, initial, gap, options.sector_count);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    c.time_s.push_back(frame_time_s[k]);
    c.front_m.push_back(column_front_m(geometry, frames[k], gap, options.sector_count));
  }
  c.front_final_m = column_front_m(geometry, frames.back(), gap, options.sector_count, &c.front_final_spread_m);
  c.height_final_m = grain_top_m(frames.back());
  c.runout_normalised = (c.front_final_m - c.front_initial_m) / geometry.width_m;
  return c;
}

void write_runout_csv(const std::string& path, const ColumnCollapse& collapse) {
  std::ofstream out(path);
  if (!out) throw InputError(fmt::format("{}: cannot write", path));
  out << "time_s,front_m\n";
  for (std::size_t k = 0; k < collapse.time_s.size(); ++k) {
    out << fmt::format("{},{}\n", collapse.time_s[k], collapse.front_m[k]);
  }
  if (!out) throw InputError(fmt::format("{}: write failed", path));
}

nlohmann::json column_results_json(const std::optional<ColumnCollapse>& column, const std::optional<FlankAngles>& pile) {
  constexpr double deg = 180.0 / std::numbers::pi;
  nlohmann::json json = nlohmann::json::object();
  if (column) {
    const ColumnCollapse& c = *column;
    json["column"] = {{"shape", column_shape_name(c.geometry.shape)},
                      {"width_m", c.geometry.width_m},
                      {"slot_gap_m", c.geometry.gap_m},
                      {"height_initial_m", c.height_initial_m},
                      {"aspect_ratio", c.aspect_ratio},
                      {"front_initial_m", c.front_initial_m},
                      {"front_final_m", c.front_final_m},
                      {"front_final_spread_m", c.front_final_spread_m},
                      {"height_final_m", c.height_final_m},
                      {"runout_normalised", c.runout_normalised}};
  }
  if (pile) {
    json["pile"] = {{"flank_angle_mean_deg", pile->mean_rad * deg},
                    {"flank_angle_std_deg", pile->std_rad * deg},
                    {"azimuth_count", pile->angle_rad.size()}};
  }
  return json;
}

}  // namespace repose
