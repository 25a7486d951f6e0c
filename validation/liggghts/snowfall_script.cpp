#include "validation/liggghts/snowfall_script.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/initial_height.h"
#include "models/snow/snow_section.h"
#include "validation/liggghts/liggghts_motion.h"
#include "validation/liggghts/liggghts_section.h"

namespace repose {

namespace {

constexpr std::uint64_t kStreamSalt = 0x736e6f7766616c6cULL;  // "snowfall": not the heuristic's direction stream
constexpr double kLayerDiameters = 4.0;    // insertion layer thickness, grain diameters
constexpr double kClearanceDiameters = 4.0;  // above the highest object and twice the open depth
constexpr double kSettleCheckS = 0.02;

const SnowSpec& require_snow(const Scene& scene) {
  const SnowSection* snow = scene.section<SnowSection>();
  if (snow == nullptr) {
    throw InputError(fmt::format("{}: dem: initial: snowfall needs the scene's snow: section (directions, depth)",
                                 scene.source_path));
  }
  return snow->spec;
}

void check_scene(const Scene& scene, const DemSpec& dem) {
  if (dem.initial != DemSpec::Initial::kSnowfall) {
    throw InputError(fmt::format("{}: dem: initial: the snowfall script needs initial: snowfall", scene.source_path));
  }
  const HeightField ground = make_initial_height(scene);
  if (ground.heights().abs().maxCoeff() > 0.0) {
    throw InputError(fmt::format("{}: ground: initial_height: dem.initial snowfall needs a flat ground at height 0 "
                                 "(the DEM floor is z = 0)", scene.source_path));
  }
  for (const ObjectSpec& o : scene.objects) {
    if (o.dynamic) {
      throw InputError(fmt::format("{}: objects: '{}' is dynamic; dem.initial snowfall takes static objects only",
                                   scene.source_path, o.name));
    }
  }
}

// Highest point of any object at its t = 0 pose (0 without objects).
double objects_top_m(const std::vector<LiggghtsMeshFile>& meshes) {
  double top = 0.0;
  for (const LiggghtsMeshFile& m : meshes) {
    if (m.mesh.V.rows() > 0) top = std::max(top, m.mesh.V.col(2).maxCoeff());
  }
  return top;
}

SnowfallPlan plan_snowfall(const Scene& scene, const DemSpec& dem, const SnowSpec& snow, const SnowfallOptions& o,
                           const std::vector<Eigen::Vector3d>& directions, double objects_top, long max_grain_count) {
  const Grid& g = scene.ground.grid;
  SnowfallPlan p;
  p.open_depth_m = snow.options.snowfall.depth_between_m(0.0, scene.time.duration_s);
  const double area = g.extent_x_m() * g.extent_y_m();
  p.grain_count = std::lround(p.open_depth_m * area * o.packing_fraction / mean_grain_volume_m3(dem));
  if (p.grain_count < 1) {
    throw InputError(fmt::format("{}: snow: the snowfall ({} m on open ground) holds no grain of radius {} m",
                                 scene.source_path, p.open_depth_m, dem.grain_radius_m));
  }
  if (p.grain_count > max_grain_count) {
    throw InputError(fmt::format("{}: snow: the snowfall would rain {} grains, more than the limit of {}; use larger "
                                 "grains (dem.grain_radius_m), less snow or a smaller ground grid",
                                 scene.source_path, p.grain_count, max_grain_count));
  }
  const double diameter = 2.0 * dem.grain_radius_m * (1.0 + dem.radius_spread);
  p.layer_bottom_m = std::max(objects_top, 0.0) + 2.0 * p.open_depth_m + kClearanceDiameters * diameter;
  p.layer_top_m = p.layer_bottom_m + kLayerDiameters * diameter;
  p.domain = {g.origin_x_m, g.origin_x_m + g.extent_x_m(), g.origin_y_m, g.origin_y_m + g.extent_y_m(), 0.0,
              p.layer_top_m + kClearanceDiameters * diameter};
  // a stream's grains leave the layer before its next insertion
  const double layer_s = (p.layer_top_m - p.layer_bottom_m) / o.fall_speed_m_s;
  p.insert_every_steps = std::max(2L * o.stream_count, liggghts_steps(layer_s, dem.time_step_s));
  p.insert_steps = std::max(p.insert_every_steps, liggghts_steps(o.insert_time_s, dem.time_step_s));
  // the slowest stream's vertical speed brings its last grain down from the layer's top
  double slowest = 1.0;
  for (const Eigen::Vector3d& d : directions) slowest = std::min(slowest, -d.z());
  p.landing_steps = liggghts_steps(p.layer_top_m / (o.fall_speed_m_s * slowest), dem.time_step_s);
  p.settle_chunk_steps = std::max(1L, liggghts_steps(kSettleCheckS, dem.time_step_s));
  p.max_settle_chunks = std::max(1L, std::lround(std::ceil(o.max_settle_time_s / kSettleCheckS)));
  return p;
}

std::string box_block(const DemDomain& d) {
  const auto n = [](double v) { return liggghts_number(v); };
  return fmt::format("{} {} {} {} {} {}", n(d.x_min_m), n(d.x_max_m), n(d.y_min_m), n(d.y_max_m), n(d.z_min_m),
                     n(d.z_max_m));
}

int surface_type(const DemSpec& dem) { return dem.floor == DemSpec::Floor::kRough ? 2 : 1; }

void write_box_and_walls(std::ostringstream& s, const Scene& scene, const DemSpec& dem, const SnowfallOptions& o,
                         const SnowfallScript& out) {
  const auto n = [](double v) { return liggghts_number(v); };
  const LiggghtsOptions neighbor = liggghts_options_of(scene);
  s << "# repose: snowfall onto scene '" << scene.name << "' (generated; do not edit)\n"
    << "atom_style granular\natom_modify map array\nboundary p p f\nnewton off\n"
    << "communicate single vel yes\nunits si\n"
    << "region domain block " << box_block(out.plan.domain) << " units box\n"
    << "create_box " << surface_type(dem) << " domain\n"
    << "neighbor " << n(neighbor.neighbor_skin_radii * dem.grain_radius_m * (1.0 + dem.radius_spread)) << " bin\n"
    << "neigh_modify delay 0\n\n"
    << liggghts_contact_commands(dem) << "\n"
    << "# snow falls at its terminal speed: gravity acts on grains slower than " << n(o.fall_speed_m_s) << " m/s\n"
    << "variable fall_gz atom -mass*" << n(dem.gravity_m_s2) << "*((vx*vx+vy*vy+vz*vz)<"
    << n(o.fall_speed_m_s * o.fall_speed_m_s) << ")\n"
    << "fix fall all addforce 0 0 v_fall_gz\n\n"
    << "# the floor and the objects (type " << surface_type(dem) << ": the floor's material)\n"
    << "fix wall_floor all wall/gran " << liggghts_wall_model(dem) << " primitive type " << surface_type(dem)
    << " zplane 0\n";
  if (!out.meshes.empty()) {
    std::string ids;
    for (const LiggghtsMeshFile& m : out.meshes) {
      s << "fix " << m.fix_id << " all mesh/surface file " << m.file_name << " type " << surface_type(dem) << "\n";
      ids += " " + m.fix_id;
    }
    s << "fix object_walls all wall/gran " << liggghts_wall_model(dem) << " mesh n_meshes " << out.meshes.size()
      << " meshes" << ids << "\n";
  }
  s << "fix integrate all nve/sphere\n\n";
}

// Grain templates and one insertion stream per direction.
void write_streams(std::ostringstream& s, const Scene& scene, const DemSpec& dem, const SnowfallOptions& o,
                   const SnowfallScript& out) {
  const auto n = [](double v) { return liggghts_number(v); };
  const SnowfallPlan& p = out.plan;
  const auto radii = grain_radii_m(dem);
  const int streams = static_cast<int>(out.directions.size());
  const auto seeds = liggghts_seeds(scene.seed, static_cast<int>(radii.size()) + 1 + streams);
  s << "# grains: " << radii.size() << " radii, equal in number\n";
  for (std::size_t k = 0; k < radii.size(); ++k) {
    s << "fix pts" << k << " all particletemplate/sphere " << seeds[k] << " atom_type 1 density constant "
      << n(dem.density_kg_m3) << " radius constant " << n(radii[k]) << "\n";
  }
  s << "fix pdd all particledistribution/discrete/numberbased " << seeds[radii.size()] << " " << radii.size();
  for (std::size_t k = 0; k < radii.size(); ++k) s << " pts" << k << " " << n(1.0 / static_cast<double>(radii.size()));
  s << "\n\n# " << streams << " streams of " << p.grain_count << " grains over " << n(o.insert_time_s) << " s\n"
    << "region snow_layer block " << n(p.domain.x_min_m) << " " << n(p.domain.x_max_m) << " " << n(p.domain.y_min_m)
    << " " << n(p.domain.y_max_m) << " " << n(p.layer_bottom_m) << " " << n(p.layer_top_m) << " units box\n";
  const double seconds = static_cast<double>(p.insert_steps) * dem.time_step_s;
  for (int k = 0; k < streams; ++k) {
    const long count = p.grain_count / streams + (k < p.grain_count % streams ? 1 : 0);
    if (count == 0) continue;
    const Eigen::Vector3d v = o.fall_speed_m_s * out.directions[static_cast<std::size_t>(k)];
    const long start = 1 + k * p.insert_every_steps / streams;
    s << "fix snow" << k << " all insert/rate/region seed " << seeds[radii.size() + 1 + static_cast<std::size_t>(k)]
      << " distributiontemplate pdd nparticles " << count << " particlerate " << n(static_cast<double>(count) / seconds)
      << " insert_every " << p.insert_every_steps << " start " << start << " overlapcheck yes all_in yes vel constant "
      << n(v.x()) << " " << n(v.y()) << " " << n(v.z()) << " region snow_layer ntry_mc 10000\n";
  }
  s << "\n";
}

void write_run_and_settle(std::ostringstream& s, const DemSpec& dem, const SnowfallOptions& o, const SnowfallPlan& p) {
  s << "thermo_style custom step atoms ke\n"
    << "thermo " << p.settle_chunk_steps << "\n"
    << "thermo_modify lost error norm no\n"
    << "# grains enter, then the last ones land\n"
    << "run " << p.insert_steps + p.landing_steps << "\n\n";
  const std::string settled = std::string("dump snow all custom 1 ") + kSnowfallDumpFile +
                              " id type x y z radius\ndump_modify snow sort id\nrun 0\nundump snow\n";
  write_settle_loop(s, dem, SettleLoop{p.settle_chunk_steps, p.max_settle_chunks, "snow", o.max_settle_time_s, settled});
}

}  // namespace

std::vector<Eigen::Vector3d> snowfall_stream_directions(const Scene& scene, int count) {
  const SnowSpec& snow = require_snow(scene);
  std::mt19937_64 rng(scene.seed ^ kStreamSalt);
  return draw_snowfall_directions(snow.options.main_direction, snow.params.direction_spread_rad, count, &rng);
}

SnowfallScript snowfall_script(const Scene& scene, long max_grain_count) {
  const DemSpec& dem = require_dem(scene, "LIGGGHTS");
  const SnowSpec& snow = require_snow(scene);
  const SnowfallOptions o = snowfall_options_of(scene);
  check_scene(scene, dem);
  SnowfallScript out;
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const ObjectSpec& obj = scene.objects[k];
    out.meshes.push_back({fmt::format("object_{}.stl", k), fmt::format("obj{}", k), transformed(obj.body, obj.pose_at(0.0))});
  }
  out.directions = snowfall_stream_directions(scene, o.stream_count);
  out.plan = plan_snowfall(scene, dem, snow, o, out.directions, objects_top_m(out.meshes), max_grain_count);
  std::ostringstream s;
  write_box_and_walls(s, scene, dem, o, out);
  write_streams(s, scene, dem, o, out);
  write_run_and_settle(s, dem, o, out.plan);
  out.text = s.str();
  return out;
}

}  // namespace repose
