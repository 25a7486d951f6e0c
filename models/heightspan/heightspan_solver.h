#pragma once
// `--solver heightspan`: the height-span model (models/heightspan) as a
// repose Solver, for scenes with a `heightspan:` section. Compiling builds
// the HeightSpanModel once; its parameters are the ground model's, by the
// same names ("sand.alpha", "sand.repose_angle_deg", "sand.sigma";
// models/ground/material_parameters.h), so a calibration fits them alike,
// and its own "intake_layer_m" (heightspan.intake_layer_m, m; ground_contact.h),
// "intake_fraction" (heightspan.intake_fraction, 1; ground_contact.h: Intake)
// and "wedge_fraction" (heightspan.wedge_fraction, 1; drag_wedge.h) and
// "lip_wedge_fraction" (heightspan.lip_wedge_fraction, 1; with wedge_source split) and
// "press_fraction" (heightspan.press_fraction, 1; drag_wedge.h) and
// "press_wedge_fraction" (heightspan.press_wedge_fraction, 1; drag_wedge.h) and "side_cut_m"
// (heightspan.side_cut_m, m; side_cut.h) and "over_lip_fraction"
// (heightspan.over_lip_fraction, 1; drag_wedge.h) and "release_speed_m_s"
// (heightspan.release_speed_m_s, m/s; span_erosion.h) and "shear_layer_m" (heightspan.shear_layer_m, m;
// ground_contact.h).
// A scene where no object holds material runs the ground model itself
// (simulate_ground) and builds no span map and no particles.
//
// A run returns the fields height_initial and height_final (m), and the
// measures steps, step_wall_s_median, step_wall_s_mean, contact_cells_total,
// volume.* (m^3: initial, ground_final, held_final, in_flight_final,
// compressed, left_grid, imbalance), ledger.max_abs_imbalance_m3 and
// ledger.max_relative_imbalance (over every step), per held object
// mass_held_kg.<object> (at the end, bulk_density_kg_m3 times the volume on
// its spans, named as the particle references name theirs),
// mass_held_max_kg.<object> and volume_held_m3.<object>, and particles.*
// (counts) and flows.* (m^3), and the series mass_held_kg.<object> (kg, at
// every step: the held_mass.csv column <object>_mass_kg). Run::details["built"] lists what was built:
// span maps (and by which path: heightspan.span_maps, cpu or osmesa depth
// peeling), the objects left on the ground path, whether particles were
// made; Run::stages the modules ("span-maps:cpu", "span-erosion",
// "particles", ...). With an output folder it writes
// held_mass.csv (per step: time, each held object's volume and mass, the
// particles' volume, the ledger's imbalance) and, every frame_interval_s,
// frames/frame_NNNN.png (frame_image.h) and frames/height_NNNN.npy (ground).

#include "models/core/solver/solver.h"

namespace repose {

class HeightSpanSolver final : public Solver {
 public:
  std::string name() const override { return "heightspan"; }
  std::string description() const override {
    return "the height-span model (models/heightspan): objects that scoop, carry and spill material";
  }
  std::vector<SectionType> sections() const override;
  // Also false for a scene with a free body (ground_model.h).
  bool can_run(const Scene& scene, std::string* why) const override;
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override;
};

}  // namespace repose
