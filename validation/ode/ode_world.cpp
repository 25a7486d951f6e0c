#include "validation/ode/ode_world.h"

#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>
#include <vector>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/rigid/rigid_shape.h"

namespace repose {

namespace {

static_assert(sizeof(dReal) == sizeof(double), "ODE must be the double-precision build");

// What the near callback needs of a geom.
struct GeomInfo {
  bool grain = false;
  double radius_m = 0.0;      // grains
  double rolling_mu = 0.0;    // mu_r against grains
  bool free = false;          // a free body: meets walls, objects and other free bodies too
  double cfm_scale = 1.0;     // its contacts' CFM relative to the grains' (free bodies: grain mass / its mass)
  int object = -1;            // a kinematic object: its index (its contacts' forces are recorded)
};

void init_ode_once() {
  static std::once_flag once;
  std::call_once(once, [] { dInitODE2(0); });
  dAllocateODEDataForThread(dAllocateMaskAll);
}

class OdeWorld final : public RigidWorld {
 public:
  OdeWorld(const RigidWorldSpec& spec, const OdeOptions& options);
  ~OdeWorld() override;
  void set_object_poses(const std::vector<Pose>& end_of_step) override;
  void step() override;
  double time_step_s() const override { return options_.rigid.time_step_s; }
  GrainSet grains() const override;
  double kinetic_energy_j() const override;
  std::vector<FreeBodyState> free_bodies() const override;
  std::vector<Eigen::Vector3d> object_forces_n() const override;

 private:
  void add_free_body(const ObjectSpec& object, const RigidContactLaw& law);
  static void near_callback(void* self, dGeomID a, dGeomID b);
  void collide_pair(dGeomID a, dGeomID b);
  void add_grains(const RigidWorldSpec& spec);
  dGeomID object_geom(const ObjectSpec& object);
  void attach(dGeomID geom, const GeomInfo& info) {
    infos_.push_back(info);
    geoms_.push_back(geom);
  }

  OdeOptions options_;
  RigidContactLaw law_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  unsigned long random_seed_ = 0;
  std::vector<dGeomID> geoms_;       // in the order of infos_
  std::vector<GeomInfo> infos_;      // geom data points into this (reserved, never reallocated)
  std::vector<dBodyID> grains_;
  std::vector<double> grain_radius_m_;
  std::vector<dBodyID> objects_;
  std::vector<Pose> object_targets_;
  std::vector<dBodyID> free_;
  std::vector<Eigen::Vector3d> free_torque_n_m_;  // per free body, added before every step
  double grain_mass_kg_ = 0.0;  // of the largest grain: sizes a free body's contact softness
  std::vector<dTriMeshDataID> mesh_data_;
  std::vector<std::vector<double>> mesh_vertices_;
  std::vector<std::vector<dTriIndex>> mesh_indices_;
  std::vector<dContactGeom> scratch_;
  // The feedback of this step's grain-object contacts (stable addresses) and
  // each one's object and the grain's side (1 or 2).
  std::deque<dJointFeedback> feedback_;
  std::vector<std::pair<int, int>> feedback_object_side_;
};

OdeWorld::OdeWorld(const RigidWorldSpec& spec, const OdeOptions& options) : options_(options), law_(spec.law) {
  REPOSE_DEMAND(spec.velocity_m_s.rows() == 0 || spec.velocity_m_s.rows() == spec.grains.size());
  REPOSE_DEMAND(spec.angular_velocity_rad_s.rows() == 0 || spec.angular_velocity_rad_s.rows() == spec.grains.size());
  init_ode_once();
  world_ = dWorldCreate();
  const Eigen::Vector3d gravity = spec.gravity_m_s2 * spec.gravity_direction;
  dWorldSetGravity(world_, gravity.x(), gravity.y(), gravity.z());
  dWorldSetERP(world_, options.erp);
  dWorldSetCFM(world_, options.cfm);
  dWorldSetQuickStepNumIterations(world_, options.rigid.solver_iterations);
  dWorldSetAutoDisableFlag(world_, 0);
  const double r_max = spec.grains.size() > 0 ? spec.grains.radius_m.maxCoeff() : 0.001;
  grain_mass_kg_ = spec.density_kg_m3 * 4.0 / 3.0 * M_PI * r_max * r_max * r_max;
  dWorldSetContactSurfaceLayer(world_, options.surface_layer_fraction * r_max);
  space_ = dHashSpaceCreate(nullptr);
  const int min_level = static_cast<int>(std::floor(std::log2(2.0 * r_max)));
  dHashSpaceSetLevels(space_, min_level, min_level + 4);
  contacts_ = dJointGroupCreate(0);
  scratch_.resize(static_cast<std::size_t>(options.max_contacts_per_pair));
  infos_.reserve(static_cast<std::size_t>(spec.grains.size()) + spec.walls.size() + spec.objects.size() +
                 spec.bodies.size());

  add_grains(spec);
  for (const StaticBox& wall : spec.walls) {
    const Eigen::Vector3d size = 2.0 * wall.half_extents_m;
    dGeomID geom = dCreateBox(space_, size.x(), size.y(), size.z());
    dGeomSetPosition(geom, wall.centre_m.x(), wall.centre_m.y(), wall.centre_m.z());
    dMatrix3 turn;
    dRFromAxisAndAngle(turn, 0, 0, 1, wall.yaw_rad);
    dGeomSetRotation(geom, turn);
    attach(geom, {false, 0.0, wall.rolling_friction});
  }
  for (const ObjectSpec& object : spec.objects) {
    dBodyID body = dBodyCreate(world_);
    dBodySetKinematic(body);
    dGeomID geom = object_geom(object);
    dGeomSetBody(geom, body);
    GeomInfo info{false, 0.0, spec.law.rolling_friction};
    info.object = static_cast<int>(objects_.size());
    attach(geom, info);
    const Pose p = object.pose_at(0.0);
    dBodySetPosition(body, p.position_m.x(), p.position_m.y(), p.position_m.z());
    const dQuaternion q = {p.orientation.w(), p.orientation.x(), p.orientation.y(), p.orientation.z()};
    dBodySetQuaternion(body, q);
    objects_.push_back(body);
    object_targets_.push_back(p);
  }
  for (const ObjectSpec& object : spec.bodies) add_free_body(object, spec.law);
  for (std::size_t k = 0; k < geoms_.size(); ++k) dGeomSetData(geoms_[k], &infos_[k]);
}

void OdeWorld::add_grains(const RigidWorldSpec& spec) {
  for (Eigen::Index g = 0; g < spec.grains.size(); ++g) {
    const double r = spec.grains.radius_m(g);
    dBodyID body = dBodyCreate(world_);
    dMass mass;
    dMassSetSphereTotal(&mass, spec.density_kg_m3 * 4.0 / 3.0 * M_PI * r * r * r, r);
    dBodySetMass(body, &mass);
    dBodySetPosition(body, spec.grains.position_m(g, 0), spec.grains.position_m(g, 1), spec.grains.position_m(g, 2));
    if (spec.velocity_m_s.rows() > 0) dBodySetLinearVel(body, spec.velocity_m_s(g, 0), spec.velocity_m_s(g, 1), spec.velocity_m_s(g, 2));
    if (spec.angular_velocity_rad_s.rows() > 0) {
      const auto w = spec.angular_velocity_rad_s.row(g);
      dBodySetAngularVel(body, w(0), w(1), w(2));
    }
    dGeomID geom = dCreateSphere(space_, r);
    dGeomSetBody(geom, body);
    attach(geom, {true, r, spec.law.rolling_friction});
    grains_.push_back(body);
    grain_radius_m_.push_back(r);
  }
}

// The mass of a primitive is ODE's exact one; a mesh's is its bounding box's
// of the same mass (ODE's own trimesh mass needs the centre of mass at the
// body origin, which a scene mesh need not have).
void OdeWorld::add_free_body(const ObjectSpec& object, const RigidContactLaw& law) {
  REPOSE_DEMAND(object.dynamic.has_value());
  const DynamicBody& d = *object.dynamic;
  const RigidShape s = rigid_shape(object);
  const double m = object.mass_kg();
  dMass mass;
  switch (s.kind) {
    case RigidShape::Kind::kSphere: dMassSetSphereTotal(&mass, m, s.radius_m); break;
    case RigidShape::Kind::kBox: {
      const Eigen::Vector3d size = 2.0 * s.half_extents_m;
      dMassSetBoxTotal(&mass, m, size.x(), size.y(), size.z());
      break;
    }
    case RigidShape::Kind::kCylinder: dMassSetCylinderTotal(&mass, m, 3, s.radius_m, 2.0 * s.half_height_m); break;
    case RigidShape::Kind::kCapsule: dMassSetCapsuleTotal(&mass, m, 3, s.radius_m, 2.0 * s.half_height_m); break;
    case RigidShape::Kind::kMesh: {
      const Eigen::Vector3d size = object.body.V.colwise().maxCoeff() - object.body.V.colwise().minCoeff();
      dMassSetBoxTotal(&mass, m, size.x(), size.y(), size.z());
      break;
    }
  }
  dBodyID body = dBodyCreate(world_);
  dBodySetMass(body, &mass);
  dGeomID geom = object_geom(object);
  dGeomSetBody(geom, body);
  attach(geom, {false, 0.0, law.rolling_friction, true, std::min(1.0, grain_mass_kg_ / m)});
  const Pose p = object.pose_at(0.0);
  dBodySetPosition(body, p.position_m.x(), p.position_m.y(), p.position_m.z());
  const dQuaternion q = {p.orientation.w(), p.orientation.x(), p.orientation.y(), p.orientation.z()};
  dBodySetQuaternion(body, q);
  dBodySetLinearVel(body, d.velocity_m_s.x(), d.velocity_m_s.y(), d.velocity_m_s.z());
  dBodySetAngularVel(body, d.angular_velocity_rad_s.x(), d.angular_velocity_rad_s.y(), d.angular_velocity_rad_s.z());
  free_.push_back(body);
  free_torque_n_m_.push_back(d.torque_n_m);
}

OdeWorld::~OdeWorld() {
  dJointGroupDestroy(contacts_);
  dSpaceDestroy(space_);  // destroys its geoms (cleanup mode on)
  for (dTriMeshDataID data : mesh_data_) dGeomTriMeshDataDestroy(data);
  dWorldDestroy(world_);
}

dGeomID OdeWorld::object_geom(const ObjectSpec& object) {
  const RigidShape s = rigid_shape(object);
  switch (s.kind) {
    case RigidShape::Kind::kSphere: return dCreateSphere(space_, s.radius_m);
    case RigidShape::Kind::kBox: {
      const Eigen::Vector3d size = 2.0 * s.half_extents_m;
      return dCreateBox(space_, size.x(), size.y(), size.z());
    }
    case RigidShape::Kind::kCylinder: return dCreateCylinder(space_, s.radius_m, 2.0 * s.half_height_m);
    case RigidShape::Kind::kCapsule: return dCreateCapsule(space_, s.radius_m, 2.0 * s.half_height_m);
    case RigidShape::Kind::kMesh: break;
  }
  const TriangleMesh& m = *s.mesh;
  auto& vertices = mesh_vertices_.emplace_back(m.V.data(), m.V.data() + m.V.size());
  auto& indices = mesh_indices_.emplace_back();
  for (Eigen::Index k = 0; k < m.F.size(); ++k) indices.push_back(static_cast<dTriIndex>(m.F.data()[k]));
  dTriMeshDataID data = mesh_data_.emplace_back(dGeomTriMeshDataCreate());
  dGeomTriMeshDataBuildDouble(data, vertices.data(), 3 * sizeof(double), static_cast<int>(m.V.rows()), indices.data(),
                              static_cast<int>(indices.size()), 3 * sizeof(dTriIndex));
  return dCreateTriMesh(space_, data, nullptr, nullptr, nullptr);
}

void OdeWorld::near_callback(void* self, dGeomID a, dGeomID b) { static_cast<OdeWorld*>(self)->collide_pair(a, b); }

void OdeWorld::collide_pair(dGeomID a, dGeomID b) {
  const auto* ia = static_cast<const GeomInfo*>(dGeomGetData(a));
  const auto* ib = static_cast<const GeomInfo*>(dGeomGetData(b));
  const bool rolling = ia->grain || ib->grain;  // rolling resistance is the grains' (rigid_world.h)
  if (!rolling && !ia->free && !ib->free) return;  // walls and kinematic objects do not meet
  const int n = dCollide(a, b, static_cast<int>(scratch_.size()), scratch_.data(), sizeof(dContactGeom));
  if (n == 0) return;
  const double lever = !rolling              ? 0.0
                       : ia->grain && ib->grain ? rolling_lever_m(ia->rolling_mu, ia->radius_m, ib->radius_m)
                       : ia->grain            ? rolling_lever_m(ib->rolling_mu, ia->radius_m, 0.0)
                                              : rolling_lever_m(ia->rolling_mu, ib->radius_m, 0.0);
  for (int k = 0; k < n; ++k) {
    dContact c{};
    c.geom = scratch_[static_cast<std::size_t>(k)];
    c.surface.mode = dContactApprox1 | dContactBounce | (rolling ? dContactRolling | dContactAxisDep : 0);
    // ODE's CFM is an absolute compliance: a free body many grains heavy would sink into it
    // and lose its bounce (rebound 0.67 e at 33 g), so its contacts are as stiff relative to its mass as a grain's
    if (ia->free || ib->free) {
      c.surface.mode |= dContactSoftCFM;
      c.surface.soft_cfm = options_.cfm * std::min(ia->cfm_scale, ib->cfm_scale);
    }
    c.surface.mu = c.surface.mu2 = law_.friction;
    c.surface.bounce = law_.restitution;
    c.surface.bounce_vel = options_.rigid.restitution_velocity_threshold_m_s;
    c.surface.rho = c.surface.rho2 = lever;
    c.surface.rhoN = 0.0;
    dJointID joint = dJointCreateContact(world_, contacts_, &c);
    dJointAttach(joint, dGeomGetBody(a), dGeomGetBody(b));
    // the force on an object is the opposite of the grain's (a kinematic body's own is not reliable)
    if ((ia->object >= 0 && ib->grain) || (ib->object >= 0 && ia->grain)) {
      dJointSetFeedback(joint, &feedback_.emplace_back());
      feedback_object_side_.emplace_back(ia->object >= 0 ? ia->object : ib->object, ia->grain ? 1 : 2);
    }
  }
}

void OdeWorld::set_object_poses(const std::vector<Pose>& end_of_step) {
  REPOSE_DEMAND(end_of_step.size() == objects_.size());
  const double dt = options_.rigid.time_step_s;
  for (std::size_t k = 0; k < objects_.size(); ++k) {
    const Pose& from = object_targets_[k];
    const Pose& to = end_of_step[k];
    const Eigen::Vector3d v = (to.position_m - from.position_m) / dt;
    const Eigen::AngleAxisd turn(to.orientation * from.orientation.conjugate());
    const Eigen::Vector3d w = turn.axis() * (turn.angle() / dt);
    dBodySetLinearVel(objects_[k], v.x(), v.y(), v.z());
    dBodySetAngularVel(objects_[k], w.x(), w.y(), w.z());
    object_targets_[k] = to;
  }
}

void OdeWorld::step() {
  dRandSetSeed(random_seed_);
  // ODE zeroes each body's force and torque accumulators after a step
  for (std::size_t k = 0; k < free_.size(); ++k) {
    const Eigen::Vector3d& t = free_torque_n_m_[k];
    dBodyAddTorque(free_[k], t.x(), t.y(), t.z());
  }
  feedback_.clear();
  feedback_object_side_.clear();
  dSpaceCollide(space_, this, &OdeWorld::near_callback);
  dWorldQuickStep(world_, options_.rigid.time_step_s);
  dJointGroupEmpty(contacts_);
  random_seed_ = dRandGetSeed();
  // kinematic objects end exactly where their keyframes say
  for (std::size_t k = 0; k < objects_.size(); ++k) {
    const Pose& p = object_targets_[k];
    dBodySetPosition(objects_[k], p.position_m.x(), p.position_m.y(), p.position_m.z());
    const dQuaternion q = {p.orientation.w(), p.orientation.x(), p.orientation.y(), p.orientation.z()};
    dBodySetQuaternion(objects_[k], q);
  }
}

GrainSet OdeWorld::grains() const {
  GrainSet out;
  out.position_m.resize(static_cast<Eigen::Index>(grains_.size()), 3);
  out.radius_m.resize(static_cast<Eigen::Index>(grains_.size()));
  out.velocity_m_s.resize(out.size(), 3);
  for (std::size_t g = 0; g < grains_.size(); ++g) {
    const dReal* p = dBodyGetPosition(grains_[g]);
    const dReal* v = dBodyGetLinearVel(grains_[g]);
    out.position_m.row(static_cast<Eigen::Index>(g)) << p[0], p[1], p[2];
    out.velocity_m_s.row(static_cast<Eigen::Index>(g)) << v[0], v[1], v[2];
    out.radius_m(static_cast<Eigen::Index>(g)) = grain_radius_m_[g];
  }
  return out;
}

std::vector<Eigen::Vector3d> OdeWorld::object_forces_n() const {
  std::vector<Eigen::Vector3d> force(objects_.size(), Eigen::Vector3d::Zero());
  std::size_t k = 0;
  for (const dJointFeedback& fb : feedback_) {
    const auto [object, side] = feedback_object_side_[k++];
    const dReal* on_grain = side == 1 ? fb.f1 : fb.f2;
    force[static_cast<std::size_t>(object)] -= Eigen::Vector3d(on_grain[0], on_grain[1], on_grain[2]);
  }
  return force;
}

double OdeWorld::kinetic_energy_j() const {
  double e = 0.0;
  for (std::size_t g = 0; g < grains_.size(); ++g) {
    dMass m;
    dBodyGetMass(grains_[g], &m);
    const dReal* v = dBodyGetLinearVel(grains_[g]);
    const dReal* w = dBodyGetAngularVel(grains_[g]);
    const double inertia = 0.4 * m.mass * grain_radius_m_[g] * grain_radius_m_[g];
    e += 0.5 * m.mass * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]) + 0.5 * inertia * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
  }
  return e;
}

std::vector<FreeBodyState> OdeWorld::free_bodies() const {
  std::vector<FreeBodyState> out;
  for (dBodyID b : free_) {
    const dReal *p = dBodyGetPosition(b), *q = dBodyGetQuaternion(b);
    const dReal *v = dBodyGetLinearVel(b), *w = dBodyGetAngularVel(b);
    out.push_back({Pose{Eigen::Vector3d(p[0], p[1], p[2]), Eigen::Quaterniond(q[0], q[1], q[2], q[3])},
                   Eigen::Vector3d(v[0], v[1], v[2]), Eigen::Vector3d(w[0], w[1], w[2])});
  }
  return out;
}

}  // namespace

std::string ode_version() {
  // ODE has no version call; the build's pkg-config version is passed by CMake
  return fmt::format("ODE {} (double)", REPOSE_ODE_VERSION);
}

std::unique_ptr<RigidWorld> make_ode_world(const RigidWorldSpec& spec, const OdeOptions& options) {
  validate(options);
  return std::make_unique<OdeWorld>(spec, options);
}

}  // namespace repose
