#include "models/ground/ground_params.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/ground/ground_model.h"

namespace repose {

GroundParams default_params(const GroundModel& model) { return GroundParams{model.materials}; }

namespace {

void check(bool ok, std::size_t index, const Material& m, const char* field, double value, const char* rule) {
  if (ok) return;
  throw InputError(fmt::format("ground params: materials[{}] ({}): {} = {} is outside {}", index, m.name, field,
                               value, rule));
}

}  // namespace

void validate(const GroundParams& params, const GroundModel& model) {
  if (params.materials.size() != model.materials.size()) {
    throw InputError(fmt::format("ground params: {} materials given, the scene has {}", params.materials.size(),
                                 model.materials.size()));
  }
  for (std::size_t k = 0; k < params.materials.size(); ++k) {
    const Material& m = params.materials[k];
    check(m.alpha >= 0.0 && m.alpha <= 1.0, k, m, "alpha", m.alpha, "[0, 1]");
    check(m.repose_angle_rad > 0.0 && m.repose_angle_rad <= std::numbers::pi / 2, k, m, "repose_angle_rad",
          m.repose_angle_rad, "(0, pi/2]");
    check(m.sigma > 0.0 && m.sigma <= kSigmaMax, k, m, "sigma", m.sigma,
          "(0, 0.25] (erosion diverges above 1/4, see ground_params.h)");
    check(m.erosion_iterations >= 1, k, m, "erosion_iterations", m.erosion_iterations, "[1, inf)");
  }
}

}  // namespace repose
