#pragma once
// When and how a snow run draws itself (figures only, no physics): pictures
// of the scene under snow at chosen times and an animation frame series, as
// the snow paper's Figs. 7-9 show its results (snow_picture.h draws them).
// Scene keys (snow_section.h) in brackets; nothing is drawn by default.

#include <vector>

namespace repose {

struct SnowPictureOptions {
  // A picture at each of these times (s), strictly increasing, each in
  // [0, the run's duration] (validate_picture_times). [picture_times_s]
  std::vector<double> times_s;
  // Animation frames spread evenly from t = 0 to the run's end (frame 0 the
  // bare scene, the last the end; one frame: the end). [0, 10000] [frame_count]
  int frame_count = 0;
  int width_px = 640;   // [16, 4096] [picture_width_px]
  int height_px = 480;  // [16, 4096] [picture_height_px]
  // The orthographic camera: its direction from the scene's centre, raised
  // this far above the horizontal, [5, 90] deg (90: straight down)
  // [view_elevation_deg] and turned this far from +x towards +y, finite
  // [view_azimuth_deg].
  double view_elevation_rad = 0.6108652381980153;  // 35 deg
  double view_azimuth_rad = -1.0471975511965976;   // -60 deg

  bool any() const { return !times_s.empty() || frame_count > 0; }
};

// Throws FieldError naming the scene key and its rule.
void validate(const SnowPictureOptions& options);
// The times against the run's duration: FieldError(picture_times_s) for a
// time after the end.
void validate_picture_times(const SnowPictureOptions& options, double duration_s);

// The times of the animation frames: frame_count times from 0 to duration_s.
std::vector<double> frame_times_s(const SnowPictureOptions& options, double duration_s);

}  // namespace repose
