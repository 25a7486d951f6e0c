#include "validation/bullet/bullet_debris_world.h"

#include <btBulletDynamicsCommon.h>

#include <algorithm>
#include <vector>

#include "models/core/base/error.h"
#include "validation/bullet/bullet_globals.h"
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include "validation/rigid/debris_ledger.h"
#include "validation/rigid/rigid_world.h"

namespace repose {

namespace {

constexpr int kElementTag = 1;  // user index of element bodies
constexpr int kPartTag = 2;     // of building parts; the terrain has 0
// Bullet's mass unit is at least this many times the heaviest element's mass (header).
constexpr double kMassUnitsPerElement = 10.0;

btVector3 bt(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }
Eigen::Vector3d eig(const btVector3& v) { return {v.x(), v.y(), v.z()}; }

// The pair values debris_world.h states; bodies carry their own values.
btScalar pair_friction(const btCollisionObject* a, const btCollisionObject* b) {
  const bool ea = a->getUserIndex() == kElementTag, eb = b->getUserIndex() == kElementTag;
  if (ea && eb) return 0.5 * (a->getFriction() + b->getFriction());
  return ea ? a->getFriction() : b->getFriction();  // neither: both carry the building value
}
btScalar pair_restitution(const btCollisionObject* a, const btCollisionObject* b) {
  const bool ea = a->getUserIndex() == kElementTag, eb = b->getUserIndex() == kElementTag;
  if (ea && eb) return 0.5 * (a->getRestitution() + b->getRestitution());
  return ea ? a->getRestitution() : b->getRestitution();
}
double sphere_radius(const btCollisionObject* o) {
  return static_cast<const btSphereShape*>(o->getCollisionShape())->getRadius();
}
// Elements carry mu_r as rolling friction; Bullet wants the lever mu_r r_eff (rigid_world.h).
btScalar pair_rolling(const btCollisionObject* a, const btCollisionObject* b) {
  const bool ea = a->getUserIndex() == kElementTag, eb = b->getUserIndex() == kElementTag;
  if (!ea && !eb) return 0.0;
  if (ea && eb) {
    return rolling_lever_m(0.5 * (a->getRollingFriction() + b->getRollingFriction()), sphere_radius(a), sphere_radius(b));
  }
  // an element against the terrain or a building part: only the element is a sphere
  const btCollisionObject* element = ea ? a : b;
  return rolling_lever_m(element->getRollingFriction(), sphere_radius(element), 0.0);
}

class BulletDebrisWorld final : public DebrisWorld {
 public:
  BulletDebrisWorld(const DebrisWorldSpec& spec, const BulletOptions& options);
  ~BulletDebrisWorld() override;
  void step() override;
  double time_step_s() const override { return options_.rigid.time_step_s; }
  GrainSet elements() const override;
  std::vector<Pose> part_poses() const override;
  std::vector<bool> joints_broken() const override { return ledger_.joints_broken(); }
  std::vector<double> joint_forces_n() const override { return ledger_.joint_forces_n(); }
  std::vector<Eigen::Vector3d> part_element_forces_n() const override { return ledger_.part_forces_n(); }

 private:
  void set_globals() const;
  btRigidBody* add_body(btCollisionShape* shape, double mass_kg, const btVector3& inertia, const btVector3& at,
                        int tag, double friction, double restitution, double rolling);
  void add_terrain(const TriangleMesh& m, const DebrisMaterial& material);
  void add_plain(double height_m, const DebrisMaterial& material);
  void add_part(const DebrisPart& part, const DebrisMaterial& material, double margin_m);
  void add_joint(const DebrisJoint& joint);
  void add_element_forces_on_parts();

  BulletOptions options_;
  DebrisLedger ledger_;
  double kg_per_unit_ = 1.0;  // Bullet's mass unit (header): masses in Bullet are kg / kg_per_unit_
  double radius_m_;  // the largest element's
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_{&configuration_};
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_{&dispatcher_, &broadphase_, &solver_, &configuration_};
  std::vector<std::unique_ptr<btCollisionShape>> shapes_;
  std::unique_ptr<btTriangleIndexVertexArray> terrain_array_;
  std::vector<int> terrain_indices_;
  std::vector<btScalar> terrain_vertices_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<btRigidBody*> elements_;
  std::vector<btRigidBody*> parts_;
  std::vector<std::unique_ptr<btFixedConstraint>> joints_;
  std::vector<btJointFeedback> feedback_;  // per joint (sized once: the constraints point into it)
};

BulletDebrisWorld::BulletDebrisWorld(const DebrisWorldSpec& spec, const BulletOptions& options)
    : options_(options), ledger_(spec.joints, spec.parts.size()) {
  radius_m_ = 0.01;
  for (const DebrisElement& e : spec.elements) {
    radius_m_ = std::max(radius_m_, e.radius_m);
    kg_per_unit_ = std::max(kg_per_unit_, kMassUnitsPerElement * element_mass_kg(e));
  }
  set_globals();
  world_.setGravity(btVector3(0, 0, -spec.gravity_m_s2));
  btContactSolverInfo& info = world_.getSolverInfo();
  info.m_numIterations = options.rigid.solver_iterations;
  info.m_erp2 = options.erp;
  info.m_linearSlop = options.linear_slop_fraction * radius_m_;
  info.m_splitImpulse = true;
  info.m_splitImpulsePenetrationThreshold = -options.split_impulse_fraction * radius_m_;
  info.m_restitutionVelocityThreshold = options.rigid.restitution_velocity_threshold_m_s;
  if (options.friction_directions == 2) info.m_solverMode |= SOLVER_USE_2_FRICTION_DIRECTIONS;

  add_terrain(spec.terrain, spec.material);
  add_plain(spec.plain_height_m, spec.material);
  for (const DebrisElement& e : spec.elements) {
    const double mass = element_mass_kg(e) / kg_per_unit_;
    auto* sphere = shapes_.emplace_back(new btSphereShape(e.radius_m)).get();
    btVector3 inertia;
    sphere->calculateLocalInertia(mass, inertia);
    btRigidBody* body = add_body(sphere, mass, inertia, bt(e.centre_m), kElementTag, e.friction, e.restitution,
                                 e.rolling_friction);
    body->setLinearVelocity(bt(e.velocity_m_s));
    elements_.push_back(body);
  }
  // the parts' margin: a third of the smallest gap between parts, at most the options' margin
  double margin_m = options.shape_margin_fraction * radius_m_;
  for (std::size_t i = 0; i < spec.parts.size(); ++i) {
    for (std::size_t j = i + 1; j < spec.parts.size(); ++j) {
      const DebrisPart &a = spec.parts[i], &b = spec.parts[j];
      const double dz = std::abs(a.centre_m.z() - b.centre_m.z()) - a.half_extents_m.z() - b.half_extents_m.z();
      if (dz > 0.0) margin_m = std::min(margin_m, dz / 3.0);
    }
  }
  for (const DebrisPart& part : spec.parts) add_part(part, spec.material, margin_m);
  feedback_.resize(spec.joints.size());
  for (const DebrisJoint& joint : spec.joints) add_joint(joint);
}

void BulletDebrisWorld::add_terrain(const TriangleMesh& m, const DebrisMaterial& material) {
  terrain_indices_.assign(m.F.data(), m.F.data() + m.F.size());
  terrain_vertices_.assign(m.V.data(), m.V.data() + m.V.size());
  terrain_array_ = std::make_unique<btTriangleIndexVertexArray>(
      static_cast<int>(m.F.rows()), terrain_indices_.data(), 3 * sizeof(int), static_cast<int>(m.V.rows()),
      terrain_vertices_.data(), 3 * sizeof(btScalar));
  auto* shape = shapes_.emplace_back(new btBvhTriangleMeshShape(terrain_array_.get(), true)).get();
  shape->setMargin(options_.shape_margin_fraction * radius_m_);
  add_body(shape, 0.0, btVector3(0, 0, 0), btVector3(0, 0, 0), 0, material.building_friction,
           material.building_restitution, 0.0);
}

void BulletDebrisWorld::add_plain(double height_m, const DebrisMaterial& material) {
  auto* plane = shapes_.emplace_back(new btStaticPlaneShape(btVector3(0, 0, 1), height_m)).get();
  add_body(plane, 0.0, btVector3(0, 0, 0), btVector3(0, 0, 0), 0, material.building_friction,
           material.building_restitution, 0.0);
}

void BulletDebrisWorld::add_part(const DebrisPart& part, const DebrisMaterial& material, double margin_m) {
  auto* hull = new btConvexHullShape();
  for (Eigen::Index v = 0; v < part.hull_m.rows(); ++v) hull->addPoint(bt(Eigen::Vector3d(part.hull_m.row(v))), false);
  hull->recalcLocalAabb();
  hull->setMargin(margin_m);
  shapes_.emplace_back(hull);
  const Eigen::Vector3d s = 2.0 * part.half_extents_m;
  const double mass = part.mass_kg / kg_per_unit_;
  const double k = mass / 12.0;
  const btVector3 inertia(k * (s.y() * s.y() + s.z() * s.z()), k * (s.x() * s.x() + s.z() * s.z()),
                          k * (s.x() * s.x() + s.y() * s.y()));
  btRigidBody* body = add_body(hull, mass, inertia, bt(part.centre_m), kPartTag, material.building_friction,
                               material.building_restitution, 0.0);
  body->setUserIndex2(static_cast<int>(parts_.size()));  // the part's index
  parts_.push_back(body);
}

void BulletDebrisWorld::add_joint(const DebrisJoint& joint) {
  btRigidBody* a = parts_.at(static_cast<std::size_t>(joint.a));
  btRigidBody* b = joint.b < 0 ? &btTypedConstraint::getFixedBody() : parts_.at(static_cast<std::size_t>(joint.b));
  btTransform anchor(btQuaternion::getIdentity(), bt(joint.anchor_m));
  auto* c = joints_.emplace_back(new btFixedConstraint(*a, *b, a->getWorldTransform().inverse() * anchor,
                                                       b->getWorldTransform().inverse() * anchor)).get();
  c->setJointFeedback(&feedback_[joints_.size() - 1]);
  world_.addConstraint(c, true);
}

btRigidBody* BulletDebrisWorld::add_body(btCollisionShape* shape, double mass_kg, const btVector3& inertia,
                                         const btVector3& at, int tag, double friction, double restitution,
                                         double rolling) {
  btRigidBody::btRigidBodyConstructionInfo ci(mass_kg, nullptr, shape, inertia);
  ci.m_startWorldTransform = btTransform(btQuaternion::getIdentity(), at);
  ci.m_friction = friction;
  ci.m_restitution = restitution;
  ci.m_rollingFriction = rolling;
  btRigidBody* body = bodies_.emplace_back(new btRigidBody(ci)).get();
  body->setUserIndex(tag);
  body->setActivationState(DISABLE_DEACTIVATION);
  world_.addRigidBody(body);
  return body;
}

BulletDebrisWorld::~BulletDebrisWorld() {
  for (auto& c : joints_) world_.removeConstraint(c.get());
  for (auto& body : bodies_) world_.removeRigidBody(body.get());
}

void BulletDebrisWorld::set_globals() const {
  set_bullet_globals(options_, radius_m_, {pair_friction, pair_restitution, pair_rolling});
}

// The solver adds each joint row's force to its feedback; a joint whose
// linear force exceeds its threshold is disabled for the following steps.
// (Bullet's own setBreakingImpulseThreshold compares each row's impulse,
// the angular rows' too, so it would break on a torque component in N m s.)
void BulletDebrisWorld::step() {
  set_globals();
  for (btJointFeedback& f : feedback_) f = btJointFeedback();
  world_.stepSimulation(options_.rigid.time_step_s, 0, options_.rigid.time_step_s);
  ledger_.begin_step();
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    if (ledger_.broken(k)) continue;
    if (ledger_.record_joint(k, kg_per_unit_ * feedback_[k].m_appliedForceBodyA.length())) joints_[k]->setEnabled(false);
  }
  add_element_forces_on_parts();
}

// The solver applies +impulse along the normal on B to body A and its
// opposite to B, and the friction impulses along their directions to A
// (as BulletWorld::object_forces_n reads them).
void BulletDebrisWorld::add_element_forces_on_parts() {
  const double dt = options_.rigid.time_step_s;
  for (int m = 0; m < dispatcher_.getNumManifolds(); ++m) {
    const btPersistentManifold* manifold = dispatcher_.getManifoldByIndexInternal(m);
    const btCollisionObject *a = manifold->getBody0(), *b = manifold->getBody1();
    const bool part_a = a->getUserIndex() == kPartTag && b->getUserIndex() == kElementTag;
    const bool part_b = b->getUserIndex() == kPartTag && a->getUserIndex() == kElementTag;
    if (!part_a && !part_b) continue;
    const auto part = static_cast<std::size_t>((part_a ? a : b)->getUserIndex2());
    for (int p = 0; p < manifold->getNumContacts(); ++p) {
      const btManifoldPoint& pt = manifold->getContactPoint(p);
      const btVector3 on_a = pt.m_normalWorldOnB * pt.m_appliedImpulse + pt.m_lateralFrictionDir1 * pt.m_appliedImpulseLateral1 +
                             pt.m_lateralFrictionDir2 * pt.m_appliedImpulseLateral2;
      ledger_.add_part_force(part, (part_a ? kg_per_unit_ : -kg_per_unit_) / dt * eig(on_a));
    }
  }
}

GrainSet BulletDebrisWorld::elements() const {
  GrainSet out;
  const auto n = static_cast<Eigen::Index>(elements_.size());
  out.position_m.resize(n, 3);
  out.radius_m.resize(n);
  out.velocity_m_s.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const btRigidBody* b = elements_[static_cast<std::size_t>(i)];
    out.position_m.row(i) = eig(b->getWorldTransform().getOrigin()).transpose();
    out.velocity_m_s.row(i) = eig(b->getLinearVelocity()).transpose();
    out.radius_m(i) = sphere_radius(b);
  }
  return out;
}

std::vector<Pose> BulletDebrisWorld::part_poses() const {
  std::vector<Pose> out;
  for (const btRigidBody* b : parts_) {
    const btTransform& t = b->getWorldTransform();
    const btQuaternion q = t.getRotation();
    out.push_back({eig(t.getOrigin()), Eigen::Quaterniond(q.w(), q.x(), q.y(), q.z())});
  }
  return out;
}

}  // namespace

std::unique_ptr<DebrisWorld> make_bullet_debris_world(const DebrisWorldSpec& spec, const BulletOptions& options) {
  validate(options);
  return std::make_unique<BulletDebrisWorld>(spec, options);
}

}  // namespace repose
