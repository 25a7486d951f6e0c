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
      if (m.erosion_passes(model.grid.cell_size_m) > kMaxErosionPasses) {
        throw FieldError("erosion_iterations_cell_m",
                         fmt::format("at most {} passes on the grid's {} m cells ({} x {} / {})", kMaxErosionPasses,
                                     model.grid.cell_size_m, m.erosion_iterations, m.erosion_iterations_cell_m,
                                     model.grid.cell_size_m),
                         yaml_number(m.erosion_iterations_cell_m));
      }
    } catch (const FieldError& e) {
      throw InputError(fmt::format("ground params: materials[{}] ({}): {}", k, m.name, e.what()));
    }
  }
}

}  // namespace repose
