#include "models/ground/bearing_sinkage.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "models/core/base/error.h"

namespace repose {

namespace {

// The lowest covered underside; +inf when nothing is covered.
double lowest_underside(const DepthImage& u) {
  double lo = std::numeric_limits<double>::infinity();
  for (int j = 0; j < u.grid.ny; ++j) {
    for (int i = 0; i < u.grid.nx; ++i) {
      if (u.is_covered(i, j)) lo = std::min(lo, u.z(i, j));
    }
  }
  return lo;
}

}  // namespace

ContactPatch patch_below(const DepthImage& u, double level_m) {
  REPOSE_DEMAND(u.view == ViewFrom::kBelow);
  const double h = u.grid.cell_size_m;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  Eigen::Matrix2d second = Eigen::Matrix2d::Zero();
  ContactPatch p;
  for (int j = 0; j < u.grid.ny; ++j) {
    for (int i = 0; i < u.grid.nx; ++i) {
      if (!u.is_covered(i, j) || u.z(i, j) > level_m) continue;
      const Eigen::Vector2d c((i + 0.5) * h, (j + 0.5) * h);  // relative to the image's origin: no cancellation
      sum += c;
      second += c * c.transpose();
      ++p.cells;
    }
  }
  if (p.cells == 0) return p;
  p.area_m2 = p.cells * h * h;
  const Eigen::Vector2d mean = sum / p.cells;
  // each cell a uniform square: its own second moment h^2/12 on each axis
  const Eigen::Matrix2d covariance =
      second / p.cells - mean * mean.transpose() + Eigen::Matrix2d::Identity() * (h * h / 12.0);
  const double lambda_min = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(covariance).eigenvalues().minCoeff();
  p.width_m = std::max(h, std::sqrt(12.0 * std::max(lambda_min, 0.0)));
  return p;
}

double bearing_sinkage_m(const BekkerBearing& bearing, const DepthImage& underside, double height_m, double load_n) {
  REPOSE_DEMAND(load_n >= 0.0 && height_m >= 0.0);
  if (bearing.law == BekkerBearing::Law::kOff || load_n == 0.0) return 0.0;
  const double lowest = lowest_underside(underside);
  if (!std::isfinite(lowest)) return 0.0;
  // excess(z) = Bekker's sinkage under the mean pressure at z, minus z: decreasing in z
  auto excess = [&](double z) {
    const ContactPatch p = patch_below(underside, lowest + z);
    return bekker_sinkage_m(bearing, load_n / p.area_m2, p.width_m) - z;
  };
  if (excess(height_m) >= 0.0) return height_m;
  double below = 0.0, above = height_m;  // excess(below) > 0 >= excess(above) (excess(0) > 0: the load is positive)
  for (int k = 0; k < 60 && above - below > 1e-12; ++k) {
    const double mid = 0.5 * (below + above);
    (excess(mid) > 0.0 ? below : above) = mid;
  }
  return above;
}

double bearing_load_n(const BekkerBearing& bearing, const DepthImage& underside, double sinkage_m) {
  REPOSE_DEMAND(sinkage_m >= 0.0);
  const double lowest = lowest_underside(underside);
  if (bearing.law == BekkerBearing::Law::kOff || !std::isfinite(lowest) || sinkage_m == 0.0) return 0.0;
  const ContactPatch p = patch_below(underside, lowest + sinkage_m);
  return bekker_pressure_pa(bearing, sinkage_m, p.width_m) * p.area_m2;
}

double impact_sinkage_m(const BekkerBearing& bearing, const DepthImage& underside, double height_m, double from_m,
                        double weight_n, double energy_j) {
  REPOSE_DEMAND(height_m >= 0.0 && weight_n >= 0.0 && energy_j >= 0.0);
  from_m = std::clamp(from_m, 0.0, height_m);
  if (bearing.law == BekkerBearing::Law::kOff || energy_j == 0.0) return from_m;
  // the weight is borne quasi-statically down to its static sinkage (the static rule's share)
  from_m = std::max(from_m, bearing_sinkage_m(bearing, underside, height_m, weight_n));
  // march down in steps of a 512th of the body's height, the work of the
  // ground's load less the weight's by the trapezoid rule, until it has taken the energy
  const double dz = height_m / 512.0;
  double z = from_m, left = energy_j;
  double net = bearing_load_n(bearing, underside, z) - weight_n;
  while (z < height_m) {
    const double step = std::min(dz, height_m - z);
    const double next_net = bearing_load_n(bearing, underside, z + step) - weight_n;
    const double work = 0.5 * (net + next_net) * step;
    if (work >= left && work > 0.0) return z + step * left / work;  // linear within the step
    left -= work;
    z += step;
    net = next_net;
  }
  return height_m;
}

}  // namespace repose
