#include "models/tearing/sheet_params.h"

#include <cmath>

#include <fmt/format.h>

#include "models/core/config/fields.h"

namespace repose {

void SheetParams::validate() const {
  if (!(std::isfinite(stiffness_n_per_m) && stiffness_n_per_m > 0.0)) {
    throw FieldError("stiffness_n_per_m", "a stiffness > 0 N/m", fmt::format("{}", stiffness_n_per_m));
  }
  if (!(std::isfinite(tear_strain) && tear_strain > 0.0 && tear_strain <= 10.0)) {
    throw FieldError("tear_strain", "a strain in (0, 10]", fmt::format("{}", tear_strain));
  }
  if (!(fibre_anisotropy >= 0.0 && fibre_anisotropy < 1.0)) {
    throw FieldError("fibre_anisotropy", "a number in [0, 1)", fmt::format("{}", fibre_anisotropy));
  }
  if (!(std::isfinite(tear_energy_j_per_m) && tear_energy_j_per_m > 0.0)) {
    throw FieldError("tear_energy_j_per_m", "an energy per tear length > 0 J/m", fmt::format("{}", tear_energy_j_per_m));
  }
}

}  // namespace repose
