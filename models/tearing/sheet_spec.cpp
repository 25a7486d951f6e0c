#include "models/tearing/sheet_spec.h"

#include <cmath>

#include <fmt/format.h>

#include "models/core/config/fields.h"

namespace repose {

namespace {

// FieldError names the key, so that the scene loader points at it.
void require(bool ok, const std::string& field, double value, const char* rule) {
  if (!ok) throw FieldError(field, rule, fmt::format("{}", value));
}

// Whether a grip holds the vertex whose rest position is (x, y).
bool grip_holds(const GripSpec& g, double x, double y) {
  const double tol = 1e-9 * (1.0 + std::abs(x) + std::abs(y));
  return x >= g.x_min_m - tol && x <= g.x_max_m + tol && y >= g.y_min_m - tol && y <= g.y_max_m + tol;
}

void validate_grips(const SheetSpec& s) {
  const int ny = s.cells_y();
  const double h = s.cell_size_m();
  for (std::size_t k = 0; k < s.grips.size(); ++k) {
    const GripSpec& g = s.grips[k];
    const std::string name = fmt::format("grips[{}]", k);
    if (!(g.x_max_m >= g.x_min_m && g.y_max_m >= g.y_min_m && g.velocity_m_per_s.allFinite())) {
      throw FieldError("grips", name + " with x_max_m >= x_min_m, y_max_m >= y_min_m and a finite velocity",
                       fmt::format("x [{}, {}], y [{}, {}]", g.x_min_m, g.x_max_m, g.y_min_m, g.y_max_m));
    }
    int held = 0;
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= s.cells_x; ++i) {
        if (!grip_holds(g, i * h, j * h)) continue;
        ++held;
        for (std::size_t m = 0; m < k; ++m) {
          if (grip_holds(s.grips[m], i * h, j * h)) {
            throw FieldError("grips", "grips that hold no vertex in common",
                             fmt::format("grips[{}] and grips[{}] both holding the vertex at ({}, {}) m", m, k, i * h,
                                         j * h));
          }
        }
      }
    }
    if (held == 0) throw FieldError("grips", "grips that each hold a vertex of the mesh", name + " holding none");
  }
}

}  // namespace

int SheetSpec::cells_y() const { return static_cast<int>(std::lround(height_m / cell_size_m())); }

void SheetSpec::validate() const {
  require(std::isfinite(width_m) && width_m > 0.0, "width_m", width_m, "> 0");
  require(std::isfinite(height_m) && height_m > 0.0, "height_m", height_m, "> 0");
  require(std::isfinite(grammage_kg_per_m2) && grammage_kg_per_m2 > 0.0, "grammage_kg_per_m2", grammage_kg_per_m2,
          "> 0");
  require(cells_x >= 1 && cells_x <= 2000, "cells_x", cells_x, "in [1, 2000]");
  const double rows = height_m / cell_size_m();
  require(std::abs(rows - std::round(rows)) <= 1e-6 * rows && std::round(rows) >= 1.0 && rows <= 2000.5,
          "height_m", height_m, "a whole number (1 to 2000) of square cells of width_m / cells_x");
  require(std::isfinite(bending_stiffness_n_m) && bending_stiffness_n_m >= 0.0, "bending_stiffness_n_m",
          bending_stiffness_n_m, ">= 0");
  require(stiffness_density_exponent >= 0.0 && stiffness_density_exponent <= 8.0, "stiffness_density_exponent",
          stiffness_density_exponent, "in [0, 8]");
  require(tear_strain_density_exponent >= 0.0 && tear_strain_density_exponent <= 8.0,
          "tear_strain_density_exponent", tear_strain_density_exponent, "in [0, 8]");
  require(std::isfinite(damping_per_s) && damping_per_s >= 0.0, "damping_per_s", damping_per_s, ">= 0");
  require(std::isfinite(stiffness_damping_s) && stiffness_damping_s >= 0.0, "stiffness_damping_s",
          stiffness_damping_s, ">= 0");
  require(std::isfinite(release_time_s) && release_time_s >= 0.0, "release_time_s", release_time_s, ">= 0");
  require(tear_rule != TearRule::kCohesive || release_time_s == 0.0, "release_time_s", release_time_s,
          "0 with tear_rule: cohesive (its springs let go by themselves)");
  require(gravity_m_per_s2.allFinite(), "gravity_m_per_s2", gravity_m_per_s2.norm(), "finite");
  require(std::isfinite(notch_length_m) && notch_length_m >= 0.0 && notch_length_m <= height_m, "notch_length_m",
          notch_length_m, "in [0, height_m]");
  require(std::isfinite(notch_x_m) && notch_x_m >= 0.0 && notch_x_m <= width_m, "notch_x_m", notch_x_m,
          "in [0, width_m]");
  fibres.validate();
  validate_grips(*this);
}

std::vector<GripSpec> seed_twist_grips(double width_m, double height_m, double grip_depth_m, double gap_m,
                                       double speed_m_per_s) {
  GripSpec left, right;
  left.x_min_m = 0.0;
  left.x_max_m = 0.5 * (width_m - gap_m);
  right.x_min_m = 0.5 * (width_m + gap_m);
  right.x_max_m = width_m;
  left.y_min_m = right.y_min_m = height_m - grip_depth_m;
  left.y_max_m = right.y_max_m = height_m;
  left.velocity_m_per_s = Eigen::Vector3d(0.0, 0.0, -speed_m_per_s);
  right.velocity_m_per_s = Eigen::Vector3d(0.0, 0.0, speed_m_per_s);
  return {left, right};
}

}  // namespace repose
