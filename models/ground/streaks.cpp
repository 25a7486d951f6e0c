#include "models/ground/streaks.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace repose {

namespace {

// Ridges: local maxima with a prominence above the threshold.
int count_ridges(const std::vector<double>& z, double min_prominence_m) {
  int ridges = 0;
  const std::size_t n = z.size();
  for (std::size_t k = 1; k + 1 < n; ++k) {
    if (!(z[k] > z[k - 1] && z[k] >= z[k + 1])) continue;
    // lowest point on each side before a higher sample (or the profile's end)
    double left = z[k], right = z[k];
    bool left_bounded = false, right_bounded = false;
    for (std::size_t m = k; m-- > 0;) {
      if (z[m] > z[k]) break;
      left = std::min(left, z[m]);
      left_bounded = true;
    }
    for (std::size_t m = k + 1; m < n; ++m) {
      if (z[m] > z[k]) break;
      right = std::min(right, z[m]);
      right_bounded = true;
    }
    if (left_bounded && right_bounded && z[k] - std::max(left, right) > min_prominence_m) ++ridges;
  }
  return ridges;
}

}  // namespace

std::vector<double> height_along_path(const HeightField& final_height, const ObjectSpec& object,
                                      const TimeSpec& time) {
  const Grid& g = final_height.grid();
  const int steps = time.step_count();
  std::vector<Eigen::Vector2d> frames;
  for (int k = 0; k <= steps; ++k) frames.push_back(object.pose_at(k * time.step_s).position_m.head<2>());
  // the segments along which the object moves horizontally
  std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> segments;
  for (int k = 0; k < steps; ++k) {
    if ((frames[k + 1] - frames[k]).norm() > 1e-9 * g.cell_size_m) segments.emplace_back(frames[k], frames[k + 1]);
  }
  std::vector<double> profile;
  if (segments.size() < 3) return profile;
  const double spacing = 0.5 * g.cell_size_m;
  const double x_min = g.origin_x_m + 0.5 * g.cell_size_m, x_max = g.origin_x_m + (g.nx - 0.5) * g.cell_size_m;
  const double y_min = g.origin_y_m + 0.5 * g.cell_size_m, y_max = g.origin_y_m + (g.ny - 0.5) * g.cell_size_m;
  for (std::size_t s = 1; s + 1 < segments.size(); ++s) {
    const auto& [a, b] = segments[s];
    const int n = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing - 1e-9)));
    for (int k = 0; k < n; ++k) {  // the segment's end is the next one's start
      const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(k) / n);
      if (p.x() < x_min || p.x() > x_max || p.y() < y_min || p.y() > y_max) continue;
      profile.push_back(final_height.sample(p.x(), p.y()));
    }
  }
  return profile;
}

StreakStats streaks_along_path(const HeightField& final_height, const ObjectSpec& object, const TimeSpec& time,
                               double min_prominence_m) {
  const std::vector<double> z = height_along_path(final_height, object, time);
  StreakStats stats;
  stats.samples = static_cast<int>(z.size());
  if (z.empty()) return stats;
  double mean = 0.0;
  for (double v : z) mean += v / static_cast<double>(z.size());
  double sum_sq = 0.0;
  for (double v : z) sum_sq += (v - mean) * (v - mean);
  stats.rms_m = std::sqrt(sum_sq / static_cast<double>(z.size()));
  const auto [lo, hi] = std::minmax_element(z.begin(), z.end());
  stats.range_m = *hi - *lo;
  stats.ridges = count_ridges(z, min_prominence_m);
  return stats;
}

}  // namespace repose
