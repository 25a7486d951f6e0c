#pragma once
// A calibration made ready to evaluate: every scene loaded and compiled
// once by the calibrated solver (any solver of the registry: it declares its
// parameters), its reference surfaces loaded (or made), and the reference's
// observables taken once. Evaluating a parameter set then runs the solver on
// each scene (on each seed's bed for a scene with beds: each, its observables
// averaged over the beds; many sets in parallel, each run independent and deterministic,
// so results do not depend on the thread count) and returns the weighted
// residuals (solver - reference) of the fit scenes. Observables are taken the
// same way from the solver's Run and the reference's (observe_run).
//
// Parameter values are kept as one vector over spec.parameters (SI units,
// radians); the free ones are those not fixed, in the file's order.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "models/core/geometry/height_field.h"
#include "models/core/base/progress.h"
#include "models/core/config/scene.h"
#include "models/core/solver/solver_registry.h"
#include "validation/calibration/calibration_spec.h"
#include "validation/observables/calibration_observables.h"

namespace repose {

struct PreparedScene {
  CalibrationScene entry;          // name filled in
  Scene scene;                     // its initial height: the reference's initial surface
  std::shared_ptr<const CompiledSolver> solver;  // the calibrated solver, compiled for `scene`
  // per calibration parameter: its index among solver->parameters(), or -1
  // when this scene has no such parameter (e.g. a material it does not hold)
  std::vector<int> parameter_index;
  HeightField initial;             // the solver starts here: the reference's initial surface (mean over seeds)
  HeightField reference_final;     // mean over seeds
  // Each seed's surfaces (one entry for a single reference run; none for a heuristic reference).
  std::vector<HeightField> seed_initial, seed_final;
  // Each seed's time series (a data reference's held_mass.csv, as
  // mass_held_kg.<object>; a heuristic reference's Run::series): what series
  // observables compare with, as the mean over seeds at their times.
  std::vector<SeriesByName> seed_series;
  // Each seed's scalar measures (a data reference's manifest.json; a heuristic
  // reference's Run::measures): what measure observables compare with, as their mean.
  std::vector<MeasureByName> seed_measures;
  std::vector<std::vector<double>> reference_values;  // per observable
  std::size_t residual_count = 0;
  double grain_diameter_m = 0.0;   // of the scene's dem section (0 without one)
  double reference_cell_size_m = 0.0;  // the scene file's cells, the reference's surfaces' (entry.cell_size_m: the solver's)
  std::optional<double> reference_wall_time_s;  // one LIGGGHTS run's (the mean over seeds), from its manifest
  std::optional<double> reference_cpu_time_s;
  // beds: each: the solver compiled for each seed's own bed (seed_initial),
  // in seed order; empty on the mean bed (`solver`, compiled for `initial`).
  std::vector<std::shared_ptr<const CompiledSolver>> bed_solvers;
  bool fit() const { return entry.role == CalibrationScene::Role::kFit; }
  std::size_t bed_count() const { return bed_solvers.empty() ? 1 : bed_solvers.size(); }
  const HeightField& bed_initial(std::size_t bed) const { return bed_solvers.empty() ? initial : seed_initial[bed]; }
};

// A reference run's surface (.npy) on the scene's grid; InputError naming the
// file and `what` for another shape or a non-finite height.
HeightField read_height_field(const std::string& path, const Grid& grid, const std::string& what);

// The element-wise mean of an observable's values on each seed or bed (lists of one length).
std::vector<double> mean_values(const std::vector<std::vector<double>>& lists);

// A run's measures by name (their values in SI units).
MeasureByName measure_values(const Run& run);

// A reference run folder's time series: its held_mass.csv (held_mass_series.h)
// as mass_held_kg.<object>, when it has one.
SeriesByName read_reference_series(const std::string& dir);

// Is the observable's reference the mean over seeds of each seed's value
// (series, measure, heap_flank) rather than the value of the seeds' mean surfaces?
bool observed_per_seed(const ObservableSpec& o);
// The observable's value on one reference seed (its own surfaces when the
// reference kept them, else the mean surfaces) with that seed's series and measures.
std::vector<double> seed_observation(const ObservableSpec& o, const PreparedScene& s, std::size_t seed);

class CalibrationProblem {
 public:
  // Loads the scenes and references; a LIGGGHTS reference that is not made
  // yet is run now (minutes). Throws InputError (naming the file, line and
  // column) for an unknown solver, a parameter no fit scene declares or
  // outside the solver's interval, a reference that does not fit its scene's
  // grid, or a ladder scene that is not listed.
  CalibrationProblem(CalibrationSpec spec, const SolverRegistry& registry, const ProgressFn& progress = {});

  const CalibrationSpec& spec() const { return spec_; }
  const std::vector<PreparedScene>& scenes() const { return scenes_; }
  const PreparedScene& scene_named(const std::string& name) const;
  // The same problem with the scene `name` held out of the fit (cross-validation).
  CalibrationProblem holding_out(const std::string& name) const;
  // Indices into spec().parameters of the free parameters.
  const std::vector<std::size_t>& free() const { return free_; }
  // Position of parameter p among the free ones, when it is free.
  std::optional<std::size_t> free_index(std::size_t p) const;

  std::vector<double> initial_values() const;  // every parameter's initial value
  // Every parameter's value with the free ones replaced.
  std::vector<double> with_free(const std::vector<double>& free_values) const;
  std::vector<double> free_of(const std::vector<double>& values) const;

  const SolverRegistry& registry() const { return *registry_; }
  const Solver& solver() const { return *solver_; }
  // The compiled solver's values for a calibration parameter set (SI).
  std::vector<double> solver_values(const PreparedScene& scene, const std::vector<double>& values) const;
  // The calibrated solver's run on one bed of the scene (bed 0 of a scene on
  // the mean bed). Runs of one scene file, bed, seed and reference are
  // remembered (they are deterministic): entries that compare different
  // fields of one run (the snow model's maps) share it.
  Run run_on_bed(const PreparedScene& scene, const std::vector<double>& values, std::size_t bed) const;
  // Its runs on every bed of the scene, in order (calibration_spec.h: beds).
  std::vector<Run> runs(const PreparedScene& scene, const std::vector<double>& values) const;
  // The runs' compared field (height_final by default), the mean over the beds.
  HeightField mean_final(const PreparedScene& scene, const std::vector<Run>& runs) const;
  // Each observable's values in the runs (as reference_values): the mean over
  // the beds of each bed's values, each bed's change taken from its own start.
  std::vector<std::vector<double>> observed(const PreparedScene& scene, const std::vector<Run>& runs) const;
  // ... before the mean: per observable, per bed (seed order; the one mean
  // bed without beds: each), that bed's values.
  std::vector<std::vector<std::vector<double>>> observed_per_bed(const PreparedScene& scene,
                                                                 const std::vector<Run>& runs) const;
  // observed() from observed_per_bed()'s values: each observable's mean over the beds.
  static std::vector<std::vector<double>> mean_over_beds(const std::vector<std::vector<std::vector<double>>>& per_bed);
  // weight * (observed - reference) / sqrt(count), observable after observable.
  std::vector<double> weighted_residuals(const PreparedScene& scene, const std::vector<std::vector<double>>& observed) const;
  std::vector<double> residuals(const PreparedScene& scene, const std::vector<Run>& runs) const;
  // The residuals of one final surface (and series, measures) grown from the scene's `initial`.
  std::vector<double> residuals(const PreparedScene& scene, const HeightField& final_height,
                                const SeriesByName& series = {}, const MeasureByName& measures = {}) const;

  // Residuals of all fit scenes (concatenated in scene order) at each point
  // (free parameter values), computed on spec().solver.threads threads.
  std::vector<std::vector<double>> fit_residuals(const std::vector<std::vector<double>>& free_points) const;
  std::size_t fit_residual_count() const { return fit_residual_count_; }
  long long runs() const { return runs_; }  // heuristic runs so far

 private:
  void resolve_parameters();
  CalibrationSpec spec_;
  const SolverRegistry* registry_;
  const Solver* solver_;
  std::vector<PreparedScene> scenes_;
  std::vector<std::size_t> free_;
  std::size_t fit_residual_count_ = 0;
  mutable long long runs_ = 0;
  struct RunMemory;
  std::shared_ptr<RunMemory> memory_;  // shared by copies (holding_out): the same runs
};

}  // namespace repose
