#include "models/snow/snow_picture_options.h"

#include <cmath>

#include <fmt/format.h>

#include "models/core/config/fields.h"

namespace repose {

namespace {

void require(bool ok, const char* key, const char* expected, const std::string& got) {
  if (!ok) throw FieldError(key, expected, got);
}

}  // namespace

void validate(const SnowPictureOptions& o) {
  for (std::size_t k = 0; k < o.times_s.size(); ++k) {
    const double t = o.times_s[k];
    require(std::isfinite(t) && t >= 0.0, "picture_times_s", "times >= 0 s",
            fmt::format("{} at index {}", yaml_number(t), k));
    require(k == 0 || t > o.times_s[k - 1], "picture_times_s", "strictly increasing times",
            fmt::format("{} after {}", yaml_number(t), yaml_number(o.times_s[k == 0 ? 0 : k - 1])));
  }
  require(o.frame_count >= 0 && o.frame_count <= 10000, "frame_count", "an integer in [0, 10000]",
          std::to_string(o.frame_count));
  require(o.width_px >= 16 && o.width_px <= 4096, "picture_width_px", "an integer in [16, 4096]",
          std::to_string(o.width_px));
  require(o.height_px >= 16 && o.height_px <= 4096, "picture_height_px", "an integer in [16, 4096]",
          std::to_string(o.height_px));
  const double el = o.view_elevation_rad;
  require(std::isfinite(el) && el >= 5.0 * kRadPerDeg - 1e-12 && el <= 90.0 * kRadPerDeg + 1e-12,
          "view_elevation_deg", "an angle in [5, 90] deg", yaml_degrees(el / kRadPerDeg));
  require(std::isfinite(o.view_azimuth_rad), "view_azimuth_deg", "a finite angle",
          yaml_degrees(o.view_azimuth_rad / kRadPerDeg));
}

void validate_picture_times(const SnowPictureOptions& o, double duration_s) {
  if (!o.times_s.empty() && o.times_s.back() > duration_s * (1.0 + 1e-12)) {
    throw FieldError("picture_times_s", fmt::format("times within the run's duration, [0, {}] s", yaml_number(duration_s)),
                     yaml_number(o.times_s.back()));
  }
}

std::vector<double> frame_times_s(const SnowPictureOptions& o, double duration_s) {
  std::vector<double> times;
  if (o.frame_count == 1) return {duration_s};
  for (int k = 0; k < o.frame_count; ++k) times.push_back(duration_s * k / (o.frame_count - 1));
  return times;
}

}  // namespace repose
