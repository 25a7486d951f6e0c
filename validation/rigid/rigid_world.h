#pragma once
// What a rigid-body engine is asked to build and do, engine-independently:
// spheres for the grains, static boxes for the ground box (floor and side
// walls), kinematic bodies for the scene's objects, one contact law for
// every pair. Bullet (validation/bullet) and ODE (validation/ode) each
// implement RigidWorld; the settling, the run, the cache and the
// observables (rigid_simulation.h, rigid_bed_cache.h, rigid_reference.h)
// are written once against it.
//
// Pair values the engines must give each contact (their own combination
// rules, e.g. Bullet's product of the two bodies' frictions, are overridden):
//   sliding friction      law.friction for every pair
//   restitution           law.restitution for every pair
//   rolling resistance    a torque of at most mu_r * r_eff * N against rolling
//                         (LIGGGHTS' constant directional torque, `cdt`), with
//                         mu_r = law.rolling_friction (the floor's own value on a
//                         rough floor) and r_eff = r1 r2 / (r1 + r2) between two
//                         grains, the grain's radius against a wall or an object.
// Spin about the contact normal is not resisted (cdt has no spin term).

#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "models/core/config/scene.h"
#include "validation/particles/dem_section.h"
#include "validation/particles/free_body_track.h"
#include "models/core/geometry/triangle_mesh.h"
#include "validation/particles/grain_set.h"

namespace repose {

struct RigidContactLaw {
  double friction = 0.5;
  double restitution = 0.5;
  double rolling_friction = 0.1;  // mu_r (dimensionless)
};

// A static box of the ground box (or of a column's gate). The floor's top face is z = 0.
struct StaticBox {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();
  double rolling_friction = 0.1;  // mu_r against grains
  double yaw_rad = 0.0;           // turned about the vertical axis through its centre
};

// The inside of the ground box: grains outside it are lost.
struct RigidBounds {
  double x_min_m = 0, x_max_m = 0, y_min_m = 0, y_max_m = 0, z_top_m = 0;
};

struct RigidWorldSpec {
  GrainSet grains;                  // initial centres and radii
  // Initial velocities, #G by 3 each (m/s, rad/s); empty: at rest.
  MatrixX3dR velocity_m_s;
  MatrixX3dR angular_velocity_rad_s;
  double density_kg_m3 = 2500.0;
  double gravity_m_s2 = 9.81;
  Eigen::Vector3d gravity_direction = Eigen::Vector3d(0, 0, -1);  // unit; tilted on a chute (dem_section.h)
  RigidContactLaw law;
  std::vector<StaticBox> walls;     // floor first, then the side walls
  RigidBounds bounds;
  std::vector<ObjectSpec> objects;  // kinematic bodies, placed at pose_at(0); none while settling
  // Free bodies (dynamic set): rigid bodies of their mass, from their initial
  // pose and velocities, meeting grains, walls, objects and each other. A
  // mesh becomes its convex hull where the engine needs one (bullet_world.h).
  std::vector<ObjectSpec> bodies;
};

class RigidWorld {
 public:
  virtual ~RigidWorld() = default;
  // Where each kinematic object (spec order) must be at the end of the next
  // step; the engine moves it there during the step at constant velocity.
  virtual void set_object_poses(const std::vector<Pose>& end_of_step) = 0;
  // One fixed internal step.
  virtual void step() = 0;
  virtual double time_step_s() const = 0;
  // Centres, radii and velocities.
  virtual GrainSet grains() const = 0;
  // Translational plus rotational kinetic energy of the grains (J).
  virtual double kinetic_energy_j() const = 0;
  // The free bodies' states (spec.bodies order); empty without free bodies.
  virtual std::vector<FreeBodyState> free_bodies() const { return {}; }
  // The force (N) the grains exerted on each kinematic object (spec.objects
  // order) during the last step: the contact impulses on it over the step.
  virtual std::vector<Eigen::Vector3d> object_forces_n() const = 0;
};

using RigidWorldFactory = std::function<std::unique_ptr<RigidWorld>(const RigidWorldSpec&)>;

// The rolling lever mu_r * r_eff (m) of a grain of radius r_a against a
// grain of radius r_b, or against a wall or object when r_b is 0.
inline double rolling_lever_m(double mu_r, double r_a, double r_b) {
  return mu_r * (r_b > 0.0 ? r_a * r_b / (r_a + r_b) : r_a);
}

}  // namespace repose
