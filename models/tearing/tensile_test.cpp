#include "models/tearing/tensile_test.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "models/core/base/cpu_time.h"
#include "models/core/base/error.h"
#include "models/core/config/fields.h"
#include "models/tearing/explicit_integrator.h"
#include "models/tearing/sheet_state.h"
#include "models/tearing/stable_time_step.h"

namespace repose {

void TensileOptions::validate() const {
  if (!(std::isfinite(speed_m_per_s) && speed_m_per_s > 0.0)) {
    throw FieldError("speed_m_per_s", "a speed > 0 m/s", fmt::format("{}", speed_m_per_s));
  }
  if (!(time_step_fraction > 0.0 && time_step_fraction <= 1.0)) {
    throw FieldError("time_step_fraction", "a number in (0, 1]", fmt::format("{}", time_step_fraction));
  }
  if (!(std::isfinite(max_strain) && max_strain > 0.0)) {
    throw FieldError("max_strain", "a strain > 0", fmt::format("{}", max_strain));
  }
  if (!(stiffness_strain_fraction > 0.0 && stiffness_strain_fraction <= 1.0)) {
    throw FieldError("stiffness_strain_fraction", "a number in (0, 1]", fmt::format("{}", stiffness_strain_fraction));
  }
}

std::vector<GripSpec> tensile_grips(double width_m, double height_m, double cell_size_m, double speed_m_per_s) {
  GripSpec corner, left, right;
  corner.held_axes = {true, true, false};
  left.held_axes = right.held_axes = {true, false, false};
  left.x_min_m = left.x_max_m = 0.0;
  left.y_min_m = 0.5 * cell_size_m;  // above the corner vertex
  left.y_max_m = height_m;
  right.x_min_m = right.x_max_m = width_m;
  right.y_max_m = height_m;
  right.velocity_m_per_s = Eigen::Vector3d(speed_m_per_s, 0.0, 0.0);
  return {corner, left, right};
}

namespace {

void check_grips(const SheetModel& model, const TensileOptions& options) {
  const std::vector<GripSpec> expected = tensile_grips(model.spec.width_m, model.spec.height_m, model.cell_size_m, options.speed_m_per_s);
  bool same = model.spec.grips.size() == expected.size();
  for (std::size_t k = 0; same && k < expected.size(); ++k) {
    same = model.spec.grips[k].velocity_m_per_s == expected[k].velocity_m_per_s &&
           model.spec.grips[k].held_axes == expected[k].held_axes;
  }
  if (!same) {
    throw InputError("tensile test: the sheet must be held by tensile_grips() at the test's speed (tensile_test.h)");
  }
}

// Slope through the origin of force against strain over strains up to `limit`.
double slope_through_origin(const TensileResult& r, double limit) {
  double sxy = 0.0, sxx = 0.0;
  for (std::size_t k = 0; k < r.strain.size() && r.strain[k] <= limit; ++k) {
    sxy += r.strain[k] * r.force_per_width_n_per_m[k];
    sxx += r.strain[k] * r.strain[k];
  }
  return sxx > 0.0 ? sxy / sxx : 0.0;
}

}  // namespace

TensileResult run_tensile_test(const SheetModel& model, const SheetParams& params, const TensileOptions& options) {
  options.validate();
  params.validate();
  check_grips(model, options);
  const Stopwatch clock;
  ExplicitIntegrator integrator(model, params, options.time_step_fraction * stable_time_step_s(model, params));
  SheetState state = make_sheet_state(model);
  TensileResult r;
  const double length = model.spec.width_m, width = model.spec.height_m;
  std::size_t peak = 0;
  for (;;) {
    integrator.step(&state);
    r.strain.push_back(options.speed_m_per_s * state.time_s / length);
    r.force_per_width_n_per_m.push_back(state.grip_force_n(0, 2) / width);
    if (r.force_per_width_n_per_m.back() > r.force_per_width_n_per_m[peak]) peak = r.strain.size() - 1;
    r.broke = r.force_per_width_n_per_m.back() < 0.25 * r.force_per_width_n_per_m[peak] &&
              r.force_per_width_n_per_m[peak] > 0.0;
    if (r.broke || r.strain.back() >= options.max_strain) break;
  }
  r.strength_n_per_m = r.force_per_width_n_per_m[peak];
  r.strain_at_peak = r.strain[peak];
  r.stiffness_n_per_m = slope_through_origin(r, options.stiffness_strain_fraction * r.strain_at_peak);
  r.steps = state.steps;
  r.cpu_s = clock.cpu_s();
  return r;
}

}  // namespace repose
