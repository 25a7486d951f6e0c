#include "models/ground/ground_params.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"
#include "models/ground/ground_model.h"

namespace repose {

GroundParams default_params(const GroundModel& model) { return GroundParams{model.materials}; }

void validate(const GroundParams& params, const GroundModel& model) {
  if (params.materials.size() != model.materials.size()) {
    throw InputError(fmt::format("ground params: {} materials given, the scene has {}", params.materials.size(),
                                 model.materials.size()));
  }
  for (std::size_t k = 0; k < params.materials.size(); ++k) {
    const Material& m = params.materials[k];
    try {
      validate(m);  // the one rule the scene loader applies too
    } catch (const FieldError& e) {
      throw InputError(fmt::format("ground params: materials[{}] ({}): {}", k, m.name, e.what()));
    }
  }
}

}  // namespace repose
