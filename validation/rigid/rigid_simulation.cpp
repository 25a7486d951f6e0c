#include "validation/rigid/rigid_simulation.h"

#include <time.h>

#include <chrono>
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace repose {

namespace {

// Wall and CPU time of a phase.
class PhaseClock {
 public:
  PhaseClock() : wall_(std::chrono::steady_clock::now()), cpu_(process_cpu_time_s()) {}
  void stop(RigidPhaseSummary& s) const {
    s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_).count();
    s.cpu_time_s = process_cpu_time_s() - cpu_;
  }

 private:
  std::chrono::steady_clock::time_point wall_;
  double cpu_;
};

}  // namespace

double process_cpu_time_s() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

RigidPhaseSummary settle(RigidWorld& world, double threshold_j, double check_interval_s, double max_time_s) {
  const PhaseClock clock;
  RigidPhaseSummary s;
  const double dt = world.time_step_s();
  const long steps_per_check = std::max(1L, std::lround(check_interval_s / dt));
  const long max_steps = std::lround(std::ceil(max_time_s / dt));
  s.kinetic_energy_j = world.kinetic_energy_j();
  while (s.steps < max_steps) {
    for (long k = 0; k < steps_per_check && s.steps < max_steps; ++k, ++s.steps) world.step();
    s.kinetic_energy_j = world.kinetic_energy_j();
    if (s.kinetic_energy_j < threshold_j) {
      s.settled = true;
      break;
    }
  }
  s.simulated_s = static_cast<double>(s.steps) * dt;
  clock.stop(s);
  return s;
}

RigidPhaseSummary run_motion(RigidWorld& world, const std::vector<ObjectSpec>& objects, double duration_s,
                             const RigidRecording& rec) {
  const PhaseClock clock;
  RigidPhaseSummary s;
  const double dt = world.time_step_s();
  const long steps = std::lround(std::ceil(duration_s / dt - 1e-9));
  const long steps_per_frame = rec.frame_interval_s > 0.0 ? std::max(1L, std::lround(rec.frame_interval_s / dt)) : steps;
  std::vector<Pose> poses(objects.size());
  if (rec.free_bodies) record_free_bodies(*rec.free_bodies, 0.0, world.free_bodies(), rec.gravity_m_s2);
  for (; s.steps < steps; ++s.steps) {
    const double t_end = static_cast<double>(s.steps + 1) * dt;
    for (std::size_t k = 0; k < objects.size(); ++k) poses[k] = objects[k].pose_at(t_end);
    world.set_object_poses(poses);
    world.step();
    if (rec.frames && ((s.steps + 1) % steps_per_frame == 0 || s.steps + 1 == steps)) {
      rec.frames->push_back({t_end, world.grains()});
    }
    if (rec.free_bodies) record_free_bodies(*rec.free_bodies, t_end, world.free_bodies(), rec.gravity_m_s2);
    if (rec.object_forces) {
      rec.object_forces->time_s.push_back(t_end);
      rec.object_forces->force_n.push_back(world.object_forces_n());
    }
  }
  s.simulated_s = static_cast<double>(s.steps) * dt;
  s.kinetic_energy_j = world.kinetic_energy_j();
  clock.stop(s);
  return s;
}

std::vector<ObjectSpec> kinematic_objects(const std::vector<ObjectSpec>& objects) {
  std::vector<ObjectSpec> out;
  for (const ObjectSpec& o : objects) {
    if (!o.dynamic) out.push_back(o);
  }
  return out;
}

std::vector<ObjectSpec> free_body_objects(const std::vector<ObjectSpec>& objects) {
  std::vector<ObjectSpec> out;
  for (const ObjectSpec& o : objects) {
    if (o.dynamic) out.push_back(o);
  }
  return out;
}

std::vector<long> lost_grains(const GrainSet& grains, const RigidBounds& b) {
  std::vector<long> lost;
  for (Eigen::Index g = 0; g < grains.size(); ++g) {
    const double r = grains.radius_m(g);
    const auto p = grains.position_m.row(g);
    const bool inside = p.allFinite() && p.x() >= b.x_min_m - r && p.x() <= b.x_max_m + r && p.y() >= b.y_min_m - r &&
                        p.y() <= b.y_max_m + r && p.z() >= -r;
    if (!inside) lost.push_back(static_cast<long>(g));
  }
  return lost;
}

void demand_no_grain_lost(const GrainSet& grains, const RigidBounds& bounds, const std::string& engine,
                          const std::string& phase) {
  const std::vector<long> lost = lost_grains(grains, bounds);
  if (lost.empty()) return;
  const auto p = grains.position_m.row(lost.front());
  throw std::runtime_error(fmt::format("{}: {} lost {} of {} grains (first: grain {} at ({}, {}, {}))", engine, phase,
                                       lost.size(), grains.size(), lost.front(), p.x(), p.y(), p.z()));
}

}  // namespace repose
