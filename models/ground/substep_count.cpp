#include "models/ground/substep_count.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/ground/ground_model.h"

namespace repose {

namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

[[noreturn]] void refuse_angle(const GroundModel& model, std::size_t object, double angle_rad, double count,
                               int step_index) {
  const double t0 = step_index * model.time.step_s;
  throw InputError(fmt::format(
      "ground_model.max_substep_angle_deg = {:g}: object '{}' turns {:g} deg in step {} ({:g} s to {:g} s), "
      "which needs {:.3g} substeps; at most {} per step are allowed (raise max_substep_angle_deg or shorten "
      "time.step_s)",
      model.options.max_substep_angle_rad * kDegPerRad, model.objects[object].name, angle_rad * kDegPerRad,
      step_index, t0, t0 + model.time.step_s, count, kMaxSubstepsPerStep));
}

}  // namespace

int substep_count(const GroundModel& model, const std::vector<Pose>& from, const std::vector<Pose>& to,
                  int step_index) {
  const int fixed = model.options.sweep ? 1 : model.options.substeps;
  if (fixed > kMaxSubstepsPerStep) {
    throw InputError(fmt::format("ground_model.substeps = {}: at most {} are allowed", fixed, kMaxSubstepsPerStep));
  }
  int n = fixed;
  for (std::size_t o = 0; o < from.size(); ++o) {
    const double angle = from[o].orientation.angularDistance(to[o].orientation);
    // in floating point first: the quotient can be anything up to +inf (or NaN for a bad option)
    const double count = std::ceil(angle / model.options.max_substep_angle_rad - 1e-9);
    if (!(count <= kMaxSubstepsPerStep)) refuse_angle(model, o, angle, count, step_index);
    n = std::max(n, static_cast<int>(count));
  }
  return n;
}

void check_counts(const GroundModel& model) {
  const int cells = std::max(model.grid.nx, model.grid.ny);
  if (model.options.coarse_factor > cells) {
    throw InputError(fmt::format("ground_model.coarse_factor = {}: at most the grid's {} cells along its longer side",
                                 model.options.coarse_factor, cells));
  }
  const int steps = model.time.step_count();
  std::vector<Pose> from(model.objects.size()), to(model.objects.size());
  for (std::size_t o = 0; o < model.objects.size(); ++o) from[o] = model.objects[o].pose_at(0.0);
  double total = 0.0;
  for (int s = 0; s < steps; ++s) {
    const double t0 = s * model.time.step_s;  // as step() computes it
    for (std::size_t o = 0; o < model.objects.size(); ++o) to[o] = model.objects[o].pose_at(t0 + model.time.step_s);
    total += substep_count(model, from, to, s);
    std::swap(from, to);
  }
  if (total > kMaxSubstepsPerRun) {
    throw InputError(fmt::format(
        "ground_model: the run needs {:.0f} substeps in all (substeps = {}, max_substep_angle_deg = {:g}); at "
        "most {:.0f} are allowed",
        total, model.options.substeps, model.options.max_substep_angle_rad * kDegPerRad, kMaxSubstepsPerRun));
  }
}

}  // namespace repose
