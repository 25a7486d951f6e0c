#include "validation/liggghts/liggghts_free_body.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/liggghts/liggghts_script.h"

namespace repose {

namespace {

const char* shape_name(ObjectSpec::Shape s) {
  static const char* names[] = {"sphere", "box", "cylinder", "capsule", "mesh"};
  return names[static_cast<int>(s)];
}

double free_sphere_radius_m(const ObjectSpec& o) { return o.radius_m * o.scale.x(); }

std::string print_file(const ObjectSpec& o) { return "free_body_" + o.name + ".txt"; }

}  // namespace

void check_liggghts_free_bodies(const Scene& scene) {
  for (std::size_t k = 0; k < scene.objects.size(); ++k) {
    const ObjectSpec& o = scene.objects[k];
    if (!o.dynamic) continue;
    const bool uniform = o.scale.x() == o.scale.y() && o.scale.y() == o.scale.z();
    if (o.shape != ObjectSpec::Shape::kSphere || !uniform) {
      throw InputError(fmt::format(
          "LIGGGHTS: objects[{}] '{}' is a free {}{}: only a free sphere moves in LIGGGHTS here (meshes move "
          "kinematically only; a multisphere clump would stand in); run it with --solver bullet or ode",
          k, o.name, shape_name(o.shape), uniform ? "" : " scaled unevenly"));
    }
    if (!o.dynamic->torque_n_m.isZero()) {
      throw InputError(fmt::format(
          "LIGGGHTS: objects[{}] '{}': dynamic.torque_n_m is not applied in LIGGGHTS here (its free sphere is one "
          "grain, and LIGGGHTS has no per-atom torque fix); run it with --solver bullet, ode or ground",
          k, o.name));
    }
  }
}

double free_sphere_top_m(const ObjectSpec& o, double gravity_m_s2) {
  const double vz = std::max(0.0, o.dynamic->velocity_m_s.z());
  return o.dynamic->position_m.z() + free_sphere_radius_m(o) + vz * vz / (2.0 * gravity_m_s2);
}

std::string liggghts_dump_group(const Scene& scene) {
  const bool any = std::any_of(scene.objects.begin(), scene.objects.end(), [](const ObjectSpec& o) { return o.dynamic.has_value(); });
  return any ? "grains" : "all";
}

std::string free_sphere_commands(const Scene& scene, const DemSpec& dem) {
  check_liggghts_free_bodies(scene);
  if (liggghts_dump_group(scene) == "all") return "";
  const auto n = [](double v) { return liggghts_number(v); };
  const long every = std::max(1L, std::lround(kFreeBodyPrintInterval_s / dem.time_step_s));
  std::ostringstream s;
  s << "# free spheres: one granular atom each (type 1, the grains' material); groups are static,\n"
    << "# so `grains` holds the bed's grains only\n"
    << "group grains union all\n";
  int b = 0;
  for (const ObjectSpec& o : scene.objects) {
    if (!o.dynamic) continue;
    const DynamicBody& d = *o.dynamic;
    const double r = free_sphere_radius_m(o);
    const double density = o.mass_kg() / (4.0 / 3.0 * std::numbers::pi * r * r * r);
    const std::string g = fmt::format("free{}", b++);
    const Eigen::Vector3d &p = d.position_m, &v = d.velocity_m_s, &w = d.angular_velocity_rad_s;
    s << "create_atoms 1 single " << n(p.x()) << " " << n(p.y()) << " " << n(p.z()) << " units box\n"
      << "region " << g << " sphere " << n(p.x()) << " " << n(p.y()) << " " << n(p.z()) << " " << n(1e-3 * r)
      << " units box\n"
      << "group " << g << " region " << g << "\n"
      << "set group " << g << " diameter " << n(2.0 * r) << " density " << n(density) << "\n"
      << "set group " << g << " vx " << n(v.x()) << " vy " << n(v.y()) << " vz " << n(v.z()) << " omegax " << n(w.x())
      << " omegay " << n(w.y()) << " omegaz " << n(w.z()) << "\n"
      << "compute " << g << "_w " << g << " property/atom omegax omegay omegaz\n"
      << "compute " << g << " " << g << " reduce sum x y z vx vy vz fx fy fz c_" << g << "_w[1] c_" << g << "_w[2] c_"
      << g << "_w[3]\n";
    std::string line = "${" + g + "_step}";
    s << "variable " << g << "_step equal step\n";
    for (int c = 1; c <= 12; ++c) {
      s << "variable " << g << "_" << c << " equal c_" << g << "[" << c << "]\n";
      line += fmt::format(" ${{{}_{}}}", g, c);
    }
    s << "fix " << g << "_print all print " << every << " \"" << line << "\" file " << print_file(o)
      << " screen no title \"step x y z vx vy vz fx fy fz wx wy wz\"\n";
  }
  return s.str() + "\n";
}

std::vector<FreeBodyTrack> read_liggghts_free_bodies(const Scene& scene, const DemSpec& dem, const std::string& run_dir) {
  std::vector<ObjectSpec> bodies;
  for (const ObjectSpec& o : scene.objects) {
    if (o.dynamic) bodies.push_back(o);
  }
  std::vector<FreeBodyTrack> tracks = start_free_body_tracks(bodies);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    const std::string path = (std::filesystem::path(run_dir) / print_file(bodies[k])).string();
    std::ifstream in(path);
    if (!in) throw InputError(fmt::format("{}: LIGGGHTS printed no free-body file", path));
    std::string line;
    std::getline(in, line);  // title
    std::vector<FreeBodyTrack> one(1, tracks[k]);
    while (std::getline(in, line)) {
      std::istringstream row(line);
      double v[13];
      for (double& x : v) row >> x;
      if (!row) throw InputError(fmt::format("{}: a malformed line '{}'", path, line));
      FreeBodyState st;
      st.pose.position_m = {v[1], v[2], v[3]};
      st.velocity_m_s = {v[4], v[5], v[6]};
      st.angular_velocity_rad_s = {v[10], v[11], v[12]};
      const double t = v[0] * dem.time_step_s;
      if (!one[0].samples.empty() && !(t > one[0].samples.back().time_s)) continue;  // a repeated print
      record_free_bodies(one, t, {st}, dem.gravity_m_s2);
      // the printed total force plus the weight: the contact force at that step
      one[0].samples.back().contact_force_n = Eigen::Vector3d(v[7], v[8], v[9] + one[0].mass_kg * dem.gravity_m_s2);
    }
    if (one[0].samples.empty()) throw InputError(fmt::format("{}: no state printed", path));
    tracks[k] = std::move(one[0]);
  }
  return tracks;
}

}  // namespace repose
