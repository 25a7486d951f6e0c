#pragma once
// The interface every model and reference implements. A solver compiles a
// scene once into what is fixed (a CompiledSolver, as MuJoCo compiles
// mjModel), which declares the parameters a fit may change and runs with any
// values of them, returning a typed Run (run.h).
//
// To add a solver: a folder of its own with its scene section (fields.h,
// scene_section.h), a class implementing Solver, and one line in
// experiments/solvers/solver_registry.cpp. Nothing else changes: `repose
// run|experiment|calibrate` and `repose check` find it through the registry.

#include <memory>
#include <string>
#include <vector>

#include "models/core/base/progress.h"
#include "models/core/config/scene_section.h"
#include "models/core/solver/run.h"

namespace repose {

struct Scene;

// A parameter a fit may change. Values cross the interface in SI units;
// calibration files and reports use `unit`, value_si = value * si_per_unit
// (degrees: si_per_unit = pi / 180).
struct ParameterInfo {
  std::string name;         // unique within the solver, e.g. "sand.alpha", "friction"
  std::string unit;         // of the name: "1", "deg", "m", "Pa"
  double si_per_unit = 1.0;
  double lower_si = 0.0;    // the allowed interval (the model's own validate() rule)
  double upper_si = 0.0;
  double value_si = 0.0;    // this scene's value: what a run without a fit uses
  std::string description;
};

struct RunOptions {
  ProgressFn progress;
  // Where the solver may write files (the run folder, absolute); empty: write
  // nothing (calibration runs many parameter sets). Files written go in Run::files.
  std::string output_dir;
};

class CompiledSolver {
 public:
  virtual ~CompiledSolver() = default;
  // The parameters, in a fixed order; run() takes one value per entry.
  virtual const std::vector<ParameterInfo>& parameters() const = 0;
  // Runs with these parameter values (SI, one per parameters()). Const and
  // safe to call from several threads at once; the same values give the same
  // bits. Throws InputError for values outside their interval.
  virtual Run run(const std::vector<double>& values_si, const RunOptions& options) const = 0;

  // The scene's own values of parameters(), for runs without a fit.
  std::vector<double> default_values() const;
  // The index of a parameter by name, or InputError listing the names.
  std::size_t parameter_index(const std::string& name) const;
};

// InputError unless there is one value per parameter, each in its interval
// (for CompiledSolver::run implementations).
void check_values(const std::vector<ParameterInfo>& parameters, const std::vector<double>& values_si,
                  const std::string& solver);

class Solver {
 public:
  virtual ~Solver() = default;
  virtual std::string name() const = 0;         // "ground", "liggghts", ...
  virtual std::string description() const = 0;  // one line for --help
  // The scene sections this solver reads (it may define them, or share them
  // with others: the dem section is every particle reference's).
  virtual std::vector<SectionType> sections() const { return {}; }
  // Whether this solver can run the scene (its required sections present);
  // when it cannot, `why` says what is missing.
  virtual bool can_run(const Scene& scene, std::string* why) const;
  // Builds what is fixed. Throws InputError naming the scene file and what
  // is missing or inconsistent; `repose check` calls it for every solver
  // that can run the scene, so that run refuses nothing check accepted.
  virtual std::unique_ptr<CompiledSolver> compile(const Scene& scene) const = 0;
  // Whether CompiledSolver::run may be called from several threads at once.
  // An engine that keeps process-wide state (Bullet's margins, ODE's random
  // seed) says no, and calibration then runs it on one thread.
  virtual bool thread_safe() const { return true; }
};

}  // namespace repose
