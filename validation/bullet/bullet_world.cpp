#include "validation/bullet/bullet_world.h"

#include <btBulletDynamicsCommon.h>
#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include <algorithm>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/bullet/bullet_globals.h"
#include "validation/rigid/rigid_shape.h"

namespace repose {

namespace {

constexpr int kGrainTag = 1;  // btCollisionObject user index of grains

static_assert(sizeof(btScalar) == sizeof(double), "build against bullet-float64 (BT_USE_DOUBLE_PRECISION)");

bool is_grain(const btCollisionObject* o) { return o->getUserIndex() == kGrainTag; }
double grain_radius(const btCollisionObject* o) {
  return static_cast<const btSphereShape*>(o->getCollisionShape())->getRadius();
}

// The pair value: a grain's own against a grain, the other body's against a wall or object.
btScalar combined_friction(const btCollisionObject* a, const btCollisionObject* b) {
  return is_grain(b) ? a->getFriction() : b->getFriction();
}
btScalar combined_restitution(const btCollisionObject* a, const btCollisionObject* b) {
  return is_grain(b) ? a->getRestitution() : b->getRestitution();
}
// Bodies carry mu_r as their rolling friction; the pair gets the lever mu_r * r_eff.
btScalar combined_rolling(const btCollisionObject* a, const btCollisionObject* b) {
  if (!is_grain(a) && !is_grain(b)) return 0.0;
  if (!is_grain(a)) std::swap(a, b);
  if (is_grain(b)) return rolling_lever_m(a->getRollingFriction(), grain_radius(a), grain_radius(b));
  return rolling_lever_m(b->getRollingFriction(), grain_radius(a), 0.0);
}

btVector3 bt(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
btTransform bt(const Pose& p) {
  const Eigen::Quaterniond& q = p.orientation;
  return btTransform(btQuaternion(q.x(), q.y(), q.z(), q.w()), bt(p.position_m));
}

class BulletWorld final : public RigidWorld {
 public:
  BulletWorld(const RigidWorldSpec& spec, const BulletOptions& options);
  ~BulletWorld() override;
  void set_object_poses(const std::vector<Pose>& end_of_step) override;
  void step() override;
  double time_step_s() const override { return options_.rigid.time_step_s; }
  GrainSet grains() const override;
  double kinetic_energy_j() const override;
  std::vector<FreeBodyState> free_bodies() const override;
  std::vector<Eigen::Vector3d> object_forces_n() const override;

 private:
  void add_free_body(const ObjectSpec& object, const RigidContactLaw& law);
  btCollisionShape* free_body_shape(const ObjectSpec& object);
  void set_globals() const;
  btRigidBody* add_body(btCollisionShape* shape, double mass_kg, const btTransform& at, const RigidContactLaw& law,
                        double rolling_mu);
  btCollisionShape* object_shape(const ObjectSpec& object);
  btCollisionShape* own(btCollisionShape* shape) {
    shapes_.emplace_back(shape);
    return shape;
  }

  BulletOptions options_;
  double grain_radius_m_;  // the largest: sizes thresholds and margins
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &configuration_};
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::vector<std::unique_ptr<btTriangleIndexVertexArray>> mesh_arrays_;
  std::vector<std::vector<int>> mesh_indices_;
  std::vector<std::vector<btScalar>> mesh_vertices_;
  std::vector<std::unique_ptr<btMotionState>> motion_states_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;  // grains first, in spec order
  std::vector<btRigidBody*> grains_;
  std::vector<btRigidBody*> objects_;
  std::map<const btCollisionObject*, std::size_t> object_index_;
  std::vector<btRigidBody*> free_;
  std::vector<btVector3> free_torque_n_m_;  // per free body, applied before every step
};

BulletWorld::BulletWorld(const RigidWorldSpec& spec, const BulletOptions& options)
    : options_(options), grain_radius_m_(spec.grains.size() > 0 ? spec.grains.radius_m.maxCoeff() : 0.001) {
  REPOSE_DEMAND(spec.velocity_m_s.rows() == 0 || spec.velocity_m_s.rows() == spec.grains.size());
  REPOSE_DEMAND(spec.angular_velocity_rad_s.rows() == 0 || spec.angular_velocity_rad_s.rows() == spec.grains.size());
  set_globals();
  dispatcher_.setDispatcherFlags(0);  // the absolute breaking threshold, not one relative to each shape
  world_.setGravity(bt(Eigen::Vector3d(spec.gravity_m_s2 * spec.gravity_direction)));
  btContactSolverInfo& info = world_.getSolverInfo();
  info.m_numIterations = options.rigid.solver_iterations;
  info.m_erp2 = options.erp;
  info.m_linearSlop = options.linear_slop_fraction * grain_radius_m_;
  info.m_splitImpulse = true;
  info.m_splitImpulsePenetrationThreshold = -options.split_impulse_fraction * grain_radius_m_;
  info.m_restitutionVelocityThreshold = options.rigid.restitution_velocity_threshold_m_s;
  if (options.friction_directions == 2) info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;

  std::map<double, btCollisionShape*> spheres;  // one shape per radius
  for (Eigen::Index g = 0; g < spec.grains.size(); ++g) {
    const double r = spec.grains.radius_m(g);
    auto [it, fresh] = spheres.try_emplace(r, nullptr);
    if (fresh) it->second = own(new btSphereShape(r));
    const double mass = spec.density_kg_m3 * 4.0 / 3.0 * M_PI * r * r * r;
    btTransform at(btQuaternion::getIdentity(), bt(Eigen::Vector3d(spec.grains.position_m.row(g).transpose())));
    btRigidBody* body = add_body(it->second, mass, at, spec.law, spec.law.rolling_friction);
    body->setUserIndex(kGrainTag);
    if (spec.velocity_m_s.rows() > 0) body->setLinearVelocity(bt(Eigen::Vector3d(spec.velocity_m_s.row(g).transpose())));
    if (spec.angular_velocity_rad_s.rows() > 0) {
      body->setAngularVelocity(bt(Eigen::Vector3d(spec.angular_velocity_rad_s.row(g).transpose())));
    }
    grains_.push_back(body);
  }
  for (const StaticBox& wall : spec.walls) {
    btCollisionShape* box = own(new btBoxShape(bt(wall.half_extents_m)));
    box->setMargin(options.shape_margin_fraction * grain_radius_m_);
    add_body(box, 0.0, btTransform(btQuaternion(btVector3(0, 0, 1), wall.yaw_rad), bt(wall.centre_m)), spec.law,
             wall.rolling_friction);
  }
  for (const ObjectSpec& object : spec.objects) {
    auto& state = motion_states_.emplace_back(new btDefaultMotionState(bt(object.pose_at(0.0))));
    btRigidBody::btRigidBodyConstructionInfo ci(0.0, state.get(), object_shape(object));
    btRigidBody* body = bodies_.emplace_back(new btRigidBody(ci)).get();
    body->setCollisionFlags(body->getCollisionFlags() | btCollisionObject::CF_KINEMATIC_OBJECT);
    body->setActivationState(DISABLE_DEACTIVATION);
    body->setFriction(spec.law.friction);
    body->setRestitution(spec.law.restitution);
    body->setRollingFriction(spec.law.rolling_friction);
    world_.addRigidBody(body);
    objects_.push_back(body);
    object_index_[body] = objects_.size() - 1;
  }
  for (const ObjectSpec& object : spec.bodies) add_free_body(object, spec.law);
}

// A dynamic body of the object's mass: Bullet's primitive, or the convex
// hull of a mesh (Bullet moves no concave triangle mesh but through GImpact);
// its inertia is Bullet's (exact for sphere and box, the bounding box's for a hull).
void BulletWorld::add_free_body(const ObjectSpec& object, const RigidContactLaw& law) {
  REPOSE_DEMAND(object.dynamic.has_value());
  const DynamicBody& d = *object.dynamic;
  btRigidBody* body = add_body(free_body_shape(object), object.mass_kg(), bt(object.pose_at(0.0)), law,
                               law.rolling_friction);
  body->setLinearVelocity(bt(d.velocity_m_s));
  body->setAngularVelocity(bt(d.angular_velocity_rad_s));
  free_.push_back(body);
  free_torque_n_m_.push_back(bt(d.torque_n_m));
}

btCollisionShape* BulletWorld::free_body_shape(const ObjectSpec& object) {
  if (rigid_shape(object).kind != RigidShape::Kind::kMesh) return object_shape(object);
  auto* hull = new btConvexHullShape();
  for (Eigen::Index v = 0; v < object.body.V.rows(); ++v) {
    hull->addPoint(btVector3(object.body.V(v, 0), object.body.V(v, 1), object.body.V(v, 2)), false);
  }
  hull->recalcLocalAabb();
  hull->setMargin(options_.shape_margin_fraction * grain_radius_m_);
  return own(hull);
}

BulletWorld::~BulletWorld() {
  for (auto& body : bodies_) world_.removeRigidBody(body.get());
}

void BulletWorld::set_globals() const {
  set_bullet_globals(options_, grain_radius_m_, {combined_friction, combined_restitution, combined_rolling});
}

btRigidBody* BulletWorld::add_body(btCollisionShape* shape, double mass_kg, const btTransform& at,
                                   const RigidContactLaw& law, double rolling_mu) {
  btVector3 inertia(0, 0, 0);
  if (mass_kg > 0.0) shape->calculateLocalInertia(mass_kg, inertia);
  btRigidBody::btRigidBodyConstructionInfo ci(mass_kg, nullptr, shape, inertia);
  ci.m_startWorldTransform = at;
  ci.m_friction = law.friction;
  ci.m_restitution = law.restitution;
  ci.m_rollingFriction = rolling_mu;
  btRigidBody* body = bodies_.emplace_back(new btRigidBody(ci)).get();
  body->setActivationState(DISABLE_DEACTIVATION);
  world_.addRigidBody(body);
  return body;
}

btCollisionShape* BulletWorld::object_shape(const ObjectSpec& object) {
  const RigidShape s = rigid_shape(object);
  btCollisionShape* shape = nullptr;
  switch (s.kind) {
    case RigidShape::Kind::kSphere: return own(new btSphereShape(s.radius_m));
    case RigidShape::Kind::kBox: shape = own(new btBoxShape(bt(s.half_extents_m))); break;
    case RigidShape::Kind::kCylinder:
      shape = own(new btCylinderShapeZ(btVector3(s.radius_m, s.radius_m, s.half_height_m)));
      break;
    case RigidShape::Kind::kCapsule: return own(new btCapsuleShapeZ(s.radius_m, 2.0 * s.half_height_m));
    case RigidShape::Kind::kMesh: {
      const TriangleMesh& m = *s.mesh;
      auto& indices = mesh_indices_.emplace_back(m.F.data(), m.F.data() + m.F.size());
      auto& vertices = mesh_vertices_.emplace_back(m.V.data(), m.V.data() + m.V.size());
      auto& array = mesh_arrays_.emplace_back(new btTriangleIndexVertexArray(
          static_cast<int>(m.F.rows()), indices.data(), 3 * sizeof(int), static_cast<int>(m.V.rows()),
          vertices.data(), 3 * sizeof(btScalar)));
      shape = own(new btBvhTriangleMeshShape(array.get(), true));
      break;
    }
  }
  shape->setMargin(options_.shape_margin_fraction * grain_radius_m_);
  return shape;
}

void BulletWorld::set_object_poses(const std::vector<Pose>& end_of_step) {
  REPOSE_DEMAND(end_of_step.size() == objects_.size());
  for (std::size_t k = 0; k < objects_.size(); ++k) objects_[k]->getMotionState()->setWorldTransform(bt(end_of_step[k]));
}

void BulletWorld::step() {
  set_globals();
  // Bullet clears applied forces and torques at the end of stepSimulation
  for (std::size_t k = 0; k < free_.size(); ++k) free_[k]->applyTorque(free_torque_n_m_[k]);
  // maxSubSteps 0: exactly one step of this size, no time accumulator
  world_.stepSimulation(options_.rigid.time_step_s, 0, options_.rigid.time_step_s);
}

GrainSet BulletWorld::grains() const {
  GrainSet out;
  out.position_m.resize(static_cast<Eigen::Index>(grains_.size()), 3);
  out.radius_m.resize(static_cast<Eigen::Index>(grains_.size()));
  for (std::size_t g = 0; g < grains_.size(); ++g) {
    const btVector3& p = grains_[g]->getWorldTransform().getOrigin();
    out.position_m.row(static_cast<Eigen::Index>(g)) << p.x(), p.y(), p.z();
    out.radius_m(static_cast<Eigen::Index>(g)) = grain_radius(grains_[g]);
  }
  out.velocity_m_s.resize(out.size(), 3);
  for (std::size_t g = 0; g < grains_.size(); ++g) {
    const btVector3& v = grains_[g]->getLinearVelocity();
    out.velocity_m_s.row(static_cast<Eigen::Index>(g)) << v.x(), v.y(), v.z();
  }
  return out;
}

// The solver applies +impulse along the normal on B to body A and its
// opposite to B, and the friction impulses along their directions to A.
std::vector<Eigen::Vector3d> BulletWorld::object_forces_n() const {
  std::vector<Eigen::Vector3d> force(objects_.size(), Eigen::Vector3d::Zero());
  const double dt = options_.rigid.time_step_s;
  btCollisionDispatcher& dispatcher = const_cast<btCollisionDispatcher&>(dispatcher_);
  for (int m = 0; m < dispatcher.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher.getManifoldByIndexInternal(m);
    const auto a = object_index_.find(manifold->getBody0());
    const auto b = object_index_.find(manifold->getBody1());
    if (a == object_index_.end() && b == object_index_.end()) continue;
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& pt = manifold->getContactPoint(p);
      const btVector3 on_a = pt.m_normalWorldOnB * pt.m_appliedImpulse + pt.m_lateralFrictionDir1 * pt.m_appliedImpulseLateral1 +
                             pt.m_lateralFrictionDir2 * pt.m_appliedImpulseLateral2;
      const Eigen::Vector3d f(on_a.x() / dt, on_a.y() / dt, on_a.z() / dt);
      if (a != object_index_.end()) force[a->second] += f;
      if (b != object_index_.end()) force[b->second] -= f;
    }
  }
  return force;
}

double BulletWorld::kinetic_energy_j() const {
  double e = 0.0;
  for (const btRigidBody* b : grains_) {
    const btVector3 w = b->getAngularVelocity();
    const btVector3 i = b->getLocalInertia();  // a sphere: isotropic
    e += 0.5 * b->getLinearVelocity().length2() / b->getInvMass() + 0.5 * (i.x() * w.x() * w.x() + i.y() * w.y() * w.y() + i.z() * w.z() * w.z());
  }
  return e;
}

std::vector<FreeBodyState> BulletWorld::free_bodies() const {
  std::vector<FreeBodyState> out;
  for (const btRigidBody* b : free_) {
    const btTransform& t = b->getWorldTransform();
    const btQuaternion q = t.getRotation();
    const btVector3 &p = t.getOrigin(), v = b->getLinearVelocity(), w = b->getAngularVelocity();
    out.push_back({Pose{Eigen::Vector3d(p.x(), p.y(), p.z()), Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z())},
                   Eigen::Vector3d(v.x(), v.y(), v.z()), Eigen::Vector3d(w.x(), w.y(), w.z())});
  }
  return out;
}

}  // namespace

std::string bullet_version() { return fmt::format("Bullet {}.{} (double)", btGetVersion() / 100, btGetVersion() % 100); }

std::unique_ptr<RigidWorld> make_bullet_world(const RigidWorldSpec& spec, const BulletOptions& options) {
  validate(options);
  return std::make_unique<BulletWorld>(spec, options);
}

}  // namespace repose
