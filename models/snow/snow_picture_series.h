#pragma once
// The pictures and animation frames of one snow run (SnowPictureOptions),
// written as PNG while it runs: pictures/snow_t<time>s.png at the chosen
// times and frames/frame_NNNN.png from t = 0 to the end. A picture or frame
// due at time t shows the first state at or after t (the end of the step
// that reaches it; t = 0: the bare scene before any snow).

#include <string>
#include <vector>

#include "models/snow/snow_picture.h"

namespace repose {

class SnowPictureSeries {
 public:
  // Creates dir/pictures and dir/frames as needed; nothing when the options draw nothing.
  SnowPictureSeries(const SnowModel& model, double snowfall_scale, const std::string& dir);

  // Draws every picture and frame due by state.time_s (call with the
  // initial state, then after every step).
  void on_state(const SnowState& state);

  // Files written, relative to dir, in the order written.
  const std::vector<std::string>& files() const { return files_; }

 private:
  struct Due {
    double time_s;
    std::string file;
  };
  std::vector<Due> due_;  // by time; the next one first
  std::size_t next_ = 0;
  std::string dir_;
  double tolerance_s_;  // a millionth of a step: steps add up with round-off
  std::unique_ptr<SnowPictureRenderer> renderer_;
  std::vector<std::string> files_;
};

}  // namespace repose
