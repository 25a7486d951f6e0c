#pragma once
// What a paper sheet is and how it is held (the seed paper's sections 3.2
// and 4): its size and grammage, the mesh resolution, the fibre images that
// set its stiffness and mass, the grips that hold and pull it, a notch cut
// before pulling, gravity and damping. Validated once; the sheet's fixed
// description (sheet_model.h) is built from it. The fitted quantities
// (stiffness, tear strain) are SheetParams (sheet_params.h).
//
// The sheet lies in the plane z = 0 with its lower-left corner at the
// origin, x to the right, y up; the viewer looks from +z. The seed's
// experiment pulls "the right side towards the viewer and the left away":
// seed_twist_grips() below.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "models/tearing/fibre_options.h"

namespace repose {

// A grip holds every vertex whose rest position lies in its rectangle (edges
// included) and moves it at a constant velocity along the held axes; along
// the other axes the vertex moves freely (a roller).
struct GripSpec {
  double x_min_m = 0.0, x_max_m = 0.0, y_min_m = 0.0, y_max_m = 0.0;
  Eigen::Vector3d velocity_m_per_s = Eigen::Vector3d::Zero();
  std::array<bool, 3> held_axes = {true, true, true};  // x, y, z
};

// Which limit tears a cell (tear_limit.h): the seed's one strain for every
// mesh, a strain set by the energy per unit tear length and the cell size,
// or springs that soften past a fixed peak over a fixed opening set by that
// energy (cohesive_law.h).
enum class TearRule { kStrain, kEnergy, kCohesive };

struct SheetSpec {
  double width_m = 0.1;
  double height_m = 0.1;
  // Mass per area (kg/m^2); 0.08 is 80 g/m^2 office paper.
  double grammage_kg_per_m2 = 0.08;
  // Square cells across the width; the cells up the height follow, and
  // height_m must be a whole number of cells.
  int cells_x = 50;
  // Plate bending stiffness D (N m) of the sheet at mean fibre density;
  // 3e-4 N m is E t^3 / 12 for E = 4 GPa, t = 0.1 mm.
  double bending_stiffness_n_m = 3.0e-4;
  // Whether the sheet resists twist (sheet_model.h): true adds a term per
  // intact cell on its mixed second difference, so that the bending terms
  // are the isotropic plate of Poisson's ratio 0 (D/2 (k_xx^2 + k_yy^2 +
  // 2 k_xy^2)); false leaves the seed's bending along the mesh lines
  // alone, under which a twist w = kappa x y costs nothing. false is the
  // default: it is the seed's sheet and the one every fit and committed
  // experiment used, and the twist terms do not make the tear converge
  // under mesh refinement: measured, they make the grips' work per tear
  // length drift more (+27 % from 100 to 200 cells against +17 % without,
  // experiments/tearing_convergence_twist.yaml).
  bool twist_stiffness = false;
  // Spring constants scale as (relative fibre density)^exponent
  // (sheet_model.h); 1 is proportional. In [0, 8].
  double stiffness_density_exponent = 1.0;
  // A cell's tear strain is tear_strain x (relative fibre density)^exponent
  // (sheet_model.h); 0, the default, is the seed's single limit. In [0, 8].
  double tear_strain_density_exponent = 0.0;
  // The tear limit (tear_limit.h): kStrain, the default, is the seed's rule
  // (SheetParams::tear_strain on every mesh, so tearing depends on the
  // mesh); kEnergy sets the strain from SheetParams::tear_energy_j_per_m and
  // the cell size, so the work per unit tear length does not; kCohesive
  // (cohesive_law.h) softens each spring linearly from a peak at
  // SheetParams::tear_strain to zero force at a stretch (a material length,
  // the same on every mesh) set so that the law's area per unit tear length
  // is tear_energy_j_per_m, the softening work booked as fracture energy;
  // the explicit integrator only, and not with release_time_s > 0.
  TearRule tear_rule = TearRule::kStrain;
  // With fibre anisotropy a, a spring along the grain is (1 + a) stiffer; if
  // its tear strain stays the cell's, it tears holding (1 + a) times the
  // energy, so a tear's fracture energy follows the stiffness (measured:
  // across / along ~ (1 + a) / (1 - a), experiments/tearing_paper_fit.yaml).
  // true: each spring's tear strain is the cell's divided by sqrt of its
  // direction factor 1 + a cos 2(direction - grain), so every spring tears
  // holding the same energy whatever its direction (the fracture energy
  // isotropic, its strength ratio the square root of the stiffness ratio),
  // as the tear resistance of paper barely follows its fibre orientation.
  // false, the default: one strain per cell (the seed's rule).
  bool isotropic_tear_energy = false;
  // Velocity damping (1/s): each step v /= 1 + damping_per_s * dt (air drag
  // and internal losses lumped, applied implicitly so it never destabilises).
  double damping_per_s = 2.0e3;
  // Stiffness-proportional (Rayleigh beta, Kelvin-Voigt) damping time (s):
  // each spring also carries a dashpot of beta k along its axis, each
  // bending term one of beta k_b on the curvature rate, so a mode of angular
  // frequency w is damped at the rate beta w^2 / 2 (damping ratio beta w / 2),
  // where damping_per_s damps every mode alike: paper's internal friction,
  // a property of the material, so the same value on every mesh. Measured
  // as a cure for the drift of the grips' work per tear length under mesh
  // refinement (experiments/tearing_convergence_dashpots.yaml), it made the
  // drift larger, not smaller; the scenes leave it at 0. It shrinks the
  // explicit stable step (stable_time_step.h) to
  // (2 / w_max) (sqrt(1 + z^2) - z), z = beta w_max / 2. 0, the default, is
  // the seed's undamped springs. >= 0.
  double stiffness_damping_s = 0.0;
  // How long (s) a torn cell takes to let go: 0, the default, is the seed's
  // rule (every spring of the cell goes at once, its bending and twist terms
  // with it); > 0 fades the cell's springs, dashpots, twist term and its
  // share in the bending terms linearly from full strength at the step it
  // tears to nothing release_time_s later, so that a tear does not drop a
  // stretched cell in one step (a test of whether that sudden release,
  // radiating waves down to the grid scale, makes the grips' work per tear
  // length drift under mesh refinement: experiments/tearing_convergence_release.yaml).
  // The energy the fading cell gives up counts as fracture energy
  // (SheetState::torn_energy_j; its bending terms' as
  // SheetState::torn_bending_energy_j). The explicit integrator only.
  // >= 0 and finite.
  double release_time_s = 0.0;
  Eigen::Vector3d gravity_m_per_s2{0.0, -9.81, 0.0};
  // A cut from the top edge straight down at x = notch_x_m, notch_length_m
  // long (0: none): the cells it crosses start torn.
  double notch_length_m = 0.0;
  double notch_x_m = 0.05;
  std::vector<GripSpec> grips;
  FibreOptions fibres;

  int cells_y() const;  // height_m / cell size, rounded
  double cell_size_m() const { return width_m / cells_x; }

  // Throws FieldError (an InputError) naming the field and the rule (including a grip that
  // holds no vertex and two grips that hold the same vertex).
  void validate() const;
};

// The seed's experiment: two grips along the top edge, each `grip_depth_m`
// deep and reaching to within gap_m / 2 of the middle; the left one moves
// away from the viewer (-z) and the right one towards it (+z), both at
// speed_m_per_s, so the sheet tears down from the top between them.
std::vector<GripSpec> seed_twist_grips(double width_m, double height_m, double grip_depth_m, double gap_m,
                                       double speed_m_per_s);

}  // namespace repose
