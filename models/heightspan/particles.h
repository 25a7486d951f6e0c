#pragma once
// Material in the air (the height-span paper, 2.4.2: material that leaves
// a span far above the ground "is made into particles and dropped"): a
// small ballistic particle system. Each particle carries a volume; it falls
// under gravity (no drag, no collisions between particles) and, when its
// path crosses a surface below it, adds its volume there: the material on a
// span (the highest one crossed) or the ground. A particle that leaves the
// grid sideways leaves the model (the ground ledger's left_grid_m3).
//
// The system is empty, and costs nothing, until something falls
// (ParticleSystem::built says whether anything ever did). Deterministic: the
// only random draw is the spread given at release, from the generator passed in.

#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "models/heightspan/span_map.h"

namespace repose {

struct GroundModel;
struct GroundState;

inline constexpr double kGravityMs2 = 9.81;

struct Particle {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
  double volume_m3 = 0.0;
};

struct ParticleSystem {
  bool built = false;  // something fell at some time
  std::vector<Particle> particles;
  long long released = 0;
  long long landed_on_spans = 0;
  long long landed_on_ground = 0;
  long long left_grid = 0;

  double in_flight_m3() const;
  // Adds a particle; spread_m_s: standard deviation of a horizontal velocity
  // added to it (drawn from `rng`).
  void release(Particle p, double spread_m_s, std::mt19937_64* rng);
};

// Advances every particle by dt and lands those that crossed a surface:
// onto the span maps (material added, overflow pushed up) or the ground
// (the cell joins the erosion memory).
void advance_particles(double dt_s, const GroundModel& model, std::vector<SpanMap*> maps, ParticleSystem* system,
                       GroundState* ground);

}  // namespace repose
