#pragma once
// Small sheets shared by the tearing tests, built in code.

#include <random>

#include "models/tearing/fibre_image.h"
#include "models/tearing/sheet_model.h"
#include "models/tearing/sheet_params.h"
#include "models/tearing/sheet_state.h"
#include "models/tearing/stable_time_step.h"
#include "models/tearing/tear_run.h"

namespace repose::testing {

// A square sheet of side width_m, cells_x cells a side, no gravity, no
// damping, no grips.
inline SheetSpec free_sheet_spec(double width_m, int cells_x) {
  SheetSpec spec;
  spec.width_m = spec.height_m = width_m;
  spec.cells_x = cells_x;
  spec.gravity_m_per_s2.setZero();
  spec.damping_per_s = 0.0;
  spec.notch_x_m = 0.5 * width_m;
  return spec;
}

inline SheetModel uniform_sheet(const SheetSpec& spec) {
  return build_sheet_model(spec, uniform_fibre_images(spec.width_m, spec.height_m, spec.width_m / 64.0, 0.8));
}

inline SheetModel fibre_sheet(const SheetSpec& spec, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  return build_sheet_model(spec, draw_fibre_images(spec.fibres, spec.width_m, spec.height_m, rng));
}

// A uniform 21-cell (42 mm) sheet notched 4 mm in its middle column under the
// seed's twist (grips 6 mm deep, 6 mm apart, at 4 m/s), undamped.
inline SheetSpec notched_twisted_spec(bool twist_stiffness) {
  SheetSpec spec = free_sheet_spec(0.042, 21);
  spec.twist_stiffness = twist_stiffness;
  spec.grips = seed_twist_grips(0.042, 0.042, 0.006, 0.006, 4.0);
  spec.notch_length_m = 0.004;
  spec.notch_x_m = 0.021;
  return spec;
}

// A tear run that stops when the tear is 24 mm deep (20 ms at most).
inline TearRunOptions stop_at_24_mm() {
  TearRunOptions options;
  options.duration_s = 0.02;
  options.stop_at_depth_m = 0.024;
  return options;
}

// A grip holding the vertices of the column x = x_m along `axes`, moving at vx.
inline GripSpec column_grip(double x_m, double y_min_m, double y_max_m, double vx, std::array<bool, 3> axes) {
  GripSpec g;
  g.x_min_m = g.x_max_m = x_m;
  g.y_min_m = y_min_m;
  g.y_max_m = y_max_m;
  g.velocity_m_per_s = Eigen::Vector3d(vx, 0.0, 0.0);
  g.held_axes = axes;
  return g;
}

// A strip pulled along x: the left column held in x (its lowest vertex in x
// and y, so the strip cannot drift), the right column moved at speed_m_per_s
// in x; both free to contract in y (rollers), z free.
inline void add_uniaxial_grips(SheetSpec* spec, double speed_m_per_s) {
  const double w = spec->width_m, h = spec->height_m, cell = spec->cell_size_m();
  spec->grips = {column_grip(0.0, 0.0, 0.0, 0.0, {true, true, false}),
                 column_grip(0.0, cell, h, 0.0, {true, false, false}),
                 column_grip(w, 0.0, h, speed_m_per_s, {true, false, false})};
}

// The state stretched affinely by strain_x along x and strain_y along y.
inline SheetState affinely_stretched(const SheetModel& model, double strain_x, double strain_y) {
  SheetState state = make_sheet_state(model);
  state.positions.row(0) *= 1.0 + strain_x;
  state.positions.row(1) *= 1.0 + strain_y;
  return state;
}

}  // namespace repose::testing

namespace repose::testing {

// `fraction` of the stable explicit step.
inline double integrator_limit_fraction(const SheetModel& model, const SheetParams& params, double fraction) {
  return fraction * stable_time_step_s(model, params);
}

}  // namespace repose::testing
