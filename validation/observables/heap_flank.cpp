#include "validation/observables/heap_flank.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

// Bilinear value at fractional cell indices (fi, fj), cell centres at integers;
// nullopt when a corner would lie outside the grid.
std::optional<double> bilinear(const HeightField& h, double fi, double fj) {
  const int i0 = static_cast<int>(std::floor(fi)), j0 = static_cast<int>(std::floor(fj));
  const Grid& g = h.grid();
  if (i0 < 0 || j0 < 0 || i0 + 1 >= g.nx || j0 + 1 >= g.ny) return std::nullopt;
  const double u = fi - i0, v = fj - j0;
  return (1 - u) * (1 - v) * h.at(i0, j0) + u * (1 - v) * h.at(i0 + 1, j0) + (1 - u) * v * h.at(i0, j0 + 1) +
         u * v * h.at(i0 + 1, j0 + 1);
}

// atan(-slope) of the least-squares line z(s); nullopt for a degenerate set.
std::optional<double> fitted_angle(const std::vector<double>& s, const std::vector<double>& z) {
  const double n = static_cast<double>(s.size());
  double ms = 0.0, mz = 0.0;
  for (std::size_t k = 0; k < s.size(); ++k) ms += s[k] / n, mz += z[k] / n;
  double sxx = 0.0, sxz = 0.0;
  for (std::size_t k = 0; k < s.size(); ++k) sxx += (s[k] - ms) * (s[k] - ms), sxz += (s[k] - ms) * (z[k] - mz);
  if (!(sxx > 0.0)) return std::nullopt;
  return std::atan(-sxz / sxx);
}

// The highest cell whose centre lies in the region: (i, j).
std::pair<int, int> peak_cell(const HeightField& h, const std::optional<CalibrationRegion>& region) {
  const Grid& g = h.grid();
  double best = -std::numeric_limits<double>::infinity();
  std::pair<int, int> at{-1, -1};
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      if (region && !region->contains(g.centre_x(i), g.centre_y(j))) continue;
      if (h.at(i, j) > best) best = h.at(i, j), at = {i, j};
    }
  }
  if (at.first < 0) throw InputError("heap flank: its peak region holds no cell centre of the grid");
  return at;
}

}  // namespace

void HeapFlankOptions::validate() const {
  if (!std::isfinite(base_height_m)) throw InputError(fmt::format("heap flank: base_height_m: expected a finite height, got {}", base_height_m));
  if (!(reach_m > 0.0)) throw InputError(fmt::format("heap flank: reach_m: expected a positive distance, got {}", reach_m));
  if (ray_count < 1) throw InputError(fmt::format("heap flank: ray_count: expected >= 1, got {}", ray_count));
  if (!(lower_fraction >= 0.0 && lower_fraction < upper_fraction)) {
    throw InputError(fmt::format("heap flank: lower_fraction: expected 0 <= lower_fraction < upper_fraction ({}), got {}",
                                 upper_fraction, lower_fraction));
  }
  if (min_samples < 2) throw InputError(fmt::format("heap flank: min_samples: expected >= 2, got {}", min_samples));
}

HeightField median3(const HeightField& h) {
  const Grid& g = h.grid();
  HeightField out(g);
  std::vector<double> window;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      window.clear();
      for (int dj = -1; dj <= 1; ++dj) {
        for (int di = -1; di <= 1; ++di) {
          const int a = i + di, b = j + dj;
          if (a >= 0 && b >= 0 && a < g.nx && b < g.ny) window.push_back(h.at(a, b));
        }
      }
      std::sort(window.begin(), window.end());
      const std::size_t n = window.size();
      out.at(i, j) = n % 2 == 1 ? window[n / 2] : 0.5 * (window[n / 2 - 1] + window[n / 2]);
    }
  }
  return out;
}

HeapFlank heap_flank(const HeightField& height, const HeapFlankOptions& o) {
  o.validate();
  HeightField above = height;
  above.heights().array() -= o.base_height_m;
  const HeightField h = median3(above);
  const auto [pi, pj] = peak_cell(h, o.peak_region);
  HeapFlank out;
  out.peak_height_m = h.at(pi, pj);
  const double cell = h.grid().cell_size_m, lo = o.lower_fraction * out.peak_height_m,
               hi = o.upper_fraction * out.peak_height_m;
  for (int a = 0; out.peak_height_m > 0.0 && a < o.ray_count; ++a) {
    const double azimuth = 2.0 * std::numbers::pi * a / o.ray_count;
    std::vector<double> s, z;
    for (int k = 0;; ++k) {
      const double d = k * 0.5 * cell;
      if (!(d < o.reach_m)) break;
      const auto v = bilinear(h, pi + d * std::cos(azimuth) / cell, pj + d * std::sin(azimuth) / cell);
      if (!v) break;
      if (*v >= lo && *v <= hi) s.push_back(d), z.push_back(*v);
    }
    if (static_cast<int>(s.size()) < o.min_samples) continue;
    if (const auto angle = fitted_angle(s, z)) out.angle_rad.push_back(*angle);
  }
  for (const double a : out.angle_rad) out.mean_rad += a / static_cast<double>(out.angle_rad.size());
  return out;
}

}  // namespace repose
