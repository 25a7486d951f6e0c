#pragma once
// Ground material parameters of the ground model (and the models built on
// it). These are what the calibration fits, so they are plain values apart
// from the scene; a scene names its materials (scene.h) and the ground
// model's section says what each is made of (ground_section.h).

#include <string>

#include "models/core/config/yaml_reader.h"

namespace repose {

// Largest stable erosion sigma; the analysis is in models/ground/ground_params.h.
inline constexpr double kSigmaMax = 0.25;
// Most erosion passes a step may take (a bound on a step's time).
inline constexpr int kMaxErosionPasses = 1000;

struct Material {
  std::string name = "sand";
  // Fraction of the intersected height that is displaced to the contact
  // border; the rest (1 - alpha) is compressed away. [0, 1]
  double alpha = 1.0;
  // Angle of repose: slopes steeper than this erode. (0, pi/2] rad
  double repose_angle_rad = 0.5235987755982988;  // 30 deg
  // Fraction of the excess height difference moved per erosion pass.
  // (0, kSigmaMax]: above it erosion diverges (models/ground/ground_params.h).
  double sigma = 0.2;
  // Erosion passes per time step (En). >= 1
  int erosion_iterations = 5;
  // The cell size at which erosion_iterations holds, in m; 0: on any cell
  // (the paper's En, a count of passes). A pass moves sigma times a pair's
  // excess across the face between two cells: a diffusion with a
  // coefficient of about sigma h^2 per pass, so at a fixed count finer cells
  // move less per step, a quarter as far in area at half the cell. Above 0,
  // the passes on cells of size h are
  // max(1, round(erosion_iterations * (erosion_iterations_cell_m / h)^2)):
  // a step moves about as much on any grid (erosion_test.cpp: a column
  // sheds the same volume per step on 10, 5 and 2.5 mm cells at 4, 16 and
  // 64 passes), and a fit's En carries to other cell sizes. [0, 1] m
  double erosion_iterations_cell_m = 0.0;
  // What a dragging object compresses, as a ratio to what a pressing one
  // does (departure: the paper has one alpha for both). While an object
  // drags (moves sideways and not down: displacement.h), the fraction
  // displaced is 1 - drag_compaction_ratio * (1 - alpha), at least 0.
  // 1: the paper's model. Below 1: material pushed ahead of an object,
  // with a free surface in front, is compacted less than material pressed
  // into the confined bed beneath it, as the DEM references say (fitted
  // alone, pressing gives alpha 0.27 and dragging 0.92: calibration_*_only).
  // [0, 10]
  double drag_compaction_ratio = 1.0;

  // The fraction of the intersected height displaced (the rest is compressed).
  double displaced_fraction(bool dragging) const;

  // Erosion passes per time step on cells of this size (erosion_iterations_cell_m).
  int erosion_passes(double cell_size_m) const;

  bool operator==(const Material&) const = default;
};

// The presets of the ground paper: sand 30 deg / 1.0, mud 60 deg / 0.8,
// snow 90 deg / 0.0, sigma 0.2 each. Returns false for an unknown name.
bool material_preset(const std::string& name, Material* out);

// Throws FieldError (models/core/config/fields.h) naming the field when a
// value is outside its interval: alpha in [0, 1], repose_angle_rad in (0,
// pi/2], sigma in (0, kSigmaMax], erosion_iterations in [1, 1000],
// erosion_iterations_cell_m in [0, 1], drag_compaction_ratio in [0, 10]. The scene
// loader and the model both call this one rule.
void validate(const Material& material);

// The field list of a material (fields.h): alpha, repose_angle_deg, sigma,
// erosion_iterations, erosion_iterations_cell_m, drag_compaction_ratio.
template <class Visitor>
void material_fields(Visitor& v, Material& m) {
  v.number("alpha", m.alpha, Range::any());
  v.angle_deg("repose_angle_deg", m.repose_angle_rad, Range::any());
  v.number("sigma", m.sigma, Range::any());
  v.integer("erosion_iterations", m.erosion_iterations, IntRange{});
  v.number("erosion_iterations_cell_m", m.erosion_iterations_cell_m, Range::any());
  v.number("drag_compaction_ratio", m.drag_compaction_ratio, Range::any());
}

}  // namespace repose
