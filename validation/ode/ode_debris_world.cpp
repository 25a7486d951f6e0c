#include "validation/ode/ode_debris_world.h"

#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <mutex>
#include <vector>

#include "models/core/base/error.h"
#include "validation/rigid/debris_ledger.h"
#include "validation/rigid/rigid_world.h"

namespace repose {

namespace {

struct GeomInfo {
  enum class Kind { kTerrain, kElement, kPart } kind = Kind::kTerrain;
  double radius_m = 0.0;  // elements
  double friction = 0.0;
  double restitution = 0.0;
  double mass_kg = 0.0;   // 0: static
  double rolling_mu = 0.0;  // elements
  int part = -1;            // parts: the index
};

void init_ode_once() {
  static std::once_flag once;
  std::call_once(once, [] { dInitODE2(0); });
  dAllocateODEDataForThread(dAllocateMaskAll);
}

// A convex prism's planes and faces (debris_world.h: rows 2i, 2i + 1 are bottom and top of vertex i).
struct ConvexData {
  std::vector<double> points;
  std::vector<double> planes;
  std::vector<unsigned int> polygons;
};

ConvexData prism_convex(const MatrixX3dR& hull) {
  ConvexData c;
  c.points.assign(hull.data(), hull.data() + hull.size());
  const auto n = static_cast<unsigned int>(hull.rows() / 2);
  const double half_h = hull(1, 2);
  c.planes.insert(c.planes.end(), {0.0, 0.0, 1.0, half_h});
  c.polygons.push_back(n);
  for (unsigned int i = 0; i < n; ++i) c.polygons.push_back(2 * i + 1);
  c.planes.insert(c.planes.end(), {0.0, 0.0, -1.0, half_h});
  c.polygons.push_back(n);
  for (unsigned int i = n; i-- > 0;) c.polygons.push_back(2 * i);
  for (unsigned int i = 0; i < n; ++i) {
    const unsigned int j = (i + 1) % n;
    const Eigen::Vector2d e(hull(2 * j, 0) - hull(2 * i, 0), hull(2 * j, 1) - hull(2 * i, 1));
    const Eigen::Vector2d normal = Eigen::Vector2d(e.y(), -e.x()).normalized();
    c.planes.insert(c.planes.end(), {normal.x(), normal.y(), 0.0, normal.x() * hull(2 * i, 0) + normal.y() * hull(2 * i, 1)});
    c.polygons.insert(c.polygons.end(), {4u, 2 * i, 2 * j, 2 * j + 1, 2 * i + 1});
  }
  return c;
}

class OdeDebrisWorld final : public DebrisWorld {
 public:
  OdeDebrisWorld(const DebrisWorldSpec& spec, const OdeOptions& options);
  ~OdeDebrisWorld() override;
  void step() override;
  double time_step_s() const override { return options_.rigid.time_step_s; }
  GrainSet elements() const override;
  std::vector<Pose> part_poses() const override;
  std::vector<bool> joints_broken() const override { return ledger_.joints_broken(); }
  std::vector<double> joint_forces_n() const override { return ledger_.joint_forces_n(); }
  std::vector<Eigen::Vector3d> part_element_forces_n() const override { return ledger_.part_forces_n(); }

 private:
  static void near_callback(void* self, dGeomID a, dGeomID b);
  void collide_pair(dGeomID a, dGeomID b);
  double cfm_for(double lighter_mass_kg) const { return options_.cfm * kOdeCfmReferenceMassKg / lighter_mass_kg; }
  dBodyID add_body(dGeomID geom, const dMass& mass, const Eigen::Vector3d& at);
  void add_part(const DebrisPart& part, const DebrisMaterial& material);
  void add_joint(const DebrisJoint& joint);

  // A contact between an element and a part whose force is read after the step.
  struct PartContact {
    std::size_t part;
    bool part_is_first;  // the part is the joint's first body (its force is f1)
  };
  void add_element_forces_on_parts();

  OdeOptions options_;
  DebrisLedger ledger_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  unsigned long random_seed_ = 0;
  std::vector<GeomInfo> infos_;  // geom data points into this (reserved once)
  std::vector<ConvexData> convex_;  // ODE keeps pointers into these (reserved once)
  std::vector<double> terrain_vertices_;
  std::vector<dTriIndex> terrain_indices_;
  dTriMeshDataID terrain_data_ = nullptr;
  std::vector<dBodyID> elements_;
  std::vector<double> element_radius_m_;
  std::vector<dBodyID> parts_;
  std::vector<dJointID> joints_;
  std::vector<dJointFeedback> feedback_;  // per joint (sized once)
  std::deque<dJointFeedback> contact_feedback_;  // per part contact of this step (a deque: ODE keeps pointers)
  std::vector<PartContact> part_contacts_;
  std::vector<dContactGeom> scratch_;
};

OdeDebrisWorld::OdeDebrisWorld(const DebrisWorldSpec& spec, const OdeOptions& options)
    : options_(options), ledger_(spec.joints, spec.parts.size()) {
  init_ode_once();
  world_ = dWorldCreate();
  dWorldSetGravity(world_, 0, 0, -spec.gravity_m_s2);
  dWorldSetERP(world_, options.erp);
  dWorldSetCFM(world_, options.cfm * 1e-6);  // every contact and joint sets its own (header)
  dWorldSetQuickStepNumIterations(world_, options.rigid.solver_iterations);
  dWorldSetAutoDisableFlag(world_, 0);
  double r_max = 0.01;
  for (const DebrisElement& e : spec.elements) r_max = std::max(r_max, e.radius_m);
  dWorldSetContactSurfaceLayer(world_, options.surface_layer_fraction * r_max);
  space_ = dHashSpaceCreate(nullptr);
  const int min_level = static_cast<int>(std::floor(std::log2(2.0 * r_max)));
  dHashSpaceSetLevels(space_, min_level, min_level + 6);
  contacts_ = dJointGroupCreate(0);
  scratch_.resize(static_cast<std::size_t>(options.max_contacts_per_pair));
  infos_.reserve(2 + spec.elements.size() + spec.parts.size());
  convex_.reserve(spec.parts.size());

  const TriangleMesh& m = spec.terrain;
  terrain_vertices_.assign(m.V.data(), m.V.data() + m.V.size());
  for (Eigen::Index k = 0; k < m.F.size(); ++k) terrain_indices_.push_back(static_cast<dTriIndex>(m.F.data()[k]));
  terrain_data_ = dGeomTriMeshDataCreate();
  dGeomTriMeshDataBuildDouble(terrain_data_, terrain_vertices_.data(), 3 * sizeof(double), static_cast<int>(m.V.rows()),
                              terrain_indices_.data(), static_cast<int>(terrain_indices_.size()), 3 * sizeof(dTriIndex));
  // convex parts against the mesh (libccd) need the face angles
  dintptr extra[dTRIDATAPREPROCESS_BUILD__MAX] = {};
  extra[dTRIDATAPREPROCESS_BUILD_FACE_ANGLES] = dTRIDATAPREPROCESS_FACE_ANGLES_EXTRA_WORD_ALL;
  dGeomTriMeshDataPreprocess2(terrain_data_, 1U << dTRIDATAPREPROCESS_BUILD_FACE_ANGLES, extra);
  dGeomID terrain = dCreateTriMesh(space_, terrain_data_, nullptr, nullptr, nullptr);
  infos_.push_back({GeomInfo::Kind::kTerrain, 0.0, spec.material.building_friction, spec.material.building_restitution, 0.0});
  dGeomSetData(terrain, &infos_.back());
  dGeomSetData(dCreatePlane(space_, 0, 0, 1, spec.plain_height_m), &infos_.back());  // the plain: terrain's values

  for (const DebrisElement& e : spec.elements) {
    dMass mass;
    const double kg = element_mass_kg(e);
    dMassSetSphereTotal(&mass, kg, e.radius_m);
    dGeomID geom = dCreateSphere(space_, e.radius_m);
    infos_.push_back({GeomInfo::Kind::kElement, e.radius_m, e.friction, e.restitution, kg, e.rolling_friction});
    dGeomSetData(geom, &infos_.back());
    dBodyID body = add_body(geom, mass, e.centre_m);
    dBodySetLinearVel(body, e.velocity_m_s.x(), e.velocity_m_s.y(), e.velocity_m_s.z());
    elements_.push_back(body);
    element_radius_m_.push_back(e.radius_m);
  }
  for (const DebrisPart& part : spec.parts) add_part(part, spec.material);
  feedback_.resize(spec.joints.size());
  for (const DebrisJoint& joint : spec.joints) add_joint(joint);
}

dBodyID OdeDebrisWorld::add_body(dGeomID geom, const dMass& mass, const Eigen::Vector3d& at) {
  dBodyID body = dBodyCreate(world_);
  dBodySetMass(body, &mass);
  dGeomSetBody(geom, body);
  dBodySetPosition(body, at.x(), at.y(), at.z());
  return body;
}

void OdeDebrisWorld::add_part(const DebrisPart& part, const DebrisMaterial& material) {
  const ConvexData& c = convex_.emplace_back(prism_convex(part.hull_m));
  dGeomID geom = dCreateConvex(space_, c.planes.data(), static_cast<unsigned int>(c.planes.size() / 4), c.points.data(),
                               static_cast<unsigned int>(c.points.size() / 3), c.polygons.data());
  infos_.push_back({GeomInfo::Kind::kPart, 0.0, material.building_friction, material.building_restitution, part.mass_kg,
                    0.0, static_cast<int>(parts_.size())});
  dGeomSetData(geom, &infos_.back());
  dMass mass;
  const Eigen::Vector3d s = 2.0 * part.half_extents_m;
  dMassSetBoxTotal(&mass, part.mass_kg, s.x(), s.y(), s.z());
  parts_.push_back(add_body(geom, mass, part.centre_m));
}

void OdeDebrisWorld::add_joint(const DebrisJoint& joint) {
  dBodyID a = parts_.at(static_cast<std::size_t>(joint.a));
  dBodyID b = joint.b < 0 ? nullptr : parts_.at(static_cast<std::size_t>(joint.b));
  dJointID j = dJointCreateFixed(world_, nullptr);
  dJointAttach(j, a, b);
  dJointSetFixed(j);
  dMass ma;
  dBodyGetMass(a, &ma);
  double lighter = ma.mass;
  if (b != nullptr) {
    dMass mb;
    dBodyGetMass(b, &mb);
    lighter = std::min(lighter, mb.mass);
  }
  dJointSetFixedParam(j, dParamCFM, cfm_for(lighter));
  dJointSetFixedParam(j, dParamERP, options_.erp);
  dJointSetFeedback(j, &feedback_[joints_.size()]);
  joints_.push_back(j);
}

OdeDebrisWorld::~OdeDebrisWorld() {
  dJointGroupDestroy(contacts_);
  dSpaceDestroy(space_);
  dGeomTriMeshDataDestroy(terrain_data_);
  dWorldDestroy(world_);  // destroys the bodies and the remaining joints
}

void OdeDebrisWorld::near_callback(void* self, dGeomID a, dGeomID b) {
  static_cast<OdeDebrisWorld*>(self)->collide_pair(a, b);
}

void OdeDebrisWorld::collide_pair(dGeomID a, dGeomID b) {
  const auto* ia = static_cast<const GeomInfo*>(dGeomGetData(a));
  const auto* ib = static_cast<const GeomInfo*>(dGeomGetData(b));
  if (ia->mass_kg == 0.0 && ib->mass_kg == 0.0) return;
  dBodyID ba = dGeomGetBody(a), bb = dGeomGetBody(b);
  if (ba != nullptr && bb != nullptr && dAreConnectedExcluding(ba, bb, dJointTypeContact)) return;  // a live joint
  const int n = dCollide(a, b, static_cast<int>(scratch_.size()), scratch_.data(), sizeof(dContactGeom));
  if (n == 0) return;
  using K = GeomInfo::Kind;
  const bool ea = ia->kind == K::kElement, eb = ib->kind == K::kElement;
  const double friction = ea && eb ? 0.5 * (ia->friction + ib->friction) : ea ? ia->friction : ib->friction;
  const double restitution = ea && eb ? 0.5 * (ia->restitution + ib->restitution) : ea ? ia->restitution : ib->restitution;
  const double lever = ea && eb ? rolling_lever_m(0.5 * (ia->rolling_mu + ib->rolling_mu), ia->radius_m, ib->radius_m)
                       : ea     ? rolling_lever_m(ia->rolling_mu, ia->radius_m, 0.0)
                       : eb     ? rolling_lever_m(ib->rolling_mu, ib->radius_m, 0.0)
                                : 0.0;
  const double lighter = ia->mass_kg == 0.0 ? ib->mass_kg : ib->mass_kg == 0.0 ? ia->mass_kg : std::min(ia->mass_kg, ib->mass_kg);
  for (int k = 0; k < n; ++k) {
    dContact c{};
    c.geom = scratch_[static_cast<std::size_t>(k)];
    c.surface.mode = dContactApprox1 | dContactBounce | dContactSoftCFM | (lever > 0.0 ? dContactRolling | dContactAxisDep : 0);
    c.surface.soft_cfm = cfm_for(lighter);
    c.surface.mu = c.surface.mu2 = friction;
    c.surface.bounce = restitution;
    c.surface.bounce_vel = options_.rigid.restitution_velocity_threshold_m_s;
    c.surface.rho = c.surface.rho2 = lever;
    c.surface.rhoN = 0.0;
    dJointID joint = dJointCreateContact(world_, contacts_, &c);
    dJointAttach(joint, ba, bb);
    const bool part_a = ia->kind == K::kPart && eb, part_b = ib->kind == K::kPart && ea;
    if (part_a || part_b) {
      dJointSetFeedback(joint, &contact_feedback_.emplace_back());
      part_contacts_.push_back({static_cast<std::size_t>((part_a ? ia : ib)->part), part_a});
    }
  }
}

void OdeDebrisWorld::step() {
  dRandSetSeed(random_seed_);
  contact_feedback_.clear();
  part_contacts_.clear();
  dSpaceCollide(space_, this, &OdeDebrisWorld::near_callback);
  dWorldQuickStep(world_, options_.rigid.time_step_s);
  dJointGroupEmpty(contacts_);
  random_seed_ = dRandGetSeed();
  ledger_.begin_step();
  for (std::size_t k = 0; k < joints_.size(); ++k) {
    if (ledger_.broken(k)) continue;
    const dReal* f = feedback_[k].f1;
    if (ledger_.record_joint(k, std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]))) dJointDestroy(joints_[k]);
  }
  add_element_forces_on_parts();
}

// A contact joint's feedback: f1 the force on its first body, f2 on its second.
void OdeDebrisWorld::add_element_forces_on_parts() {
  auto fb = contact_feedback_.cbegin();
  for (const PartContact& c : part_contacts_) {
    const dReal* f = c.part_is_first ? fb->f1 : fb->f2;
    ledger_.add_part_force(c.part, Eigen::Vector3d(f[0], f[1], f[2]));
    ++fb;
  }
}

GrainSet OdeDebrisWorld::elements() const {
  GrainSet out;
  const auto n = static_cast<Eigen::Index>(elements_.size());
  out.position_m.resize(n, 3);
  out.radius_m.resize(n);
  out.velocity_m_s.resize(n, 3);
  for (Eigen::Index i = 0; i < n; ++i) {
    const dReal* p = dBodyGetPosition(elements_[static_cast<std::size_t>(i)]);
    const dReal* v = dBodyGetLinearVel(elements_[static_cast<std::size_t>(i)]);
    out.position_m.row(i) << p[0], p[1], p[2];
    out.velocity_m_s.row(i) << v[0], v[1], v[2];
    out.radius_m(i) = element_radius_m_[static_cast<std::size_t>(i)];
  }
  return out;
}

std::vector<Pose> OdeDebrisWorld::part_poses() const {
  std::vector<Pose> out;
  for (dBodyID b : parts_) {
    const dReal *p = dBodyGetPosition(b), *q = dBodyGetQuaternion(b);
    out.push_back({Eigen::Vector3d(p[0], p[1], p[2]), Eigen::Quaterniond(q[0], q[1], q[2], q[3])});
  }
  return out;
}

}  // namespace

std::unique_ptr<DebrisWorld> make_ode_debris_world(const DebrisWorldSpec& spec, const OdeOptions& options) {
  validate(options);
  return std::make_unique<OdeDebrisWorld>(spec, options);
}

}  // namespace repose
