#pragma once
// The ground model's driver: builds the model from a scene, runs every time
// step and returns what the run produced (no file output; the command line
// writes DIR/height_final.npy and the manifest from this).

#include <string>
#include <vector>

#include "models/core/geometry/height_field.h"
#include "models/core/base/progress.h"
#include "models/core/config/scene.h"
#include "models/ground/free_body_drive.h"
#include "models/ground/ground_params.h"
#include "models/ground/volume_ledger.h"

namespace repose {

struct GroundModel;

struct GroundRun {
  HeightField initial_height;
  HeightField final_height;
  std::vector<double> step_wall_s;  // wall time of each step
  VolumeLedger ledger;
  double final_volume_m3 = 0.0;
  // The stages the scene built, e.g. "collision:cpu", "sweep", "substeps:10",
  // "rotation-substeps", "erosion", "multires", "free-bodies:ode", "bearing:bekker".
  std::vector<std::string> stages;
  int steps = 0;
  long long contact_cells = 0;  // summed over steps
  std::vector<FreeBodyReport> free_bodies;  // objects with dynamic:, driven by ODE (free_body_drive.h)
};

// The scene's initial ground (make_initial_height), then every step. Free
// bodies (dynamic:) are driven by ODE over the field, which is built only
// when the model has one (free_body_drive.h).
// Throws InputError when params are invalid for the scene.
GroundRun simulate_ground(const Scene& scene, const GroundParams& params, const ProgressFn& progress = {});

// Same from an already built model and initial heights (for calibration:
// build once, run many parameter sets). Also throws InputError, before the
// first step, when a derived count is out of bounds (substep_count.h).
GroundRun simulate_ground(const GroundModel& model, const GroundParams& params, const HeightField& initial,
                          const ProgressFn& progress = {});

// The stages a model builds with these params.
std::vector<std::string> ground_stages(const GroundModel& model, const GroundParams& params);

}  // namespace repose
