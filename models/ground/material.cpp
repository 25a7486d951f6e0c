#include "models/ground/material.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"

namespace repose {

bool material_preset(const std::string& name, Material* out) {
  constexpr double deg = std::numbers::pi / 180.0;
  Material m;
  m.name = name;
  if (name == "sand") {
    m.alpha = 1.0;
    m.repose_angle_rad = 30 * deg;
  } else if (name == "mud") {
    m.alpha = 0.8;
    m.repose_angle_rad = 60 * deg;
  } else if (name == "snow") {
    m.alpha = 0.0;
    m.repose_angle_rad = 90 * deg;
  } else {
    return false;
  }
  m.sigma = 0.2;
  m.erosion_iterations = 5;
  *out = m;
  return true;
}

double Material::displaced_fraction(bool dragging) const {
  return dragging ? std::max(0.0, 1.0 - drag_compaction_ratio * (1.0 - alpha)) : alpha;
}

int Material::erosion_passes(double cell_size_m) const {
  if (!(erosion_iterations_cell_m > 0.0)) return erosion_iterations;
  REPOSE_DEMAND(cell_size_m > 0.0);
  const double ratio = erosion_iterations_cell_m / cell_size_m;
  const double passes = std::round(erosion_iterations * ratio * ratio);
  // more than kMaxErosionPasses is refused where the grid is known (ground_params.cpp)
  return static_cast<int>(std::clamp(passes, 1.0, static_cast<double>(kMaxErosionPasses) + 1.0));
}

void validate(const Material& m) {
  if (!(m.alpha >= 0.0 && m.alpha <= 1.0)) throw FieldError("alpha", "a number in [0, 1]", yaml_number(m.alpha));
  if (!(m.repose_angle_rad > 0.0 && m.repose_angle_rad <= std::numbers::pi / 2)) {
    throw FieldError("repose_angle_deg", "an angle in (0, 90] deg", yaml_degrees(m.repose_angle_rad / kRadPerDeg));
  }
  if (!(m.sigma > 0.0 && m.sigma <= kSigmaMax)) {
    throw FieldError("sigma", fmt::format("a number in (0, {}] (erosion diverges above it, see ground_params.h)", kSigmaMax),
                     yaml_number(m.sigma));
  }
  if (m.erosion_iterations < 1 || m.erosion_iterations > kMaxErosionPasses) {
    throw FieldError("erosion_iterations", fmt::format("an integer in [1, {}]", kMaxErosionPasses),
                     std::to_string(m.erosion_iterations));
  }
  if (!(m.erosion_iterations_cell_m >= 0.0 && m.erosion_iterations_cell_m <= 1.0)) {
    throw FieldError("erosion_iterations_cell_m", "a cell size in [0, 1] m (0: En passes on any cell)",
                     yaml_number(m.erosion_iterations_cell_m));
  }
  if (!(m.drag_compaction_ratio >= 0.0 && m.drag_compaction_ratio <= 10.0)) {
    throw FieldError("drag_compaction_ratio", "a number in [0, 10]", yaml_number(m.drag_compaction_ratio));
  }
}

}  // namespace repose
