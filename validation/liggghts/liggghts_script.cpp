#include "validation/liggghts/liggghts_script.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <set>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/liggghts/liggghts_free_body.h"
#include "validation/particles/chute_impact.h"
#include "validation/liggghts/liggghts_motion.h"
#include "validation/liggghts/liggghts_section.h"

namespace repose {

namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

bool is_prime(std::uint64_t n) {
  if (n < 2) return false;
  for (std::uint64_t d = 2; d * d <= n; ++d) {
    if (n % d == 0) return false;
  }
  return true;
}

std::string rolling_model_name(const DemSpec& dem) {
  return dem.rolling_model == DemSpec::RollingModel::kCdt ? "cdt" : "epsd2";
}

// Grain-wall contact: the grain-grain law without cohesion (grains do not stick to walls).
std::string wall_model(const DemSpec& dem) {
  return "model hertz tangential history rolling_friction " + rolling_model_name(dem);
}

std::string box_block(const DemDomain& d) {
  return fmt::format("{} {} {} {} {} {}", liggghts_number(d.x_min_m), liggghts_number(d.x_max_m),
                     liggghts_number(d.y_min_m), liggghts_number(d.y_max_m), liggghts_number(d.z_min_m),
                     liggghts_number(d.z_max_m));
}

// Atom types: 1 the grains (and every wall of their own material), then a
// rough floor when there is one, then a quarter column's frictionless
// symmetry walls when there are those. Only grains are atoms: the other
// types exist for their pair values with the grains. Per-type properties
// list the grains' values for every type.
bool rough_floor(const DemSpec& dem) { return dem.floor == DemSpec::Floor::kRough; }
bool symmetry_walls(const DemSpec& dem) {
  return dem.initial == DemSpec::Initial::kColumn && dem.column_shape == DemSpec::ColumnShape::kQuarterCylinder;
}
int floor_type(const DemSpec& dem) { return rough_floor(dem) ? 2 : 1; }
int symmetry_type(const DemSpec& dem) { return symmetry_walls(dem) ? floor_type(dem) + 1 : 1; }
int atom_type_count(const DemSpec& dem) { return std::max(floor_type(dem), symmetry_type(dem)); }

std::string per_type(const DemSpec& dem, double v) {
  std::string out = liggghts_number(v);
  for (int t = 2; t <= atom_type_count(dem); ++t) out += " " + liggghts_number(v);
  return out;
}

// A type-pair table: `grains` between grains, `floor` between a grain and
// the floor, `symmetry` between a grain and a symmetry wall; a pair of two
// wall types (which never meet) takes the value of the later one.
std::string per_type_pair(const DemSpec& dem, double grains, double floor, double symmetry) {
  const int count = atom_type_count(dem);
  std::string out = std::to_string(count);
  for (int a = 1; a <= count; ++a) {
    for (int b = 1; b <= count; ++b) {
      const int later = std::max(a, b);
      const double v = later == 1 ? grains : later == symmetry_type(dem) ? symmetry : floor;
      out += " " + liggghts_number(v);
    }
  }
  return out;
}

// "0 0 -1" on a level floor (every script's text before chutes) and while
// a chute's block settles, the tilted direction in a chute's run (dem_section.h).
std::string gravity_vector_text(const DemSpec& dem, bool settling) {
  if (dem.slope_deg == 0.0 || settling) return "0 0 -1";
  const Eigen::Vector3d g = gravity_direction(dem);
  return liggghts_number(g.x()) + " 0 " + liggghts_number(g.z());
}

bool periodic_sides(const DemSpec& dem) { return dem.sides == DemSpec::Sides::kPeriodic; }

// The box's boundaries: fixed, or periodic in y for a periodic strip.
std::string box_header(const DemSpec& dem) {
  return fmt::format("atom_style granular\natom_modify map array\nboundary f {} f\nnewton off\n"
                     "communicate single vel yes\nunits si\n",
                     periodic_sides(dem) ? "p" : "f");
}

// The neighbour list and memory sort. With the default options the lines
// are the ones every cached bed was made with (its cache key is the text).
void write_neighbor_settings(std::ostringstream& s, const DemSpec& dem, const LiggghtsOptions& o) {
  const double largest_radius_m = dem.grain_radius_m * (1.0 + dem.radius_spread);
  s << "neighbor " << liggghts_number(o.neighbor_skin_radii * largest_radius_m) << " bin\n"
    << "neigh_modify delay 0";
  if (o.neighbor_check_every_steps != 1) s << " every " << o.neighbor_check_every_steps << " check yes";
  s << "\n";
  if (o.sort_every_steps != LiggghtsOptions{}.sort_every_steps) s << "atom_modify sort " << o.sort_every_steps << " 0\n";
  s << "\n";
}

}  // namespace

std::string liggghts_contact_commands(const DemSpec& dem) {
  std::ostringstream s;
  const auto n = [](double v) { return liggghts_number(v); };
  s << "# materials (Young's modulus softened, as DEM practice does)"
    << (rough_floor(dem) ? "; type 2: the rough floor" : "")
    << (symmetry_walls(dem) ? fmt::format("; type {}: the frictionless symmetry walls", symmetry_type(dem)) : "")
    << "\n"
    << "fix m1 all property/global youngsModulus peratomtype " << per_type(dem, dem.youngs_modulus_pa) << "\n"
    << "fix m2 all property/global poissonsRatio peratomtype " << per_type(dem, dem.poisson_ratio) << "\n"
    << "fix m3 all property/global coefficientRestitution peratomtypepair "
    << per_type_pair(dem, dem.restitution, dem.restitution, dem.restitution) << "\n"
    << "fix m4 all property/global coefficientFriction peratomtypepair "
    << per_type_pair(dem, dem.friction, dem.friction, 0.0) << "\n"
    << "fix m5 all property/global coefficientRollingFriction peratomtypepair "
    << per_type_pair(dem, dem.rolling_friction, dem.floor_rolling_friction, 0.0) << "\n";
  const bool cohesive = dem.cohesion_energy_density_j_m3 > 0.0;
  if (cohesive) {
    s << "fix m6 all property/global cohesionEnergyDensity peratomtypepair "
      << per_type_pair(dem, dem.cohesion_energy_density_j_m3, 0.0, 0.0) << "\n";
  }
  // LIGGGHTS takes the sub-models in this order: model, tangential, cohesion, rolling_friction
  s << "\n# Hertz-Mindlin with tangential history and rolling friction\n"
    << "pair_style gran model hertz tangential history" << (cohesive ? " cohesion sjkr" : "")
    << " rolling_friction " << rolling_model_name(dem) << "\n"
    << "pair_coeff * *\n"
    << "timestep " << n(dem.time_step_s) << "\n";
  return s.str();
}

std::string liggghts_wall_model(const DemSpec& dem) { return wall_model(dem); }

namespace {

// Everything both scripts set after the box exists: contact law, materials,
// time step, gravity, the floor and side walls, integration.
void write_physics(std::ostringstream& s, const DemSpec& dem, const DemDomain& d, const LiggghtsOptions& neighbor,
                   bool settling) {
  const auto n = [](double v) { return liggghts_number(v); };
  write_neighbor_settings(s, dem, neighbor);
  s << liggghts_contact_commands(dem)
    << "fix gravity all gravity " << n(dem.gravity_m_s2) << " vector " << gravity_vector_text(dem, settling) << "\n\n"
    << "# floor and side walls on the ground grid's edges\n";
  const std::string wall = "all wall/gran " + wall_model(dem) + " primitive type 1";
  const std::string floor = "all wall/gran " + wall_model(dem) + " primitive type " + std::to_string(floor_type(dem));
  const std::string symmetry = "all wall/gran " + wall_model(dem) + " primitive type " + std::to_string(symmetry_type(dem));
  s << "fix wall_floor " << floor << " zplane " << n(d.z_min_m) << "\n"
    << "fix wall_xmin " << symmetry << " xplane " << n(d.x_min_m) << "\n"
    << "fix wall_xmax " << wall << " xplane " << n(d.x_max_m) << "\n";
  if (!periodic_sides(dem)) {
    s << "fix wall_ymin " << symmetry << " yplane " << n(d.y_min_m) << "\n"
      << "fix wall_ymax " << wall << " yplane " << n(d.y_max_m) << "\n";
  }
  s << "fix integrate all nve/sphere\n\n";
}

bool is_column(const DemSpec& dem) { return dem.initial == DemSpec::Initial::kColumn; }

// Height of the insertion region: grains are inserted loosely (at
// insert_volume_fraction) and fall. In a narrow column the walls keep grain
// centres a radius away, so the region is made taller by the ratio of the
// footprint to the area open to centres (a bed's is left as it is).
double fill_height_m(const Scene& scene, const BedScriptOptions& o) {
  const DemSpec& dem = *dem_of(scene);
  double factor = 1.0;
  if (is_column(dem)) {
    const ColumnGeometry c = column_geometry(scene);
    const double r = dem.grain_radius_m * (1.0 + dem.radius_spread);
    const double rho = c.width_m - r;  // axisymmetric: the radius open to centres
    double open = std::numbers::pi * rho * rho;
    if (c.shape == DemSpec::ColumnShape::kSlot) {
      open = (c.width_m - 2 * r) * (periodic_sides(dem) ? c.gap_m : c.gap_m - 2 * r);
    } else if (c.shape == DemSpec::ColumnShape::kQuarterCylinder) {
      open = 0.25 * std::numbers::pi * rho * rho - 2.0 * r * rho + r * r;  // less the strips along both walls
    }
    factor = c.footprint_m2 / open;
  }
  return settled_height_m(dem) * o.packing_fraction / o.insert_volume_fraction * factor;
}

// The region grains are inserted into and, for a column, the gate that holds them.
void write_insertion_region(std::ostringstream& s, const Scene& scene, const DemDomain& d, double fill_m) {
  const auto n = [](double v) { return liggghts_number(v); };
  const DemSpec& dem = *dem_of(scene);
  if (!is_column(dem)) {
    s << "region fill block " << n(d.x_min_m) << " " << n(d.x_max_m) << " " << n(d.y_min_m) << " " << n(d.y_max_m)
      << " 0 " << n(fill_m) << " units box\n";
    return;
  }
  const ColumnGeometry c = column_geometry(scene);
  const std::string wall = "all wall/gran " + wall_model(dem) + " primitive type 1";
  s << "# the column's gate (left out of the run script: removed at t = 0)\n";
  if (c.shape == DemSpec::ColumnShape::kSlot) {
    s << "fix gate " << wall << " xplane " << n(c.gate_x_m) << "\n"
      << "region fill block " << n(c.back_wall_x_m) << " " << n(c.gate_x_m) << " " << n(d.y_min_m) << " "
      << n(d.y_max_m) << " 0 " << n(fill_m) << " units box\n";
    return;
  }
  s << "fix gate " << wall << " zcylinder " << n(c.width_m) << " " << n(c.axis_xy_m.x()) << " " << n(c.axis_xy_m.y())
    << "\n";
  if (c.shape == DemSpec::ColumnShape::kCylinder) {
    s << "region fill cylinder z " << n(c.axis_xy_m.x()) << " " << n(c.axis_xy_m.y()) << " " << n(c.width_m) << " 0 "
      << n(fill_m) << " units box\n";
    return;
  }
  // the quarter between the symmetry walls: the cylinder cut by the quadrant x, y >= the axis
  s << "region fill_cylinder cylinder z " << n(c.axis_xy_m.x()) << " " << n(c.axis_xy_m.y()) << " " << n(c.width_m)
    << " 0 " << n(fill_m) << " units box\n"
    << "region fill_quadrant block " << n(c.axis_xy_m.x()) << " " << n(c.axis_xy_m.x() + c.width_m) << " "
    << n(c.axis_xy_m.y()) << " " << n(c.axis_xy_m.y() + c.width_m) << " 0 " << n(fill_m) << " units box\n"
    << "region fill intersect 2 fill_cylinder fill_quadrant units box\n";
}

}  // namespace

std::string liggghts_number(double v) {
  REPOSE_DEMAND(std::isfinite(v));
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  REPOSE_DEMAND(r.ec == std::errc());
  return {buf, r.ptr};
}

std::vector<std::uint64_t> liggghts_seeds(std::uint64_t scene_seed, int count) {
  std::vector<std::uint64_t> seeds;
  std::uint64_t state = scene_seed;
  while (static_cast<int>(seeds.size()) < count) {
    state = splitmix64(state);
    std::uint64_t candidate = 10007 + state % 100000000ULL;
    while (!is_prime(candidate)) ++candidate;
    if (std::find(seeds.begin(), seeds.end(), candidate) == seeds.end()) seeds.push_back(candidate);
  }
  return seeds;
}

std::vector<double> grain_radii_m(const DemSpec& dem) {
  if (dem.radius_spread == 0.0) return {dem.grain_radius_m};
  std::vector<double> radii;
  constexpr int kCount = 5;
  for (int k = 0; k < kCount; ++k) {
    radii.push_back(dem.grain_radius_m * (1.0 + dem.radius_spread * (2.0 * k / (kCount - 1) - 1.0)));
  }
  return radii;
}

double mean_grain_volume_m3(const DemSpec& dem) {
  const auto radii = grain_radii_m(dem);
  double sum = 0.0;
  for (double r : radii) sum += 4.0 / 3.0 * std::numbers::pi * r * r * r;
  return sum / static_cast<double>(radii.size());
}

long bed_grain_count(const Scene& scene, const BedScriptOptions& options) {
  const DemSpec& dem = require_dem(scene, "LIGGGHTS");
  const Grid& g = scene.ground.grid;
  const double footprint = is_column(dem) ? column_geometry(scene).footprint_m2 : g.extent_x_m() * g.extent_y_m();
  const double volume = footprint * settled_height_m(dem) * options.packing_fraction;
  return std::lround(volume / mean_grain_volume_m3(dem));
}

DemDomain bed_domain(const Scene& scene, const BedScriptOptions& options) {
  const DemSpec& dem = require_dem(scene, "LIGGGHTS");
  const Grid& g = scene.ground.grid;
  DemDomain d;
  d.x_min_m = g.origin_x_m;
  d.x_max_m = g.origin_x_m + g.extent_x_m();
  d.y_min_m = g.origin_y_m;
  d.y_max_m = g.origin_y_m + g.extent_y_m();
  d.z_min_m = 0.0;
  d.z_max_m = fill_height_m(scene, options) + 4.0 * dem.grain_radius_m;
  return d;
}

long bed_max_steps(const Scene& scene, const BedScriptOptions& options) {
  const DemSpec& dem = require_dem(scene, "LIGGGHTS");
  const long chunk = std::max(1L, liggghts_steps(options.settle_check_interval_s, dem.time_step_s));
  const long chunks = std::max(1L, std::lround(std::ceil(options.max_settle_time_s / options.settle_check_interval_s)));
  return 1 + chunk * chunks;
}

void write_settle_loop(std::ostringstream& s, const DemSpec& dem, const SettleLoop& loop) {
  const auto n = [](double v) { return liggghts_number(v); };
  s << "# settle until the kinetic energy falls below the threshold\n"
    << "variable settle_ke equal ke\n"
    << "label settle_loop\n"
    << "variable settle_i loop " << loop.chunks << "\n"
    << "run " << loop.chunk_steps << "\n"
    << "if \"${settle_ke} < " << n(dem.settle_kinetic_energy_j) << "\" then \"jump SELF settled\"\n"
    << "next settle_i\n"
    << "jump SELF settle_loop\n"
    << "print \"" << kFailureMarker << ": the " << loop.what << " did not settle below " << n(dem.settle_kinetic_energy_j)
    << " J within " << n(loop.max_settle_time_s) << " s\"\n"
    << "jump SELF finished\n"
    << "label settled\n"
    << "print \"" << kSettledMarker << "\"\n"
    << loop.settled_commands
    << "print \"" << kCompleteMarker << "\"\n"
    << "label finished\n";
}

std::string bed_script(const Scene& scene, const BedScriptOptions& options) {
  const DemSpec& dem = require_dem(scene, "LIGGGHTS");
  if (!(options.insert_volume_fraction > 0.0 && options.insert_volume_fraction < options.packing_fraction &&
        options.packing_fraction < 0.75)) {
    throw InputError("bed options: expected 0 < insert_volume_fraction < packing_fraction < 0.75");
  }
  const auto n = [](double v) { return liggghts_number(v); };
  const DemDomain d = bed_domain(scene, options);
  const auto radii = grain_radii_m(dem);
  const auto seeds = liggghts_seeds(scene.seed, static_cast<int>(radii.size()) + 2);
  const long grains = bed_grain_count(scene, options);
  if (grains > options.max_grain_count) {
    throw InputError(fmt::format(
        "{}: dem: the bed would hold {} grains, more than the limit of {}; use larger grains, a shallower bed "
        "(bed_depth_m) or a smaller ground grid",
        scene.source_path, grains, options.max_grain_count));
  }
  const long chunk = std::max(1L, liggghts_steps(options.settle_check_interval_s, dem.time_step_s));
  const long chunks = std::max(1L, std::lround(std::ceil(options.max_settle_time_s / options.settle_check_interval_s)));

  std::ostringstream s;
  // no scene name here: the script is the bed's cache key, and scenes that
  // differ only in their objects (same grid, grains and seed) share a bed
  s << "# repose: settled bed (generated; do not edit)\n"
    << box_header(dem)
    << "region domain block " << box_block(d) << " units box\n"
    << "create_box " << atom_type_count(dem) << " domain\n";
  write_physics(s, dem, d, LiggghtsOptions{}, true);
  s << "# grains: " << radii.size() << " radii, equal in number\n";
  for (std::size_t k = 0; k < radii.size(); ++k) {
    s << "fix pts" << k << " all particletemplate/sphere " << seeds[k] << " atom_type 1 density constant "
      << n(dem.density_kg_m3) << " radius constant " << n(radii[k]) << "\n";
  }
  s << "fix pdd all particledistribution/discrete/numberbased " << seeds[radii.size()] << " " << radii.size();
  for (std::size_t k = 0; k < radii.size(); ++k) s << " pts" << k << " " << n(1.0 / static_cast<double>(radii.size()));
  s << "\n";
  write_insertion_region(s, scene, d, fill_height_m(scene, options));
  s << "fix ins all insert/pack seed " << seeds[radii.size() + 1]
    << " distributiontemplate pdd maxattempt 200 insert_every once overlapcheck yes all_in yes"
    << " vel constant 0 0 0 region fill particles_in_region " << grains << " ntry_mc 100000\n\n"
    << "thermo_style custom step atoms ke\n"
    << "thermo " << std::max(1L, liggghts_steps(options.thermo_interval_s, dem.time_step_s)) << "\n"
    << "thermo_modify lost error norm no\n"
    << "run 1\nunfix ins\n\n";
  const std::string settled = std::string("write_restart ") + kBedRestartFile + "\n" + "dump bed all custom 1 " +
                              kBedDumpFile + " id type x y z radius\n" + "dump_modify bed sort id\nrun 0\nundump bed\n";
  write_settle_loop(s, dem, SettleLoop{chunk, chunks, "bed", options.max_settle_time_s, settled});
  return s.str();
}

namespace {

// The run's walls (the grid's extent, up to the highest point any object
// reaches), its box (the walls' extent grown in x and y to hold every
// object's whole motion: LIGGGHTS deletes the mesh elements whose centre
// lies outside the box, "mesh elements have been lost / left the domain")
// and each object's STL mesh at its start pose.
void place_objects(const Scene& scene, const DemSpec& dem, const RunScriptOptions& options, RunScript* out) {
  const Grid& g = scene.ground.grid;
  DemDomain& d = out->domain;
  d.x_min_m = g.origin_x_m;
  d.x_max_m = g.origin_x_m + g.extent_x_m();
  d.y_min_m = g.origin_y_m;
  d.y_max_m = g.origin_y_m + g.extent_y_m();
  // a column, once its gate is gone, only falls; a bed may be heaped up by the objects
  if (is_column(dem)) column_geometry(scene);  // refuses a column that does not fit, before any run
  double top = is_column(dem) ? 1.25 * dem.column_height_m : dem.bed_depth_m * 2.0;
  Aabb reached;  // by the keyframed objects
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const ObjectSpec& o = scene.objects[k];
    if (o.dynamic) top = std::max(top, free_sphere_top_m(o, dem.gravity_m_s2));  // an atom (liggghts_free_body.h)
    if (o.dynamic) continue;
    const Aabb swept = swept_bounds(o);
    reached.extend(swept.min);
    reached.extend(swept.max);
    top = std::max(top, swept.max.z());
    Pose start = o.pose_at(0.0);
    if (!rotates(o)) start = Pose{position_at(o, 0.0), o.keyframes.front().pose.orientation};
    out->meshes.push_back({fmt::format("object_{}.stl", k), fmt::format("obj{}", k), transformed(o.body, start)});
  }
  if (dem.slope_deg > 0.0) top = std::max(top, chute_splash_top_m(dem, scene.ground.grid));
  const double margin = options.top_margin_m > 0 ? options.top_margin_m : 8.0 * dem.grain_radius_m;
  d.z_max_m = top + margin;
  out->box = d;
  if (reached.empty()) return;
  // a side grows (by the margin beyond the object) only where an object crosses it
  if (reached.min.x() < d.x_min_m) out->box.x_min_m = reached.min.x() - margin;
  if (reached.max.x() > d.x_max_m) out->box.x_max_m = reached.max.x() + margin;
  if (reached.min.y() < d.y_min_m) out->box.y_min_m = reached.min.y() - margin;
  if (reached.max.y() > d.y_max_m) out->box.y_max_m = reached.max.y() + margin;
}

// The box after the restart: z up to the walls' top; x and y grown only
// when an object reaches beyond the walls (otherwise the line every run has had).
std::string change_box_line(const RunScript& out) {
  const auto n = [](double v) { return liggghts_number(v); };
  const DemDomain& d = out.domain;
  const DemDomain& b = out.box;
  std::string xy;
  if (b.x_min_m != d.x_min_m || b.x_max_m != d.x_max_m || b.y_min_m != d.y_min_m || b.y_max_m != d.y_max_m) {
    xy = fmt::format("x final {} {} y final {} {} ", n(b.x_min_m), n(b.x_max_m), n(b.y_min_m), n(b.y_max_m));
  }
  return fmt::format("change_box all {}z final {} {} units box\n", xy, n(d.z_min_m), n(d.z_max_m));
}

// The objects as granular walls; their force columns join the thermo line.
void write_object_walls(std::ostringstream& s, const RunScript& out, const DemSpec& dem, std::string* thermo) {
  if (out.meshes.empty()) return;
  s << "# objects: STL meshes (force on each in f_objK[1..3]) made granular walls\n";
  std::string ids;
  for (const LiggghtsMeshFile& m : out.meshes) {
    s << "fix " << m.fix_id << " all mesh/surface/stress file " << m.file_name << " type 1 stress on\n";
    ids += " " + m.fix_id;
    *thermo += fmt::format(" f_{0}[1] f_{0}[2] f_{0}[3]", m.fix_id);
  }
  s << "fix object_walls all wall/gran " << wall_model(dem) << " mesh n_meshes " << out.meshes.size() << " meshes"
    << ids << "\n\n";
}

}  // namespace

RunScript run_script(const Scene& scene, const RunScriptOptions& options) {
  const DemSpec& dem = require_dem(scene, "LIGGGHTS");
  RunScript out;
  place_objects(scene, dem, options, &out);
  const DemDomain& d = out.domain;
  const long thermo_every = std::max(1L, liggghts_steps(options.thermo_interval_s, dem.time_step_s));
  out.dump_interval_steps = std::max(1L, liggghts_steps(dem.dump_interval_s, dem.time_step_s));

  std::ostringstream s;
  s << "# repose: run of scene '" << scene.name << "' on a settled bed (generated; do not edit)\n"
    << box_header(dem)
    << "read_restart " << kBedRestartFile << "\n";
  write_physics(s, dem, d, liggghts_options_of(scene), false);
  s << "# per-atom restart data must be consumed by a run before the box may grow;\n"
    << "# after a restart, reset_timestep must come right before a run\n"
    << "reset_timestep 0\n"
    << "run 0\n"
    << change_box_line(out) << "\n";
  s << free_sphere_commands(scene, dem);
  std::string thermo = "thermo_style custom step atoms ke";
  write_object_walls(s, out, dem, &thermo);
  s << thermo << "\n"
    << "thermo " << thermo_every << "\n"
    << "thermo_modify lost error norm no\n"
    << "dump grains " << liggghts_dump_group(scene) << " custom " << out.dump_interval_steps << " " << kDumpDirectory
    << "/dump.*.txt id type x y z radius" << (measures_impact(dem) ? " vx vy vz" : "") << "\n"
    << "dump_modify grains sort id\n\n";
  std::vector<std::string> mesh_fix_ids;
  for (std::size_t k = 0, mesh = 0; k < scene.objects.size(); ++k) {  // a free sphere has no mesh: ""
    mesh_fix_ids.push_back(scene.objects[k].dynamic ? std::string() : out.meshes[mesh++].fix_id);
  }
  out.total_steps = write_motion(s, scene, dem, mesh_fix_ids);
  s << "print \"" << kCompleteMarker << "\"\n";
  out.text = s.str();
  return out;
}

}  // namespace repose
