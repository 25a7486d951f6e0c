#include "validation/particles/particle_observables.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

double sphere_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

// (distance, height) samples on one ray with height in [lo, hi].
void flank_samples(const HeightField& height, const Eigen::Vector2d& centre, double azimuth, double lo, double hi,
                   std::vector<double>* s, std::vector<double>* z) {
  const Grid& g = height.grid();
  const double step = 0.5 * g.cell_size_m;
  const Eigen::Vector2d dir(std::cos(azimuth), std::sin(azimuth));
  for (double d = 0.0;; d += step) {
    const Eigen::Vector2d p = centre + d * dir;
    if (p.x() < g.origin_x_m || p.y() < g.origin_y_m || p.x() > g.origin_x_m + g.extent_x_m() ||
        p.y() > g.origin_y_m + g.extent_y_m()) {
      return;
    }
    const double h = height.sample(p.x(), p.y());
    if (h >= lo && h <= hi) {
      s->push_back(d);
      z->push_back(h);
    }
  }
}

double peak_on_rays(const HeightField& height, const Eigen::Vector2d& centre, const FlankAngleOptions& o) {
  double peak = -std::numeric_limits<double>::infinity();
  for (int a = 0; a < o.azimuth_count; ++a) {
    std::vector<double> s, z;
    flank_samples(height, centre, 2 * std::numbers::pi * a / o.azimuth_count,
                  -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), &s, &z);
    for (double h : z) peak = std::max(peak, h);
  }
  return peak;
}

// (centre distance, radius) pairs -> the deposit front (see deposit_front_m).
double front_of(std::vector<std::pair<double, double>> d, double max_gap_m) {
  REPOSE_DEMAND(!d.empty());
  std::sort(d.begin(), d.end());
  double front = d.front().first + d.front().second;
  for (std::size_t k = 0; k < d.size(); ++k) {
    if (k > 0 && d[k].first - d[k - 1].first > max_gap_m) break;
    front = std::max(front, d[k].first + d[k].second);
  }
  return front;
}

void require_front_inputs(const GrainSet& grains, double max_gap_m) {
  if (grains.size() == 0) throw InputError("deposit front: no grains");
  if (!(std::isfinite(max_gap_m) && max_gap_m > 0.0)) {
    throw InputError(fmt::format("deposit front: max_gap_m: expected a positive number, got {}", max_gap_m));
  }
}

}  // namespace

double deposit_front_m(const GrainSet& grains, const Eigen::Vector3d& origin_m, const Eigen::Vector3d& direction,
                       double max_gap_m) {
  require_front_inputs(grains, max_gap_m);
  REPOSE_DEMAND(direction.norm() > 0.0);
  const Eigen::Vector3d u = direction.normalized();
  std::vector<std::pair<double, double>> d;
  d.reserve(static_cast<std::size_t>(grains.size()));
  for (Eigen::Index g = 0; g < grains.size(); ++g) {
    d.emplace_back((grains.position_m.row(g).transpose() - origin_m).dot(u), grains.radius_m[g]);
  }
  return front_of(std::move(d), max_gap_m);
}

RadialFront radial_deposit_front(const GrainSet& grains, const Eigen::Vector2d& axis_xy_m, double max_gap_m,
                                 int sector_count, const AzimuthRange& range) {
  require_front_inputs(grains, max_gap_m);
  REPOSE_DEMAND(sector_count >= 1 && range.span_rad > 0.0 && range.span_rad <= 2.0 * std::numbers::pi);
  std::vector<std::vector<std::pair<double, double>>> sectors(static_cast<std::size_t>(sector_count));
  for (Eigen::Index g = 0; g < grains.size(); ++g) {
    const Eigen::Vector2d v(grains.position_m(g, 0) - axis_xy_m.x(), grains.position_m(g, 1) - axis_xy_m.y());
    const double azimuth = std::atan2(v.y(), v.x()) - range.begin_rad;
    const int k = std::clamp(static_cast<int>(std::floor(azimuth / range.span_rad * sector_count)), 0, sector_count - 1);
    sectors[static_cast<std::size_t>(k)].emplace_back(v.norm(), grains.radius_m[g]);
  }
  RadialFront out;
  for (auto& sector : sectors) {
    if (!sector.empty()) out.sector_front_m.push_back(front_of(std::move(sector), max_gap_m));
  }
  const double n = static_cast<double>(out.sector_front_m.size());
  for (double f : out.sector_front_m) out.mean_m += f / n;
  double var = 0.0;
  for (double f : out.sector_front_m) var += (f - out.mean_m) * (f - out.mean_m);
  out.std_m = n > 1 ? std::sqrt(var / (n - 1)) : 0.0;
  return out;
}

double grain_top_m(const GrainSet& grains) {
  if (grains.size() == 0) throw InputError("grain top: no grains");
  return (grains.position_m.col(2) + grains.radius_m).maxCoeff();
}

HeightField material_per_area(const GrainSet& grains, const Grid& grid) {
  HeightField out(grid, 0.0);
  const double inv_area = 1.0 / grid.cell_area_m2();
  for (Eigen::Index g = 0; g < grains.size(); ++g) {
    const int i = static_cast<int>(std::floor((grains.position_m(g, 0) - grid.origin_x_m) / grid.cell_size_m));
    const int j = static_cast<int>(std::floor((grains.position_m(g, 1) - grid.origin_y_m) / grid.cell_size_m));
    if (grid.contains(i, j)) out.at(i, j) += sphere_volume(grains.radius_m[g]) * inv_area;
  }
  return out;
}

HeightField equivalent_height(const GrainSet& grains, const Grid& grid, double packing_fraction) {
  if (!(packing_fraction > 0.0 && packing_fraction <= 1.0)) {
    throw InputError(fmt::format("packing_fraction: expected a value in (0, 1], got {}", packing_fraction));
  }
  HeightField out = material_per_area(grains, grid);
  out.heights() /= packing_fraction;
  return out;
}

double grain_volume_m3(const GrainSet& grains) {
  double v = 0.0;
  for (Eigen::Index g = 0; g < grains.size(); ++g) v += sphere_volume(grains.radius_m[g]);
  return v;
}

double mass_in_box_kg(const GrainSet& grains, const Aabb& box, double density_kg_m3) {
  double v = 0.0;
  for (Eigen::Index g = 0; g < grains.size(); ++g) {
    const Eigen::Vector3d p = grains.position_m.row(g).transpose();
    if ((p.array() >= box.min.array()).all() && (p.array() <= box.max.array()).all()) {
      v += sphere_volume(grains.radius_m[g]);
    }
  }
  return v * density_kg_m3;
}

namespace {

// Solid angle of triangle (a, b, c) seen from the origin (Van Oosterom & Strackee), signed.
double solid_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double la = a.norm(), lb = b.norm(), lc = c.norm();
  const double numerator = a.dot(b.cross(c));
  const double denominator = la * lb * lc + a.dot(b) * lc + b.dot(c) * la + c.dot(a) * lb;
  return 2.0 * std::atan2(numerator, denominator);
}

double winding_number(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  double w = 0.0;
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    w += solid_angle(mesh.V.row(mesh.F(f, 0)).transpose() - p, mesh.V.row(mesh.F(f, 1)).transpose() - p,
                     mesh.V.row(mesh.F(f, 2)).transpose() - p);
  }
  return w / (4.0 * std::numbers::pi);
}

// Does the downward vertical ray from p meet an upward-facing face at or below p.z?
bool above_upward_face(const TriangleMesh& mesh, const Eigen::Vector3d& p) {
  for (Eigen::Index f = 0; f < mesh.F.rows(); ++f) {
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)).transpose();
    const Eigen::Vector3d b = mesh.V.row(mesh.F(f, 1)).transpose();
    const Eigen::Vector3d c = mesh.V.row(mesh.F(f, 2)).transpose();
    const Eigen::Vector3d normal = (b - a).cross(c - a);  // outward, |normal| = 2 area
    if (!(normal.z() > 0.0)) continue;
    // barycentric coordinates of p's projection in the projected triangle (positive orientation: normal.z > 0)
    const double wa = (b.x() - p.x()) * (c.y() - p.y()) - (c.x() - p.x()) * (b.y() - p.y());
    const double wb = (c.x() - p.x()) * (a.y() - p.y()) - (a.x() - p.x()) * (c.y() - p.y());
    const double wc = (a.x() - p.x()) * (b.y() - p.y()) - (b.x() - p.x()) * (a.y() - p.y());
    if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;
    const double z = (wa * a.z() + wb * b.z() + wc * c.z()) / normal.z();
    if (z <= p.z()) return true;
  }
  return false;
}

}  // namespace

double mass_held_by_object_kg(const GrainSet& grains, const TriangleMesh& object_world, double density_kg_m3) {
  if (object_world.empty()) return 0.0;
  const Aabb box = bounding_box(object_world);
  double v = 0.0;
  for (Eigen::Index g = 0; g < grains.size(); ++g) {
    const Eigen::Vector3d p = grains.position_m.row(g).transpose();
    if (p.z() > box.max.z() || p.z() < box.min.z()) continue;  // neither inside nor below the rim and above a floor
    const bool inside_xy = p.x() >= box.min.x() && p.x() <= box.max.x() && p.y() >= box.min.y() && p.y() <= box.max.y();
    if (!inside_xy) continue;
    if (above_upward_face(object_world, p) || winding_number(object_world, p) > 0.5) v += sphere_volume(grains.radius_m[g]);
  }
  return v * density_kg_m3;
}

double front_position_m(const GrainSet& grains, const Eigen::Vector3d& origin_m, const Eigen::Vector3d& direction,
                        double quantile) {
  if (grains.size() == 0) throw InputError("front position: no grains");
  if (!(quantile >= 0.0 && quantile <= 1.0)) throw InputError(fmt::format("front quantile: expected [0, 1], got {}", quantile));
  REPOSE_DEMAND(direction.norm() > 0.0);
  const Eigen::Vector3d u = direction.normalized();
  std::vector<double> d(static_cast<std::size_t>(grains.size()));
  for (Eigen::Index g = 0; g < grains.size(); ++g) d[g] = (grains.position_m.row(g).transpose() - origin_m).dot(u);
  std::sort(d.begin(), d.end());
  // linear interpolation between order statistics (NumPy's default "linear")
  const double pos = quantile * static_cast<double>(d.size() - 1);
  const std::size_t k = static_cast<std::size_t>(std::floor(pos));
  const double t = pos - static_cast<double>(k);
  return k + 1 < d.size() ? (1 - t) * d[k] + t * d[k + 1] : d[k];
}

FlankAngles pile_flank_angles(const HeightField& height, const Eigen::Vector2d& centre_m,
                              const FlankAngleOptions& options) {
  REPOSE_DEMAND(options.azimuth_count >= 1 && options.min_samples >= 2);
  const double peak = peak_on_rays(height, centre_m, options);
  if (!(peak > 0.0)) throw InputError("pile flank angles: the height field has no pile (peak height <= 0)");
  FlankAngles out;
  for (int a = 0; a < options.azimuth_count; ++a) {
    const double azimuth = 2 * std::numbers::pi * a / options.azimuth_count;
    std::vector<double> s, z;
    flank_samples(height, centre_m, azimuth, options.lower_fraction * peak, options.upper_fraction * peak, &s, &z);
    if (static_cast<int>(s.size()) < options.min_samples) continue;
    const double n = static_cast<double>(s.size());
    double ms = 0, mz = 0;
    for (std::size_t k = 0; k < s.size(); ++k) ms += s[k] / n, mz += z[k] / n;
    double sxx = 0, sxz = 0;
    for (std::size_t k = 0; k < s.size(); ++k) sxx += (s[k] - ms) * (s[k] - ms), sxz += (s[k] - ms) * (z[k] - mz);
    if (sxx <= 0.0) continue;
    out.azimuth_rad.push_back(azimuth);
    out.angle_rad.push_back(std::atan(-sxz / sxx));
  }
  if (out.angle_rad.empty()) throw InputError("pile flank angles: no ray crosses a flank (is there a pile at the centre?)");
  const double n = static_cast<double>(out.angle_rad.size());
  for (double a : out.angle_rad) out.mean_rad += a / n;
  double var = 0.0;
  for (double a : out.angle_rad) var += (a - out.mean_rad) * (a - out.mean_rad);
  out.std_rad = n > 1 ? std::sqrt(var / (n - 1)) : 0.0;
  return out;
}

void write_field_csv(const std::string& path, const HeightField& field, const std::string& value_name) {
  std::ofstream out(path);
  if (!out) throw InputError(fmt::format("{}: cannot write", path));
  out << "x_m,y_m," << value_name << "\n";
  const Grid& g = field.grid();
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) out << fmt::format("{},{},{}\n", g.centre_x(i), g.centre_y(j), field.at(i, j));
  }
  if (!out) throw InputError(fmt::format("{}: write failed", path));
}

void write_flank_angles_csv(const std::string& path, const FlankAngles& angles) {
  std::ofstream out(path);
  if (!out) throw InputError(fmt::format("{}: cannot write", path));
  out << "azimuth_deg,angle_deg\n";
  constexpr double deg = 180.0 / std::numbers::pi;
  for (std::size_t k = 0; k < angles.angle_rad.size(); ++k) {
    out << fmt::format("{},{}\n", angles.azimuth_rad[k] * deg, angles.angle_rad[k] * deg);
  }
  if (!out) throw InputError(fmt::format("{}: write failed", path));
}

}  // namespace repose
