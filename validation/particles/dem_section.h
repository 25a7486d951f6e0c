#pragma once
// The grains of a scene's particle references (`dem:`), shared by LIGGGHTS,
// Bullet and ODE: size distribution, material, contact law, the settled bed
// or column the run starts from, the floor. Defined here once with one field
// list and one validate(); each engine may add its own section for what has
// no equivalent in the others.
//
//   dem:
//     grain_radius_m: 0.002        # mean radius; radius_spread: relative half-width of a uniform spread
//     youngs_modulus_pa: 5.0e6     # softened, as DEM practice does
//     time_step_s: 1.0e-5          # refused above 20 % of the Rayleigh time of the smallest grain
//     initial: bed                 # bed | column | snowfall (LIGGGHTS) (column_shape slot | cylinder, column_width_m, column_height_m)
//     ...                          # see DemSpec

#include <memory>
#include <string>

#include <Eigen/Core>

#include "models/core/base/error.h"
#include "models/core/config/scene.h"
#include "models/core/config/scene_section.h"
#include "models/core/config/yaml_reader.h"

namespace repose {

// Grains and contact law of the DEM reference runs (LIGGGHTS), for scenes
// that are also run as a reference. Young's modulus is softened, as DEM
// practice does, to allow a practical time step.
struct DemSpec {
  double grain_radius_m = 0.002;
  double radius_spread = 0.1;          // relative half-width of a uniform radius distribution [0, 0.5)
  double density_kg_m3 = 2500.0;
  double youngs_modulus_pa = 5.0e6;    // softened
  double poisson_ratio = 0.3;
  double restitution = 0.5;            // (0, 1]
  double friction = 0.5;               // sliding, grain-grain and grain-wall
  double rolling_friction = 0.1;
  enum class RollingModel { kCdt, kEpsd2 };
  RollingModel rolling_model = RollingModel::kCdt;
  double cohesion_energy_density_j_m3 = 0.0;  // sjkr cohesion; 0: none
  double time_step_s = 1.0e-5;          // refused above 20 % of the Rayleigh time
  double bed_depth_m = 0.02;            // depth of the settled bed the ground is made of
  double settle_kinetic_energy_j = 1.0e-7;  // settling ends below this total kinetic energy
  double gravity_m_s2 = 9.81;
  double dump_interval_s = 0.01;

  // The grains the run starts from. bed: a settled layer of bed_depth_m over
  // the whole grid. column: a column of grains settled behind a gate that is
  // removed at t = 0 (column collapse, piles); bed_depth_m is then unused.
  // snowfall: no grains at first; grains rain onto the scene's objects from
  //   the directions of its snow: section and settle (LIGGGHTS only, the
  //   cohesive snow reference: validation/liggghts/snowfall_script.h).
  //   slot: quasi-2-D; the column fills x from the grid's x_min edge to
  //     x_min + column_width_m across the grid's whole y extent (the grid's
  //     y extent is the gap between the two side walls); the gate is the
  //     plane x = x_min + column_width_m.
  //   cylinder: axisymmetric; a cylinder of radius column_width_m on the
  //     grid's centre; the gate is the cylinder wall.
  //   quarter_cylinder: axisymmetric at a quarter of the grains: the
  //     quarter of a cylinder of radius column_width_m whose axis is the
  //     grid's (x_min, y_min) corner, between the x_min and y_min walls made
  //     frictionless (no sliding or rolling friction), so they act as the
  //     column's two planes of symmetry. LIGGGHTS only; the rigid engines
  //     refuse it.
  enum class Initial { kBed, kColumn, kSnowfall };
  Initial initial = Initial::kBed;
  enum class ColumnShape { kSlot, kCylinder, kQuarterCylinder };
  ColumnShape column_shape = ColumnShape::kCylinder;
  double column_width_m = 0.02;   // slot: length L0 along x; cylinder and quarter: radius R0
  double column_height_m = 0.04;  // H0, the settled column's intended height

  // The floor (z = 0). smooth: a plane of the grains' own material. rough: a
  // plane whose rolling friction with the grains is floor_rolling_friction,
  // standing in for the base of glued grains the column-collapse and pile
  // experiments use (single grains would otherwise roll far over a smooth plane).
  enum class Floor { kSmooth, kRough };
  Floor floor = Floor::kSmooth;
  double floor_rolling_friction = 1.0;  // rough floor only

  // The grid's y edges. walls: two side walls of the grains' own material
  // (a slot column's gap is between them). periodic: y repeats with the
  // grid's y extent as its period, a strip with no side walls, so a
  // quasi-2-D column collapses without wall friction (a channel far wider
  // than the strip). LIGGGHTS only; the rigid engines refuse it.
  enum class Sides { kWalls, kPeriodic };
  Sides sides = Sides::kWalls;

  // How the reference's surface height field is read off the grains
  // (surface_height.h): 0 takes the top of the grain over each cell centre;
  // > 0 lowers a probe sphere of this radius onto the packing, a smooth
  // surface whose cells are not each one grain's top. Scale-separated
  // references use about a grain diameter.
  double surface_probe_radius_m = 0.0;

  // A chute (chute_impact.h): the floor is inclined by slope_deg. The scene
  // stays bed-aligned (z normal to the floor, x down the slope) and gravity
  // is tilted instead, to g (sin slope, 0, -cos slope): the standard trick
  // that keeps an inclined floor's mesh out. 0: gravity along -z (the text
  // of every script is then the one before this field existed). The grains
  // settle under gravity along -z (one bed for every slope) and gravity
  // tilts at t = 0, when a column's gate is removed.
  double slope_deg = 0.0;  // [0, 80)
  // > 0: the run measures the impact of the flow on the scene's first object
  // (the wall at the chute's foot): flow depth and speed over the grains
  // whose centres lie in the window [face - gap - window, face - gap] along
  // x upstream of the object's upstream face, the force on the object over
  // time, the pressure and its coefficient against the Froude number.
  double impact_window_m = 0.0;
  double impact_window_gap_m = 0.0;  // from the object's upstream face to the window's downstream end
};


// Rayleigh time of the smallest grain (s): T_R = pi*r*sqrt(rho/G)/(0.1631*nu+0.8766),
// G = E/(2(1+nu)), r = grain_radius_m*(1 - radius_spread).
double rayleigh_time_s(const DemSpec& dem);
// The largest time step accepted: 20 % of the Rayleigh time.
inline constexpr double kMaxRayleighFraction = 0.2;

// Throws FieldError naming the field: non-positive or non-finite grain and
// contact parameters, a spread outside [0, 0.5), a time step above 20 % of
// the Rayleigh time (naming the largest allowed step).
void validate(const DemSpec& dem);
// The rules that involve the common scene too: a column must fit the grid
// and be at least two grains across (column_geometry.h); an impact window
// needs a first object that is not a free body. InputError.
void validate(const DemSpec& dem, const Scene& scene);

template <class Visitor>
void dem_fields(Visitor& v, DemSpec& d) {
  v.number("grain_radius_m", d.grain_radius_m, Range::any());
  v.number("radius_spread", d.radius_spread, Range::any());
  v.number("density_kg_m3", d.density_kg_m3, Range::any());
  v.number("youngs_modulus_pa", d.youngs_modulus_pa, Range::any());
  v.number("poisson_ratio", d.poisson_ratio, Range::any());
  v.number("restitution", d.restitution, Range::any());
  v.number("friction", d.friction, Range::any());
  v.number("rolling_friction", d.rolling_friction, Range::any());
  using R = DemSpec::RollingModel;
  v.choice("rolling_model", d.rolling_model, std::vector<std::pair<std::string, R>>{{"cdt", R::kCdt}, {"epsd2", R::kEpsd2}});
  v.number("cohesion_energy_density_j_m3", d.cohesion_energy_density_j_m3, Range::any());
  v.number("time_step_s", d.time_step_s, Range::any());
  v.number("bed_depth_m", d.bed_depth_m, Range::any());
  v.number("settle_kinetic_energy_j", d.settle_kinetic_energy_j, Range::any());
  v.number("gravity_m_s2", d.gravity_m_s2, Range::any());
  v.number("dump_interval_s", d.dump_interval_s, Range::any());
  using I = DemSpec::Initial;
  v.choice("initial", d.initial, std::vector<std::pair<std::string, I>>{{"bed", I::kBed}, {"column", I::kColumn}, {"snowfall", I::kSnowfall}});
  using C = DemSpec::ColumnShape;
  v.choice("column_shape", d.column_shape,
           std::vector<std::pair<std::string, C>>{
               {"slot", C::kSlot}, {"cylinder", C::kCylinder}, {"quarter_cylinder", C::kQuarterCylinder}});
  v.number("column_width_m", d.column_width_m, Range::any());
  v.number("column_height_m", d.column_height_m, Range::any());
  using F = DemSpec::Floor;
  v.choice("floor", d.floor, std::vector<std::pair<std::string, F>>{{"smooth", F::kSmooth}, {"rough", F::kRough}});
  v.number("floor_rolling_friction", d.floor_rolling_friction, Range::any());
  using S = DemSpec::Sides;
  v.choice("sides", d.sides, std::vector<std::pair<std::string, S>>{{"walls", S::kWalls}, {"periodic", S::kPeriodic}});
  v.number("surface_probe_radius_m", d.surface_probe_radius_m, Range::any());
  v.number("slope_deg", d.slope_deg, Range::any());
  v.number("impact_window_m", d.impact_window_m, Range::any());
  v.number("impact_window_gap_m", d.impact_window_gap_m, Range::any());
}

// Gravity's direction (unit): (sin slope, 0, -cos slope); (0, 0, -1) on a level floor.
Eigen::Vector3d gravity_direction(const DemSpec& dem);
// Does the run measure a chute impact (impact_window_m > 0)?
inline bool measures_impact(const DemSpec& dem) { return dem.impact_window_m > 0.0; }

class DemSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "dem";
  DemSpec spec;
  void write_yaml(YAML::Emitter& out) const override;
  std::string summary() const override;
};

// The scene's grains, or nullptr when it has no dem section.
const DemSpec* dem_of(const Scene& scene);
// The scene's grains, validated; InputError naming the scene and `solver`
// when it has no dem section.
const DemSpec& require_dem(const Scene& scene, const std::string& solver);
// The scene with this dem section (validated against it).
Scene with_dem(Scene scene, const DemSpec& dem);
// A copy of the scene with its dem section changed by change(DemSpec&).
template <class Change>
Scene with_dem_changed(Scene scene, Change change) {
  const DemSpec* current = dem_of(scene);
  REPOSE_DEMAND(current != nullptr);
  DemSpec dem = *current;
  change(dem);
  return with_dem(std::move(scene), dem);
}

SectionType dem_section_type();

}  // namespace repose
