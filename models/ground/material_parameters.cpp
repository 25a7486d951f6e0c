#include "models/ground/material_parameters.h"

#include <algorithm>
#include <numbers>

#include "models/ground/ground_model.h"

namespace repose {

MaterialParameters::MaterialParameters(const GroundModel& model) {
  for (const Material& m : model.materials) {
    const bool seen =
        std::any_of(targets_.begin(), targets_.end(), [&](const Target& p) { return p.material == m.name; });
    if (!seen) declare(m);
  }
}

void MaterialParameters::declare(const Material& m) {
  const double deg = std::numbers::pi / 180.0;
  auto add = [&](const std::string& field, Field f, const std::string& unit, double si_per_unit, double lo, double hi,
                 double value, const std::string& what) {
    infos_.push_back({m.name + "." + field, unit, si_per_unit, lo, hi, value, what});
    targets_.push_back({m.name, f});
  };
  add("alpha", Field::kAlpha, "1", 1.0, 0.0, 1.0, m.alpha, "fraction of the intersected height displaced");
  add("repose_angle_deg", Field::kReposeAngle, "deg", deg, 1e-6 * deg, 90.0 * deg, m.repose_angle_rad,
      "angle of repose: steeper slopes erode");
  add("sigma", Field::kSigma, "1", 1.0, 1e-9, kSigmaMax, m.sigma, "fraction of the excess moved per erosion pass");
  add("drag_compaction_ratio", Field::kDragCompactionRatio, "1", 1.0, 0.0, 10.0, m.drag_compaction_ratio,
      "what dragging compresses, as a ratio to what pressing does");
}

GroundParams MaterialParameters::params_for(const GroundModel& model, const std::vector<double>& values_si) const {
  GroundParams params = default_params(model);
  for (std::size_t k = 0; k < targets_.size(); ++k) {
    for (Material& m : params.materials) {
      if (m.name != targets_[k].material) continue;
      if (targets_[k].field == Field::kAlpha) m.alpha = values_si[k];
      if (targets_[k].field == Field::kReposeAngle) m.repose_angle_rad = values_si[k];
      if (targets_[k].field == Field::kSigma) m.sigma = values_si[k];
      if (targets_[k].field == Field::kDragCompactionRatio) m.drag_compaction_ratio = values_si[k];
    }
  }
  validate(params, model);
  return params;
}

}  // namespace repose
