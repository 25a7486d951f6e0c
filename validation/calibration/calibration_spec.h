#pragma once
// A calibration: which scenes, compared with which reference runs, through
// which observables, fitting which parameters of which solver, with which solver
// options, and which speed/accuracy ladder to measure. Loaded and validated
// once from a YAML file (calibration_loader.h); SI units and radians inside,
// degrees only in the file.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "models/ground/material.h"
#include "validation/observables/observable_spec.h"

namespace repose {


// Where a scene's reference surface comes from.
struct ReferenceSpec {
  enum class Kind {
    kData,       // run folders holding height_initial.npy and height_final.npy on the scene's grid
                 // (canonical LIGGGHTS runs, data/...), with their manifests for their cost;
                 // several folders are the same scene on different random beds (seeds): the
                 // reference is their mean and their spread its noise floor
    kLiggghts,   // a LIGGGHTS run made into `directory` when it holds no height_final.npy yet
    kHeuristic,  // the calibrated solver itself at known parameter values (synthetic references)
  };
  Kind kind = Kind::kData;
  std::vector<std::string> directories;  // data: one per seed; liggghts: one; absolute
  // heuristic: parameter values by full name ("ground.sand.alpha"), in the
  // parameter's unit; the others keep the scene's own values, and the
  // scene's initial surface is the start.
  std::vector<std::pair<std::string, double>> values;
  std::string location;   // FILE:LINE:COL of the reference, for messages
};

struct CalibrationScene {
  enum class Role { kFit, kHeldOut };
  std::string name;        // default: the scene's name
  std::string scene_path;  // absolute
  Role role = Role::kFit;
  ReferenceSpec reference;
  std::vector<ObservableSpec> observables;  // at least one
  // The surface compared: the solver run's field of this name and the
  // reference folder's NAME.npy (e.g. snow_depth_final.table for the snow
  // model's depth on one snow map); its initial surface is height_initial either way.
  std::string field = "height_final";
  // Region of the reported surface RMSE (default: whole grid).
  std::optional<CalibrationRegion> rmse_region;
  // The random bed the calibrated solver builds (default: the scene file's
  // seed). Several entries of one scene file with different seeds fit the
  // solver over several beds at once (each needs its own name).
  std::optional<std::uint64_t> seed;
  // The bed the calibrated solver runs on. kMean: the mean of the reference
  // seeds' initial surfaces, one run. kEach: each seed's own bed, one run per
  // seed, every observable the mean over the beds of its value on each, as
  // the reference's per-seed observables are. A nonlinear observable (a
  // heap's flank) of the mean bed, smoother than any seed's, is not the mean
  // of the beds' (the scoop's dumped flank 1 deg steeper on it). kEach needs
  // a data reference of two or more seeds. The ladder's rungs (one timed run
  // each) run on the mean bed either way.
  enum class Beds { kMean, kEach };
  Beds beds = Beds::kMean;
  // The cells the calibrated solver runs on, in m (default: the scene
  // file's). Coarser cells only, dividing the scene's extent: the
  // reference's surfaces, on the scene file's grid, are averaged onto them
  // (area-weighted), and every surface observable compares on them. A fit on
  // coarser cells than its reference trades the ground's detail for speed.
  std::optional<double> cell_size_m;
  std::string cell_size_location;  // FILE:LINE:COL of cell_size_m, for messages
};

// One fitted (or fixed) parameter of the calibrated solver, named
// `solver.parameter` in the file ("ground.sand.alpha",
// "ground.sand.repose_angle_deg"): the solver declares its parameters, their
// units and intervals (models/core/solver/solver.h), so calibration fits any
// solver's parameters without knowing which model they belong to.
struct ParameterSpec {
  std::string solver;   // "ground"
  std::string name;     // its name in the solver: "sand.alpha"
  // As written, in the parameter's own unit (degrees for *_deg):
  double file_initial = 0.0;
  std::optional<double> file_lower, file_upper;  // default: the solver's interval
  std::optional<double> file_step;               // default: 5 % of the bounds' width
  bool fixed = false;
  std::string location;  // FILE:LINE:COL of the entry, for messages
  // Resolved against the solver's declaration by CalibrationProblem (SI units):
  std::string unit;
  double si_per_unit = 1.0;
  double initial = 0.0;
  double lower = 0.0;
  double upper = 0.0;
  double step = 0.0;     // central-difference half-width, absolute

  std::string label() const { return solver + "." + name; }  // "ground.sand.alpha"
  double in_file_units(double si) const { return si / si_per_unit; }
};

struct CalibrationSolverSpec {
  enum class Loss { kNone, kHuber, kCauchy };
  Loss loss = Loss::kNone;
  double loss_scale = 1.0;     // of Huber/Cauchy, in residual units
  int starts = 4;              // the initial values, then Halton points over the bounds
  int max_iterations = 30;     // per start
  std::uint64_t seed = 1;      // scrambles the Halton starts
  int threads = 2;             // parallel heuristic runs (results do not depend on it)
  // Leave-one-scene-out refits after the fit (cross_validation.h): one more
  // fit per fit scene; false leaves them out (the held-out scenes still score the fit).
  bool cross_validation = true;
  // Reciprocal condition number of the range-scaled Jacobian below which a
  // direction counts as undetermined.
  double min_reciprocal_condition = 1.0e-3;
};

// A rung of a particle reference (LIGGGHTS, Bullet or ODE) in the ladder: a
// canonical run and its scene. The engine is the one that made the run (its
// manifest says which).
struct LadderReference {
  std::string scene_path;  // absolute; its dem.grain_radius_m sizes the rung
  std::string directory;   // absolute; height_final.npy and its cost (liggghts_manifest.json or manifest.json)
};

struct LadderSpec {
  std::string scene;                     // name of a calibration scene (default: the first fit scene)
  std::vector<double> heuristic_cell_sizes_m;  // >= 1 entries; the ground model at each
  bool multires = true;                  // also the scene's resolution with objects on the coarse grid
  int multires_coarse_factor = 2;
  std::vector<LadderReference> references;  // particle-engine rungs (engines, grain sizes); the yardstick is the scene's reference
  int timing_repeats = 3;                // heuristic runs timed per rung (the fastest counts)
};

struct CalibrationSpec {
  std::string source_path;  // absolute
  std::string name;
  std::vector<CalibrationScene> scenes;     // at least one with role fit
  std::string fitted_solver;                // the calibrated solver: every parameter's prefix
  std::vector<ParameterSpec> parameters;    // at least one free
  CalibrationSolverSpec solver;
  std::optional<LadderSpec> ladder;
};

}  // namespace repose
