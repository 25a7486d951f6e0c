#pragma once
// Calibration files (YAML) -> a validated CalibrationSpec. Strict as scene
// files are: unknown or duplicated keys, missing required keys and values out
// of range are one-line InputErrors, FILE:LINE:COL: KEY.PATH: expected WHAT,
// got WHAT. Paths are relative to the calibration file's folder. The format
// (see experiments/calibration_default.yaml):
//
//   name: indent_sand                       # optional (default: the file name)
//   scenes:                                 # at least one with role fit
//     - scene: scenes/dem_indent.yaml
//       name: dem_indent                    # optional (default: the scene's name)
//       role: fit                           # fit | held_out (default fit)
//       reference: {data: ../data/dem_indent}
//         # or {liggghts: DIR}  (the run is made into DIR when DIR has no height_final.npy)
//         # or {heuristic: {material: sand, alpha: 0.7, repose_angle_deg: 35, sigma: 0.15}}
//       rmse_region_m: {x: [a, b], y: [a, b]}   # optional (default: whole grid)
//       observables:                        # at least one; weight > 0 (default 1)
//         - {kind: height_field, weight: 1, region_m: {x: [a, b], y: [a, b]}}
//         - {kind: transect, from_m: [x, y], to_m: [x, y], samples: 40}
//         - {kind: crater_depth, region_m: {...}}     # region_m optional
//         - {kind: rim_height, region_m: {...}}
//         - {kind: pile_angle, centre_m: [x, y], weight: 0.01}
//         - {kind: furrow_area, from_m: [x, y], to_m: [x, y], samples: 40}
//   parameters:                             # at least one not fixed
//     - {material: sand, name: alpha, initial: 0.8, bounds: [0, 1], step: 0.05, fixed: false}
//     - {material: sand, name: repose_angle_deg, initial: 30, bounds: [10, 60], step: 2}
//     - {material: sand, name: sigma, initial: 0.2, bounds: [0.02, 0.25], step: 0.02}
//       # alpha in [0, 1], repose_angle_deg in (0, 90], sigma in (0, kSigmaMax];
//       # bounds, step optional (defaults: the whole range less a margin; 0.05, 2 deg, 0.02)
//   solver: {loss: none, loss_scale: 1, starts: 4, max_iterations: 30, seed: 1, threads: 2,
//            min_reciprocal_condition: 0.001}    # all optional
//   ladder:                                 # optional
//     scene: dem_indent                     # optional (default: the first fit scene)
//     heuristic_cell_sizes_m: [0.008, 0.004, 0.002]
//     multires: true
//     multires_coarse_factor: 2
//     timing_repeats: 3
//     references: [{scene: scenes/dem_indent.yaml, data: ../data/dem_indent}]
//       # canonical runs of LIGGGHTS, Bullet or ODE (the run's manifest names the engine)

#include <string>

#include "validation/calibration/calibration_spec.h"

namespace repose {

CalibrationSpec load_calibration(const std::string& path);
// The same from text; `pretend_path` is used in messages and to resolve relative paths.
CalibrationSpec load_calibration_from_string(const std::string& yaml, const std::string& pretend_path);

}  // namespace repose
