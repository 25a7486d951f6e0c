#pragma once
// A debris flow on generated terrain (issue 14, seed paper 003 sec. 4-5) as
// a rigid-body engine is asked to build it, engine-independently: the
// terrain mesh as one static triangle mesh, the moving elements as dynamic
// spheres (each with its layer's friction, restitution and density), and
// each building's convex parts as dynamic convex bodies held together by
// breakable fixed joints. Bullet (validation/bullet/bullet_debris_world.h)
// and ODE (validation/ode/ode_debris_world.h) implement DebrisWorld; the
// scene-to-spec step (debris_setup.h) and the run with its observables
// (debris_run.h) are written once against it.
//
// Pair values every engine gives a contact (their own combination rules are
// replaced):
//   element - element      the mean of the two elements' friction and restitution
//   element - terrain/part the element's own (its layer's)
//   part - part, part - terrain   DebrisMaterial (building_friction, building_restitution)
//   rolling resistance     a torque of at most mu_r r_eff N on elements
//                          (rigid_world.h), mu_r the element's own (the mean of
//                          the two between elements); none between parts
// Parts joined by a joint do not collide with each other while it holds
// (they start a gap apart; the joint carries the load); once it breaks they do.
//
// A joint breaks in the step after the force it carried exceeds its
// break_force_n: ODE reads each fixed joint's feedback force and destroys
// it; Bullet reads each constraint's linear feedback force and disables it
// (debris_ledger.h keeps the joints' state for both).

#include <functional>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "models/core/geometry/triangle_mesh.h"
#include "validation/particles/grain_set.h"

namespace repose {

struct DebrisElement {
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
  double radius_m = 0.5;
  double density_kg_m3 = 2500.0;
  double friction = 0.5;
  double restitution = 0.2;
  double rolling_friction = 0.1;  // mu_r
};

// A convex part, a vertical prism: its vertices relative to its centre
// (body frame, axes the world's at the start), its centre in the world, its
// mass. Rows 2i and 2i + 1 are the bottom and top of the footprint's vertex
// i, the footprint counter-clockwise seen from above (ODE builds the faces from this).
struct DebrisPart {
  MatrixX3dR hull_m;                     // 2n rows, n >= 3
  Eigen::Vector3d centre_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();  // of the hull's box: sizes the inertia
  double mass_kg = 0.0;
  int building = 0;
};

// A fixed joint between parts a and b (b = -1: part a to the ground) at anchor_m.
struct DebrisJoint {
  int a = 0;
  int b = -1;
  Eigen::Vector3d anchor_m = Eigen::Vector3d::Zero();
  double break_force_n = 1.0e7;
};

struct DebrisMaterial {
  double building_friction = 0.6;     // part against part or terrain
  double building_restitution = 0.0;
};

struct DebrisWorldSpec {
  TriangleMesh terrain;                 // static, faces counter-clockwise seen from above
  // A static horizontal plane at this height under and around the terrain:
  // the plain outside the outermost key contour, as the terrain's height
  // field has it (elements that leave the mesh land on it).
  double plain_height_m = 0.0;
  std::vector<DebrisElement> elements;
  std::vector<DebrisPart> parts;
  std::vector<DebrisJoint> joints;
  DebrisMaterial material;
  double gravity_m_s2 = 9.81;           // along -z
};

class DebrisWorld {
 public:
  virtual ~DebrisWorld() = default;
  virtual void step() = 0;
  virtual double time_step_s() const = 0;
  // Element centres, radii and velocities (spec order).
  virtual GrainSet elements() const = 0;
  // Each part's pose: its centre and orientation (spec order).
  virtual std::vector<Pose> part_poses() const = 0;
  // Per joint (spec order): broken yet.
  virtual std::vector<bool> joints_broken() const = 0;
  // Per joint: the magnitude of the force it carried in the last step (N; 0 once broken).
  virtual std::vector<double> joint_forces_n() const = 0;
  // Per part: the sum of the contact forces elements put on it in the last
  // step (N; the contact impulses / time step), world frame.
  virtual std::vector<Eigen::Vector3d> part_element_forces_n() const = 0;
};

using DebrisWorldFactory = std::function<std::unique_ptr<DebrisWorld>(const DebrisWorldSpec&)>;

}  // namespace repose
