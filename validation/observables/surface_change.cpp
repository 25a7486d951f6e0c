#include "validation/observables/surface_change.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <tuple>

#include "models/core/base/error.h"
#include "validation/observables/calibration_observables.h"

namespace repose {

namespace {

// Δh over the region's cells, row-major order.
std::vector<double> change_in(const HeightField& initial, const HeightField& final_height,
                              const std::vector<std::size_t>& cells) {
  REPOSE_DEMAND(initial.grid() == final_height.grid());
  std::vector<double> dh;
  dh.reserve(cells.size());
  for (const std::size_t c : cells) dh.push_back(final_height.heights().data()[c] - initial.heights().data()[c]);
  return dh;
}

double rms(const std::vector<double>& v) {
  double sum = 0.0;
  for (const double x : v) sum += x * x;
  return std::sqrt(sum / static_cast<double>(v.size()));
}

// RMSE and R² of `model` against `reference` (values on the same cells).
std::pair<double, double> rmse_and_r2(const std::vector<double>& model, const std::vector<double>& reference) {
  REPOSE_DEMAND(model.size() == reference.size() && !model.empty());
  double mean = 0.0;
  for (const double r : reference) mean += r;
  mean /= static_cast<double>(reference.size());
  double ss_res = 0.0, ss_tot = 0.0;
  for (std::size_t k = 0; k < model.size(); ++k) {
    ss_res += (model[k] - reference[k]) * (model[k] - reference[k]);
    ss_tot += (reference[k] - mean) * (reference[k] - mean);
  }
  const double rmse = std::sqrt(ss_res / static_cast<double>(model.size()));
  // a reference that does not change: R² is 1 for a model that does not either, else undefined (reported as 0)
  const double r2 = ss_tot > 0.0 ? 1.0 - ss_res / ss_tot : (ss_res == 0.0 ? 1.0 : 0.0);
  return {rmse, r2};
}

// Contiguous cells from (i, j) stepping by (di, dj) while `inside` holds.
int run_length(int i, int j, int di, int dj, const std::function<bool(int, int)>& inside) {
  int n = 0;
  for (int a = i + di, b = j + dj; inside(a, b); a += di, b += dj) ++n;
  return n;
}

// The narrower of the runs of cells dug deeper than half the depth along x
// and along y through the cell holding the imprint's centre (0 when that cell
// is not itself dug that deep: a curved trench).
double width_across(const HeightField& initial, const HeightField& final_height, const std::vector<char>& in_region,
                    const ChangeFeatures& f) {
  const Grid& g = initial.grid();
  const int i0 = static_cast<int>(std::floor((f.depth_x_m - g.origin_x_m) / g.cell_size_m));
  const int j0 = static_cast<int>(std::floor((f.depth_y_m - g.origin_y_m) / g.cell_size_m));
  const auto dug_deep = [&](int i, int j) {
    if (!g.contains(i, j) || !in_region[static_cast<std::size_t>(j) * g.nx + i]) return false;
    return final_height.at(i, j) - initial.at(i, j) < -0.5 * f.depth_m;
  };
  if (!dug_deep(i0, j0)) return 0.0;
  const int across_y = 1 + run_length(i0, j0, 0, 1, dug_deep) + run_length(i0, j0, 0, -1, dug_deep);
  const int across_x = 1 + run_length(i0, j0, 1, 0, dug_deep) + run_length(i0, j0, -1, 0, dug_deep);
  return std::min(across_x, across_y) * g.cell_size_m;
}

}  // namespace

ChangeScores score_change(const HeightField& initial, const HeightField& model_final, const HeightField& reference_final,
                          const std::optional<CalibrationRegion>& region) {
  const auto cells = cells_in(region, initial.grid());
  const std::vector<double> model = change_in(initial, model_final, cells);
  const std::vector<double> reference = change_in(initial, reference_final, cells);
  ChangeScores s;
  std::tie(s.rmse_m, s.r2) = rmse_and_r2(model, reference);
  s.rmse_nothing_m = rms(reference);
  s.skill = s.rmse_nothing_m > 0.0 ? 1.0 - s.rmse_m / s.rmse_nothing_m : 0.0;
  return s;
}

std::optional<NoiseFloor> noise_floor(const std::vector<HeightField>& initial, const std::vector<HeightField>& final_height,
                                      const std::optional<CalibrationRegion>& region) {
  REPOSE_DEMAND(initial.size() == final_height.size());
  const std::size_t n = initial.size();
  if (n < 2) return std::nullopt;
  const auto cells = cells_in(region, initial.front().grid());
  std::vector<std::vector<double>> dh;
  for (std::size_t s = 0; s < n; ++s) dh.push_back(change_in(initial[s], final_height[s], cells));
  NoiseFloor floor;
  floor.seeds = static_cast<int>(n);
  for (std::size_t s = 0; s < n; ++s) {
    std::vector<double> others(cells.size(), 0.0);
    for (std::size_t t = 0; t < n; ++t) {
      if (t == s) continue;
      for (std::size_t c = 0; c < cells.size(); ++c) others[c] += dh[t][c] / static_cast<double>(n - 1);
    }
    const auto [rmse, r2] = rmse_and_r2(dh[s], others);
    floor.rmse_m += rmse / static_cast<double>(n);
    floor.r2 += r2 / static_cast<double>(n);
  }
  int pairs = 0;
  for (std::size_t s = 0; s < n; ++s) {
    for (std::size_t t = s + 1; t < n; ++t) {
      floor.pair_rmse_m += rmse_and_r2(dh[s], dh[t]).first;
      ++pairs;
    }
  }
  floor.pair_rmse_m /= pairs;
  return floor;
}

ChangeFeatures change_features(const HeightField& initial, const HeightField& final_height,
                               const std::optional<CalibrationRegion>& region) {
  const Grid& g = initial.grid();
  const auto cells = cells_in(region, g);
  const std::vector<double> dh = change_in(initial, final_height, cells);
  std::vector<char> in_region(static_cast<std::size_t>(g.nx) * g.ny, 0);
  for (const std::size_t c : cells) in_region[c] = 1;
  ChangeFeatures f;
  const double area = g.cell_size_m * g.cell_size_m;
  std::size_t deepest = 0, highest = 0;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    (dh[k] < 0 ? f.dug_m3 : f.heaped_m3) += std::abs(dh[k]) * area;
    if (dh[k] < dh[deepest]) deepest = k;
    if (dh[k] > dh[highest]) highest = k;
  }
  const auto centre = [&](std::size_t k, double* x, double* y) {
    const int i = static_cast<int>(cells[k] % g.nx), j = static_cast<int>(cells[k] / g.nx);
    *x = g.centre_x(i);
    *y = g.centre_y(j);
  };
  f.depth_m = std::max(0.0, -dh[deepest]);
  f.height_m = std::max(0.0, dh[highest]);
  centre(highest, &f.height_x_m, &f.height_y_m);
  centre(deepest, &f.depth_x_m, &f.depth_y_m);
  if (f.depth_m > 0.0) {
    // the imprint's centre: the depth-weighted centroid of the cells dug
    // deeper than half the depth (a flat-bottomed imprint has no single deepest cell)
    double w = 0.0, x = 0.0, y = 0.0;
    for (std::size_t k = 0; k < cells.size(); ++k) {
      if (dh[k] >= -0.5 * f.depth_m) continue;
      double cx = 0.0, cy = 0.0;
      centre(k, &cx, &cy);
      w += -dh[k];
      x += -dh[k] * cx;
      y += -dh[k] * cy;
    }
    f.depth_x_m = x / w;
    f.depth_y_m = y / w;
    f.trench_width_m = width_across(initial, final_height, in_region, f);
  }
  f.rim_distance_m = std::hypot(f.height_x_m - f.depth_x_m, f.height_y_m - f.depth_y_m);
  return f;
}

HeightField mean_field(const std::vector<HeightField>& fields) {
  REPOSE_DEMAND(!fields.empty());
  ArrayXXdR sum = ArrayXXdR::Zero(fields.front().grid().ny, fields.front().grid().nx);
  for (const HeightField& f : fields) {
    REPOSE_DEMAND(f.grid() == fields.front().grid());
    sum += f.heights();
  }
  return HeightField(fields.front().grid(), sum / static_cast<double>(fields.size()));
}

}  // namespace repose
