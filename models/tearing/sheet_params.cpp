#include "models/tearing/sheet_params.h"

#include <cmath>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

void SheetParams::validate() const {
  if (!(std::isfinite(stiffness_n_per_m) && stiffness_n_per_m > 0.0)) {
    throw InputError(fmt::format("tearing params: stiffness_n_per_m = {} must be > 0", stiffness_n_per_m));
  }
  if (!(std::isfinite(tear_strain) && tear_strain > 0.0 && tear_strain <= 10.0)) {
    throw InputError(fmt::format("tearing params: tear_strain = {} must be in (0, 10]", tear_strain));
  }
}

}  // namespace repose
