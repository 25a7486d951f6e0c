#include "models/snow/snow_picture_series.h"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

namespace repose {

SnowPictureSeries::SnowPictureSeries(const SnowModel& model, double snowfall_scale, const std::string& dir)
    : dir_(dir), tolerance_s_(1e-6 * model.time.step_s) {
  const SnowPictureOptions& o = model.options.pictures;
  validate(o);
  validate_picture_times(o, model.time.duration_s);
  for (const double t : o.times_s) due_.push_back({t, fmt::format("pictures/snow_t{:09.3f}s.png", t)});
  const std::vector<double> frames = frame_times_s(o, model.time.duration_s);
  for (std::size_t k = 0; k < frames.size(); ++k) due_.push_back({frames[k], fmt::format("frames/frame_{:04d}.png", k)});
  std::stable_sort(due_.begin(), due_.end(), [](const Due& a, const Due& b) { return a.time_s < b.time_s; });
  if (due_.empty()) return;
  if (!o.times_s.empty()) std::filesystem::create_directories(std::filesystem::path(dir) / "pictures");
  if (!frames.empty()) std::filesystem::create_directories(std::filesystem::path(dir) / "frames");
  renderer_ = std::make_unique<SnowPictureRenderer>(model, o, snow_picture_top_m(model, snowfall_scale));
}

void SnowPictureSeries::on_state(const SnowState& state) {
  const double reached = state.time_s + tolerance_s_;
  if (next_ >= due_.size() || due_[next_].time_s > reached) return;
  const RgbImage image = renderer_->render(state);
  for (; next_ < due_.size() && due_[next_].time_s <= reached; ++next_) {
    write_png_rgb((std::filesystem::path(dir_) / due_[next_].file).string(), image);
    files_.push_back(due_[next_].file);
  }
}

}  // namespace repose
