#pragma once
// A calibration: which scenes, compared with which reference runs, through
// which observables, fitting which ground-model parameters, with which solver
// options, and which speed/accuracy ladder to measure. Loaded and validated
// once from a YAML file (calibration_loader.h); SI units and radians inside,
// degrees only in the file.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/core/config/material.h"
#include "validation/observables/observable_spec.h"

namespace repose {


// Where a scene's reference surface comes from.
struct ReferenceSpec {
  enum class Kind {
    kData,       // a folder holding height_initial.npy and height_final.npy on the scene's grid
                 // (a canonical LIGGGHTS run, data/dem_*), with liggghts_manifest.json for its cost
    kLiggghts,   // a LIGGGHTS run made into `directory` when it holds no height_final.npy yet
    kHeuristic,  // the ground model itself at known parameters (synthetic references)
  };
  Kind kind = Kind::kData;
  std::string directory;  // data, liggghts: absolute
  // heuristic: these values replace those of every material named `material`
  // (every material when empty); the scene's initial surface is the start.
  std::string material;
  std::optional<double> alpha;
  std::optional<double> repose_angle_rad;
  std::optional<double> sigma;
};

struct CalibrationScene {
  enum class Role { kFit, kHeldOut };
  std::string name;        // default: the scene's name
  std::string scene_path;  // absolute
  Role role = Role::kFit;
  ReferenceSpec reference;
  std::vector<ObservableSpec> observables;  // at least one
  // Region of the reported surface RMSE (default: whole grid).
  std::optional<CalibrationRegion> rmse_region;
};

// One fitted (or fixed) material parameter.
struct ParameterSpec {
  enum class Field { kAlpha, kReposeAngle, kSigma };
  std::string material = "sand";  // applies to every material of this name in every scene
  Field field = Field::kAlpha;
  double initial = 0.0;  // SI / radians
  double lower = 0.0;
  double upper = 0.0;
  double step = 0.0;     // central-difference half-width, absolute (same units)
  bool fixed = false;

  std::string label() const;  // "sand.alpha", "sand.repose_angle_deg", "sand.sigma"
};

const char* parameter_field_name(ParameterSpec::Field field);  // "alpha", "repose_angle_deg", "sigma"

struct CalibrationSolverSpec {
  enum class Loss { kNone, kHuber, kCauchy };
  Loss loss = Loss::kNone;
  double loss_scale = 1.0;     // of Huber/Cauchy, in residual units
  int starts = 4;              // the initial values, then Halton points over the bounds
  int max_iterations = 30;     // per start
  std::uint64_t seed = 1;      // scrambles the Halton starts
  int threads = 2;             // parallel heuristic runs (results do not depend on it)
  // Reciprocal condition number of the range-scaled Jacobian below which a
  // direction counts as undetermined.
  double min_reciprocal_condition = 1.0e-3;
};

// A rung of LIGGGHTS in the ladder: a canonical run and its scene.
struct LadderReference {
  std::string scene_path;  // absolute; its dem.grain_radius_m sizes the rung
  std::string directory;   // absolute; height_final.npy and liggghts_manifest.json
};

struct LadderSpec {
  std::string scene;                     // name of a calibration scene (default: the first fit scene)
  std::vector<double> heuristic_cell_sizes_m;  // >= 1 entries; the ground model at each
  bool multires = true;                  // also the scene's resolution with objects on the coarse grid
  int multires_coarse_factor = 2;
  std::vector<LadderReference> liggghts;  // the finest grain size is the yardstick
  int timing_repeats = 3;                // heuristic runs timed per rung (the fastest counts)
};

struct CalibrationSpec {
  std::string source_path;  // absolute
  std::string name;
  std::vector<CalibrationScene> scenes;     // at least one with role fit
  std::vector<ParameterSpec> parameters;    // at least one free
  CalibrationSolverSpec solver;
  std::optional<LadderSpec> ladder;
};

}  // namespace repose
