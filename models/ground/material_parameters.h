#pragma once
// The fittable parameters of the ground model's materials, as a solver
// declares them (models/core/solver/solver.h): per named material its
// alpha, repose angle, sigma and drag compaction ratio ("sand.alpha",
// "sand.repose_angle_deg", "sand.sigma", "sand.drag_compaction_ratio"; a
// value applies to every region of that material). Shared
// by the ground solver and the models built on the ground (heightspan), so
// that a calibration fits them by the same names.

#include <string>
#include <vector>

#include "models/core/solver/solver.h"
#include "models/ground/ground_params.h"

namespace repose {

struct GroundModel;

class MaterialParameters {
 public:
  // One of each field per distinct material name of the model.
  explicit MaterialParameters(const GroundModel& model);

  const std::vector<ParameterInfo>& infos() const { return infos_; }
  // The model's default params with these values (SI, one per infos())
  // applied, validated (InputError when out of range).
  GroundParams params_for(const GroundModel& model, const std::vector<double>& values_si) const;

 private:
  enum class Field { kAlpha, kReposeAngle, kSigma, kDragCompactionRatio };
  struct Target {
    std::string material;
    Field field;
  };
  void declare(const Material& m);

  std::vector<ParameterInfo> infos_;
  std::vector<Target> targets_;  // per parameter
};

}  // namespace repose
