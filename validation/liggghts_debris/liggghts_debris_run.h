#pragma once
// A debris flow on generated terrain run in LIGGGHTS (liggghts_debris_script.h)
// and read back into the observables the rigid engines give
// (validation/rigid/debris_run.h): frames from the dumps (atoms by id, so
// in spec order; the parts at their spec poses: fixed), the buildings'
// force series from building_forces.txt, then finish_debris_result's front,
// runout, deposit, peak force and impulse. Costs are the program's (CPU:
// user + system of liggghts).

#include <string>

#include "validation/liggghts/liggghts_runner.h"
#include "validation/liggghts_debris/liggghts_debris_options.h"
#include "validation/rigid/debris_run.h"

namespace repose {

struct LiggghtsDebrisResult {
  DebrisRunResult run;
  std::string version;  // the log's first line
};

// Writes the inputs into run_dir (created), runs LIGGGHTS there and reads
// the outputs. Throws LiggghtsRunError when the run fails, InputError when
// its outputs are malformed (an element lost: a dump short of atoms).
LiggghtsDebrisResult run_liggghts_debris(const DebrisSetup& setup, double duration_s,
                                         const LiggghtsDebrisOptions& options, const std::string& run_dir,
                                         LiggghtsRunOptions run_options = {});

// The building force series of building_forces.txt (fix ave/time: lines
// "step fx0 fy0 fz0 fx1 ..." per part after '#' comments) into
// r.force_time_s and each building's force_n: the magnitude of the sum over
// its parts (part_building: each part's building, an index into r.buildings).
// InputError naming the file and line when malformed.
void read_debris_forces(const std::string& path, double time_step_s, const std::vector<int>& part_building,
                        DebrisRunResult& r);

}  // namespace repose
