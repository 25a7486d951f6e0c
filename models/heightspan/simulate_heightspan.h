#pragma once
// The height-span model's driver: every time step of a built model, with the
// ledger checked after each (ground + spans + particles in the air +
// compressed + left the grid against the initial volume), and per step the
// material each held object carries. Writes no files; a frame callback lets
// the solver render what it wants.

#include <functional>
#include <string>
#include <vector>

#include "models/core/base/progress.h"
#include "models/core/geometry/height_field.h"
#include "models/ground/ground_params.h"
#include "models/ground/volume_ledger.h"

namespace repose {

struct HeightSpanModel;
struct HeightSpanState;

struct HeightSpanRun {
  HeightField initial_height;
  HeightField final_height;
  int steps = 0;
  std::vector<double> time_s;                 // the end of each step
  std::vector<std::vector<double>> held_m3;   // per held object (model order), per step
  std::vector<double> in_flight_m3;           // per step
  std::vector<double> imbalance_m3;           // per step: initial - accounted
  std::vector<double> step_wall_s;
  double initial_m3 = 0.0;
  double max_abs_imbalance_m3 = 0.0;
  VolumeLedger ledger;                        // the ground's (compressed, left the grid)
  long long contact_cells = 0;
  double taken_up_m3 = 0.0;
  double wedge_kept_m3 = 0.0, wedge_laid_m3 = 0.0, wedge_final_m3 = 0.0;
  double side_cut_m3 = 0.0;  // part of wedge_kept_m3 (side_cut.h)
  double over_lip_m3 = 0.0;  // out of the wedges into the objects over their lips (drag_wedge.h)
  double span_to_ground_m3 = 0.0, ground_to_span_m3 = 0.0, span_to_particles_m3 = 0.0;
  long long particles_released = 0, particles_on_spans = 0, particles_on_ground = 0, particles_left_grid = 0;
  bool particles_built = false;
  int resampled = 0;
  std::vector<std::string> stages;            // the modules built (heightspan_stages)
};

// frame: called at time 0 and then whenever a step ends at or past the next
// multiple of options.frame_interval_s (never when it is 0).
using FrameFn = std::function<void(int frame, const HeightSpanState& state)>;

// Throws InputError for invalid params or a step that needs too many substeps.
HeightSpanRun simulate_heightspan(const HeightSpanModel& model, const GroundParams& params, const HeightField& initial,
                                  const ProgressFn& progress = {}, const FrameFn& frame = {});

// The stages a model builds: "collision:cpu", "displacement", "span-maps",
// "span-erosion", "erosion" (and "particles" once something fell).
std::vector<std::string> heightspan_stages(const HeightSpanModel& model, const GroundParams& params);

}  // namespace repose
