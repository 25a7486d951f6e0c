#include "validation/rigid/rigid_reference.h"

#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "models/core/io/npy_io.h"
#include "validation/liggghts/liggghts_bed.h"
#include "validation/particles/particle_observables.h"
#include "validation/rigid/grain_file.h"
#include "validation/rigid/rigid_simulation.h"

namespace repose {

namespace fs = std::filesystem;

namespace {

// The resting force is the mean over this last fraction of the run.
constexpr double kRestingWindowFraction = 0.2;

nlohmann::json phase_json(const RigidPhaseSummary& s) {
  return {{"steps", s.steps},
          {"simulated_s", s.simulated_s},
          {"kinetic_energy_j", s.kinetic_energy_j},
          {"wall_time_s", s.wall_time_s},
          {"cpu_time_s", s.cpu_time_s}};
}

// "key=value" lines as {"key": number}.
nlohmann::json options_json(const std::string& text) {
  nlohmann::json json = nlohmann::json::object();
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    const std::string line = text.substr(start, end - start);
    const std::size_t eq = line.find('=');
    if (eq != std::string::npos) json[line.substr(0, eq)] = std::stod(line.substr(eq + 1));
    start = end == std::string::npos ? text.size() : end + 1;
  }
  return json;
}

void write_manifest(const std::string& path, const RigidReferenceResult& r) {
  nlohmann::json json = {{"engine", r.engine},
                         {"engine_version", r.engine_version},
                         {"options", options_json(r.engine_options)},
                         {"bed_cache_key", r.bed.key},
                         {"bed_from_cache", r.bed.from_cache},
                         {"grain_count", r.grain_count},
                         {"particle_steps_per_cpu_s", r.particle_steps_per_cpu_s},
                         {"bed", phase_json(r.bed.settle)},
                         {"run", phase_json(r.run)},
                         {"mass_held_kg", nlohmann::json::object()}};
  for (const auto& [name, kg] : r.mass_held_kg) json["mass_held_kg"][name] = kg;
  if (!r.free_bodies.empty()) json["free_bodies"] = free_bodies_json(r.free_bodies, r.free_body_rests);
  json.update(column_results_json(r.column, r.pile));
  json.update(chute_results_json(r.chute));
  std::ofstream out(path);
  out << json.dump(2) << "\n";
  if (!out) throw std::runtime_error(fmt::format("{}: write failed", path));
}

// Runout over the frames and, for a cylinder, the final pile's flank angles.
void measure_column(RigidReferenceResult& r, const RigidInputs& in, const std::vector<RigidFrame>& frames,
                    const RigidReferenceOptions& options) {
  std::vector<GrainSet> grains;
  std::vector<double> times;
  for (const RigidFrame& f : frames) {
    times.push_back(f.time_s);
    grains.push_back(f.grains);
  }
  r.column = measure_column_collapse(*in.column, r.grains_initial, grains, times, 2.0 * in.dem.grain_radius_m,
                                     options.column);
  if (in.column->shape == DemSpec::ColumnShape::kCylinder) {
    r.pile = pile_flank_angles(r.height_final, in.column->axis_xy_m, options.flank);
  }
}

// The impact on the wall (the first object) from the frames and its force every step.
void measure_chute(RigidReferenceResult& r, const ChuteGeometry& geometry, const std::vector<RigidFrame>& frames) {
  std::vector<GrainSet> grains;
  std::vector<double> times;
  for (const RigidFrame& f : frames) {
    times.push_back(f.time_s);
    grains.push_back(f.grains);
  }
  std::vector<double> force_x;
  for (const auto& sample : r.object_forces.force_n) force_x.push_back(sample.front().x());
  r.chute = measure_chute_impact(geometry, grains, times, r.object_forces.time_s, force_x);
}

void write_forces_csv(const std::string& path, const RigidForceTrack& track, const std::vector<std::string>& names) {
  std::ofstream out(path);
  out << "time_s";
  for (const std::string& name : names) out << fmt::format(",{0}_fx_n,{0}_fy_n,{0}_fz_n", name);
  out << "\n";
  for (std::size_t k = 0; k < track.time_s.size(); ++k) {
    out << fmt::format("{}", track.time_s[k]);
    for (const Eigen::Vector3d& f : track.force_n[k]) out << fmt::format(",{},{},{}", f.x(), f.y(), f.z());
    out << "\n";
  }
  if (!out) throw std::runtime_error(fmt::format("{}: write failed", path));
}

}  // namespace

RigidReferenceResult run_rigid_reference(const RigidEngine& engine, const RigidInputs& in,
                                         const RigidReferenceOptions& options) {
  validate(engine.rigid);
  RigidReferenceResult r;
  r.engine = engine.name;
  r.engine_version = engine.version;
  r.engine_options = engine.options_text;
  r.bed = settled_rigid_bed(engine, in, options.cache_dir.empty() ? default_cache_dir() : options.cache_dir);
  r.grains_initial = r.bed.grains;

  const RigidWorldSpec spec = run_world(in, r.bed.grains);
  const auto world = engine.make_world(spec);
  std::vector<RigidFrame> frames;
  r.free_bodies = start_free_body_tracks(spec.bodies);
  const RigidRecording recording{in.dem.dump_interval_s, &frames, &r.free_bodies, &r.object_forces,
                                 in.dem.gravity_m_s2};
  r.run = run_motion(*world, spec.objects, in.time.duration_s, recording);
  for (const ObjectSpec& o : spec.objects) r.object_forces.names.push_back(o.name);
  r.grains_final = world->grains();
  demand_no_grain_lost(r.grains_final, spec.bounds, engine.name, "the run");

  r.grain_count = static_cast<long>(r.grains_final.size());
  const double particle_steps = static_cast<double>(r.grain_count) * static_cast<double>(r.run.steps);
  r.particle_steps_per_cpu_s = r.run.cpu_time_s > 0.0 ? particle_steps / r.run.cpu_time_s : 0.0;
  SurfaceHeightOptions surface = options.surface;
  surface.probe_radius_m = in.dem.surface_probe_radius_m;
  r.height_initial = surface_height(r.grains_initial, in.grid, surface);
  r.height_final = surface_height(r.grains_final, in.grid, surface);
  r.material_per_area_final = material_per_area(r.grains_final, in.grid);
  for (std::size_t k = 0; k < spec.bodies.size(); ++k) {
    r.free_body_rests.push_back(free_body_rest(spec.bodies[k], r.free_bodies[k], r.height_initial, in.dem.gravity_m_s2,
                                               kRestingWindowFraction * in.time.duration_s));
  }
  for (const ObjectSpec& o : in.objects) {
    Pose end = o.pose_at(in.time.duration_s);
    for (const FreeBodyTrack& t : r.free_bodies) {
      if (t.name == o.name) end = t.samples.back().state.pose;
    }
    const TriangleMesh world_mesh = transformed(o.body, end);
    r.mass_held_kg.emplace_back(o.name, mass_held_by_object_kg(r.grains_final, world_mesh, in.dem.density_kg_m3));
  }
  r.held_mass = held_mass_series(in.objects, frames, in.dem.density_kg_m3);
  if (in.column) measure_column(r, in, frames, options);
  if (in.chute) measure_chute(r, *in.chute, frames);
  return r;
}

void write_rigid_reference(const RigidReferenceResult& r, const std::string& run_dir) {
  const fs::path dir(run_dir);
  write_npy_2d((dir / "height_initial.npy").string(), r.height_initial.heights());
  write_npy_2d((dir / "height_final.npy").string(), r.height_final.heights());
  write_npy_2d((dir / "material_per_area_final.npy").string(), r.material_per_area_final.heights());
  write_grains_npy((dir / "grains_initial.npy").string(), r.grains_initial);
  write_grains_npy((dir / "grains_final.npy").string(), r.grains_final);
  for (const FreeBodyTrack& t : r.free_bodies) write_free_body_csv((dir / ("free_body_" + t.name + ".csv")).string(), t);
  if (r.column) write_runout_csv((dir / "runout.csv").string(), *r.column);
  if (!r.held_mass.objects.empty()) write_held_mass_csv((dir / "held_mass.csv").string(), r.held_mass);
  if (r.pile) write_flank_angles_csv((dir / "pile_flank_angles.csv").string(), *r.pile);
  if (!r.object_forces.force_n.empty() && !r.object_forces.force_n.front().empty()) {
    write_forces_csv((dir / "forces.csv").string(), r.object_forces, r.object_forces.names);
  }
  if (r.chute) write_chute_impact_csv((dir / "chute_impact.csv").string(), *r.chute);
  write_manifest((dir / fmt::format("{}_manifest.json", r.engine)).string(), r);
}

}  // namespace repose
