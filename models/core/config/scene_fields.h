#pragma once
// The field lists of the common scene's small maps (time, camera), shared by
// the loader and the writer (fields.h), and the limits that keep a typo from
// exhausting memory or time.

#include <cstdint>

#include "models/core/config/fields.h"
#include "models/core/config/scene.h"

namespace repose {

inline constexpr std::int64_t kMaxCellsPerSide = 16384;
inline constexpr double kMaxCells = 67108864.0;  // 2^26
inline constexpr double kMaxSteps = 1.0e7;
// Figures render at supersample 2 off screen, whose limit is 16384 px; 4096 px
// keeps the render within about 1 GB.
inline constexpr std::int64_t kMaxCameraPx = 4096;
// Lengths and coordinates stay within 1000 km, so that products of them stay
// finite in every model downstream.
inline constexpr double kMaxLength_m = 1.0e6;
inline const Range kLength = Range::left_open(0.0, kMaxLength_m);        // a size > 0
inline const Range kCoordinate = Range::closed(-kMaxLength_m, kMaxLength_m);
inline const Range kHeight = Range::closed(0.0, kMaxLength_m);           // an amount >= 0

template <class Visitor>
void time_fields(Visitor& v, TimeSpec& t) {
  v.number("step_s", t.step_s, Range::positive(), Need::kRequired);
  v.number("duration_s", t.duration_s, Range::positive(), Need::kRequired);
}

template <class Visitor>
void camera_fields(Visitor& v, CameraSpec& c) {
  v.vec3("position_m", c.position_m, kCoordinate);
  v.vec3("target_m", c.target_m, kCoordinate);
  v.vec3("up", c.up, Range::closed(-1.0, 1.0));
  v.angle_deg("fov_y_deg", c.fov_y_rad, Range::open(0.0, 180.0));
  v.integer("width_px", c.width_px, IntRange{1, kMaxCameraPx});
  v.integer("height_px", c.height_px, IntRange{1, kMaxCameraPx});
}

inline const auto kTimeFields = [](auto& v, TimeSpec& x) { time_fields(v, x); };
inline const auto kCameraFields = [](auto& v, CameraSpec& x) { camera_fields(v, x); };

}  // namespace repose
