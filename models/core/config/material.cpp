#include "models/core/config/material.h"

#include <numbers>

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

}  // namespace repose
