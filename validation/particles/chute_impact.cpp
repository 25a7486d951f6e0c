#include "validation/particles/chute_impact.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/geometry/triangle_mesh.h"
#include "validation/particles/column_geometry.h"

namespace repose {

namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// The mean of the samples within half_width of t (the nearest sample when none is).
double smoothed_at(const std::vector<double>& time_s, const std::vector<double>& value, double t, double half_width) {
  const auto lo = std::lower_bound(time_s.begin(), time_s.end(), t - half_width);
  const auto hi = std::upper_bound(time_s.begin(), time_s.end(), t + half_width);
  if (lo < hi) {
    double sum = 0.0;
    for (auto it = lo; it != hi; ++it) sum += value[static_cast<std::size_t>(it - time_s.begin())];
    return sum / static_cast<double>(hi - lo);
  }
  const auto next = std::min(lo, time_s.end() - 1);
  const auto prev = next == time_s.begin() ? next : next - 1;
  const auto nearest = std::abs(*prev - t) <= std::abs(*next - t) ? prev : next;
  return value[static_cast<std::size_t>(nearest - time_s.begin())];
}

double quantile(std::vector<double> v, double q) {
  REPOSE_DEMAND(!v.empty());
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto i = static_cast<std::size_t>(std::floor(pos));
  const std::size_t j = std::min(i + 1, v.size() - 1);
  return v[i] + (pos - static_cast<double>(i)) * (v[j] - v[i]);
}

// Frames in the impact phase (see the header).
void mark_impact_phase(std::vector<ChuteFrame>& frames, const ChuteImpactOptions& options) {
  double fastest = 0.0;
  for (const ChuteFrame& f : frames) {
    if (f.flow.grains >= options.min_grains) fastest = std::max(fastest, f.flow.speed_m_s);
  }
  for (ChuteFrame& f : frames) {
    f.impact = fastest > 0.0 && f.flow.grains >= options.min_grains &&
               f.flow.speed_m_s >= options.flowing_speed_fraction * fastest && f.force_n > 0.0;
  }
}

}  // namespace

ChuteGeometry chute_geometry(const Scene& scene) {
  const DemSpec* dem = dem_of(scene);
  if (dem == nullptr) throw InputError(fmt::format("{}: no dem section: not a chute", scene.source_path));
  return chute_geometry(*dem, scene);
}

ChuteGeometry chute_geometry(const DemSpec& dem_spec, const Scene& scene) {
  const DemSpec* dem = &dem_spec;
  if (!measures_impact(*dem) || scene.objects.empty()) {
    throw InputError(fmt::format("{}: dem: no impact window (impact_window_m > 0 and a first object, the wall)",
                                 scene.source_path));
  }
  const ObjectSpec& wall = scene.objects.front();
  const Aabb box = bounding_box(transformed(wall.body, wall.pose_at(0.0)));
  const Grid& grid = scene.ground.grid;
  ChuteGeometry g;
  g.slope_rad = dem->slope_deg / kDeg;
  g.gravity_m_s2 = dem->gravity_m_s2;
  g.density_kg_m3 = dem->density_kg_m3;
  g.wall_face_x_m = box.min.x();
  const double y0 = std::max(grid.origin_y_m, box.min.y());
  const double y1 = std::min(grid.origin_y_m + grid.extent_y_m(), box.max.y());
  g.width_m = y1 - y0;
  g.window_x_max_m = g.wall_face_x_m - dem->impact_window_gap_m;
  g.window_x_min_m = g.window_x_max_m - dem->impact_window_m;
  if (!(g.width_m > 0.0) || g.window_x_min_m < grid.origin_x_m) {
    throw InputError(fmt::format("{}: dem: the impact window [{}, {}] m (upstream of the wall's face at x = {} m) "
                                 "must lie on the grid (x from {} m) and the wall must span part of its width",
                                 scene.source_path, g.window_x_min_m, g.window_x_max_m, g.wall_face_x_m,
                                 grid.origin_x_m));
  }
  return g;
}

double chute_splash_top_m(const DemSpec& dem, const Grid& grid) {
  if (dem.slope_deg == 0.0) return 0.0;
  return 1.5 * (settled_height_m(dem) + grid.extent_x_m() * std::tan(dem.slope_deg / kDeg));
}

ChuteFlow window_flow(const GrainSet& grains, const ChuteGeometry& geometry, const ChuteImpactOptions& options) {
  if (grains.size() > 0 && grains.velocity_m_s.rows() != grains.size()) {
    throw InputError("chute impact: the grains have no velocities (a dump without vx vy vz?)");
  }
  ChuteFlow flow;
  double mass = 0.0, momentum = 0.0;
  std::vector<double> tops;
  for (Eigen::Index k = 0; k < grains.size(); ++k) {
    const double x = grains.position_m(k, 0);
    if (x < geometry.window_x_min_m || x > geometry.window_x_max_m) continue;
    const double r = grains.radius_m(k);
    const double m = geometry.density_kg_m3 * 4.0 / 3.0 * std::numbers::pi * r * r * r;
    mass += m;
    momentum += m * grains.velocity_m_s(k, 0);
    tops.push_back(grains.position_m(k, 2) + r);
  }
  flow.grains = static_cast<long>(tops.size());
  if (tops.empty()) return flow;
  flow.mass_per_area_kg_m2 = mass / ((geometry.window_x_max_m - geometry.window_x_min_m) * geometry.width_m);
  flow.depth_m = quantile(std::move(tops), options.depth_quantile);
  flow.speed_m_s = momentum / mass;
  return flow;
}

double froude_number(double speed_m_s, double depth_m, double gravity_m_s2, double slope_rad) {
  REPOSE_DEMAND(depth_m > 0.0 && gravity_m_s2 > 0.0);
  return speed_m_s / std::sqrt(gravity_m_s2 * depth_m * std::cos(slope_rad));
}

double pressure_coefficient(double pressure_pa, double density_kg_m3, double speed_m_s) {
  REPOSE_DEMAND(density_kg_m3 > 0.0 && speed_m_s != 0.0);
  return pressure_pa / (density_kg_m3 * speed_m_s * speed_m_s);
}

double design_pressure_coefficient(double froude, double k, double alpha) {
  REPOSE_DEMAND(froude > 0.0);
  return alpha + k / (2.0 * froude * froude);
}

ChuteLoad chute_load(const ChuteGeometry& geometry, double time_s, double force_n, const ChuteFlow& flow) {
  ChuteLoad l;
  l.time_s = time_s;
  l.force_n = force_n;
  l.depth_m = flow.depth_m;
  l.speed_m_s = flow.speed_m_s;
  l.mass_per_area_kg_m2 = flow.mass_per_area_kg_m2;
  if (!(flow.depth_m > 0.0)) return l;
  l.bulk_density_kg_m3 = flow.mass_per_area_kg_m2 / flow.depth_m;
  l.pressure_pa = force_n / (geometry.width_m * flow.depth_m);
  l.froude = froude_number(flow.speed_m_s, flow.depth_m, geometry.gravity_m_s2, geometry.slope_rad);
  if (flow.speed_m_s != 0.0) l.coefficient = pressure_coefficient(l.pressure_pa, l.bulk_density_kg_m3, flow.speed_m_s);
  return l;
}

ChuteImpact measure_chute_impact(const ChuteGeometry& geometry, const std::vector<GrainSet>& frames,
                                 const std::vector<double>& frame_time_s, const std::vector<double>& force_time_s,
                                 const std::vector<double>& force_x_n, const ChuteImpactOptions& options) {
  if (frames.empty()) throw InputError("chute impact: no frames");
  if (force_time_s.empty()) throw InputError("chute impact: no force samples");
  REPOSE_DEMAND(frames.size() == frame_time_s.size() && force_time_s.size() == force_x_n.size());
  REPOSE_DEMAND(std::is_sorted(force_time_s.begin(), force_time_s.end()));
  ChuteImpact c;
  c.geometry = geometry;
  const double half = 0.5 * options.force_smoothing_s;
  const double reach_m = geometry.wall_face_x_m - 0.5 * (geometry.window_x_min_m + geometry.window_x_max_m);
  for (std::size_t k = 0; k < frames.size(); ++k) {
    ChuteFrame f;
    f.time_s = frame_time_s[k];
    f.flow = window_flow(frames[k], geometry, options);
    const double lag = f.flow.speed_m_s > 0.0 ? reach_m / f.flow.speed_m_s : 0.0;
    f.force_n = smoothed_at(force_time_s, force_x_n, f.time_s + lag, half);
    if (f.flow.grains > 0 && c.front_arrival_s < 0.0) c.front_arrival_s = f.time_s;
    c.frames.push_back(f);
  }
  if (c.front_arrival_s < 0.0) throw InputError("chute impact: no grain ever entered the window upstream of the wall");
  mark_impact_phase(c.frames, options);

  c.final_force_n = smoothed_at(force_time_s, force_x_n, force_time_s.back(), half);
  // the peak: the largest smoothed force while the flow arrives (from the
  // first impact frame to the last one's arrival at the wall), with the flow
  // of the last impact frame at or before it
  double first = -1.0, last = -1.0;
  for (const ChuteFrame& f : c.frames) {
    if (!f.impact) continue;
    if (first < 0.0) first = f.time_s;
    last = f.time_s + reach_m / f.flow.speed_m_s + half;
  }
  double peak_t = first, peak_f = -1.0;
  for (std::size_t k = 0; k < force_time_s.size() && first >= 0.0; ++k) {
    const double t = force_time_s[k];
    if (t < first || t > last) continue;
    const double f = smoothed_at(force_time_s, force_x_n, t, half);
    if (f > peak_f) peak_f = f, peak_t = t;
  }
  const ChuteFrame* before = nullptr;
  ChuteFlow sum;
  double force_sum = 0.0;
  for (const ChuteFrame& f : c.frames) {
    if (!f.impact) continue;
    if (before == nullptr || f.time_s <= peak_t) before = &f;
    ++c.impact_frame_count;
    force_sum += f.force_n;
    sum.mass_per_area_kg_m2 += f.flow.mass_per_area_kg_m2;
    sum.depth_m += f.flow.depth_m;
    sum.speed_m_s += f.flow.speed_m_s;
  }
  if (before != nullptr) c.peak = chute_load(geometry, peak_t, peak_f, before->flow);
  if (c.impact_frame_count > 0) {
    const double n = static_cast<double>(c.impact_frame_count);
    ChuteFlow mean{0, sum.mass_per_area_kg_m2 / n, sum.depth_m / n, sum.speed_m_s / n};
    c.mean = chute_load(geometry, 0.0, force_sum / n, mean);
  }
  return c;
}

void write_chute_impact_csv(const std::string& path, const ChuteImpact& impact) {
  std::ofstream out(path);
  if (!out) throw InputError(fmt::format("{}: cannot write", path));
  out << "time_s,grains,mass_per_area_kg_m2,depth_m,speed_m_s,force_n,pressure_pa,froude,coefficient,impact\n";
  for (const ChuteFrame& f : impact.frames) {
    const ChuteLoad l = chute_load(impact.geometry, f.time_s, f.force_n, f.flow);
    out << fmt::format("{},{},{},{},{},{},{},{},{},{}\n", f.time_s, f.flow.grains, l.mass_per_area_kg_m2, l.depth_m,
                       l.speed_m_s, l.force_n, l.pressure_pa, l.froude, l.coefficient, f.impact ? 1 : 0);
  }
  if (!out) throw InputError(fmt::format("{}: write failed", path));
}

namespace {

nlohmann::json load_json(const ChuteLoad& l) {
  return {{"time_s", l.time_s},
          {"force_n", l.force_n},
          {"depth_m", l.depth_m},
          {"speed_m_s", l.speed_m_s},
          {"mass_per_area_kg_m2", l.mass_per_area_kg_m2},
          {"bulk_density_kg_m3", l.bulk_density_kg_m3},
          {"pressure_pa", l.pressure_pa},
          {"froude", l.froude},
          {"coefficient", l.coefficient}};
}

}  // namespace

nlohmann::json chute_results_json(const std::optional<ChuteImpact>& impact) {
  nlohmann::json json = nlohmann::json::object();
  if (!impact) return json;
  const ChuteImpact& c = *impact;
  json["chute"] = {{"slope_deg", c.geometry.slope_rad * kDeg},
                   {"width_m", c.geometry.width_m},
                   {"wall_face_x_m", c.geometry.wall_face_x_m},
                   {"window_x_min_m", c.geometry.window_x_min_m},
                   {"window_x_max_m", c.geometry.window_x_max_m},
                   {"front_arrival_s", c.front_arrival_s},
                   {"impact_frame_count", c.impact_frame_count},
                   {"final_force_n", c.final_force_n},
                   {"peak", load_json(c.peak)},
                   {"mean", load_json(c.mean)}};
  return json;
}

}  // namespace repose
