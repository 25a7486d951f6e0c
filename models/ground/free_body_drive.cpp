#include "models/ground/free_body_drive.h"

#include <ode/ode.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/geometry/depth_image.h"
#include "models/ground/bearing_sinkage.h"
#include "models/ground/collision.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_state.h"

namespace repose {

namespace {

static_assert(sizeof(dReal) == sizeof(double), "ODE must be the double-precision build");

// Contacts ODE may report for one pair of geoms per step.
constexpr int kMaxContactsPerPair = 16;

void init_ode_once() {
  static std::once_flag once;
  std::call_once(once, [] { dInitODE2(0); });
  dAllocateODEDataForThread(dAllocateMaskAll);
}

// An ODE primitive of a scene object, the scene's scale applied.
struct BodyShape {
  ObjectSpec::Shape kind = ObjectSpec::Shape::kSphere;
  double radius_m = 0.0, half_height_m = 0.0;
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();
};

// False when the object is no ODE primitive (a mesh, a primitive scaled out of its kind).
bool body_shape(const ObjectSpec& o, BodyShape* shape) {
  const Eigen::Vector3d& s = o.scale;
  const bool uniform = s.x() == s.y() && s.y() == s.z();
  shape->kind = o.shape;
  shape->radius_m = o.radius_m * s.x();
  shape->half_height_m = o.half_height_m * (o.shape == ObjectSpec::Shape::kCylinder ? s.z() : s.x());
  shape->half_extents_m = o.half_extents_m.cwiseProduct(s);
  switch (o.shape) {
    case ObjectSpec::Shape::kBox: return true;
    case ObjectSpec::Shape::kCylinder: return s.x() == s.y();
    case ObjectSpec::Shape::kSphere:
    case ObjectSpec::Shape::kCapsule: return uniform;
    case ObjectSpec::Shape::kMesh: return false;
  }
  return false;
}

// The lowest point of the primitive at a pose (R: body to world).
double lowest_z(const BodyShape& b, const Eigen::Vector3d& centre, const Eigen::Matrix3d& R) {
  const double az = std::abs(R(2, 2));  // the body's z axis (cylinder, capsule) against the vertical
  switch (b.kind) {
    case ObjectSpec::Shape::kBox: return centre.z() - R.row(2).cwiseAbs().dot(b.half_extents_m);
    case ObjectSpec::Shape::kCylinder:
      return centre.z() - az * b.half_height_m - b.radius_m * std::sqrt(std::max(0.0, 1.0 - az * az));
    case ObjectSpec::Shape::kCapsule: return centre.z() - az * b.half_height_m - b.radius_m;
    default: return centre.z() - b.radius_m;
  }
}

// One free body in ODE.
struct Driven {
  int object = 0;        // index into model.objects
  BodyShape shape;
  dBodyID body = nullptr;
  dGeomID geom = nullptr;
  double mass_kg = 0.0;
  Eigen::Vector3d torque_n_m = Eigen::Vector3d::Zero();  // dynamic.torque_n_m, added before every ODE step
  double impulse_n_s = 0.0;  // vertical impulse of the field on the body over the current ground step
  double impact_energy_j = 0.0;  // downward kinetic energy at the field contacts that began this ground step
  bool touching = false;         // had a field contact in the last ODE step
  bool touched = false;          // had one in this ground step
  // had none through the whole last ground step: only such a body's new
  // contact is an impact (a resting body's contact flickers with the
  // solver's round-off, and each flicker's fall of one ODE step would ratchet it down)
  bool airborne = true;
  double load_n = 0.0, max_load_n = 0.0, bearing_sinkage_m = 0.0;
};

Pose pose_of(dBodyID body) {
  const dReal *p = dBodyGetPosition(body), *q = dBodyGetQuaternion(body);
  return Pose{Eigen::Vector3d(p[0], p[1], p[2]), Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized()};
}

}  // namespace

bool has_free_bodies(const GroundModel& model) {
  return std::any_of(model.objects.begin(), model.objects.end(), [](const ObjectSpec& o) { return o.dynamic; });
}

void check_free_bodies(const GroundModel& model, const std::string& source_path) {
  for (std::size_t k = 0; k < model.objects.size(); ++k) {
    const ObjectSpec& o = model.objects[k];
    BodyShape shape;
    if (o.dynamic && !body_shape(o, &shape)) {
      throw InputError(fmt::format("{}: objects[{}] ('{}'): the ground model drives free bodies with ODE's sphere, "
                                   "box, cylinder and capsule (scaled so they stay one), not a mesh or a "
                                   "non-uniformly scaled primitive: use a primitive or a particle engine",
                                   source_path, k, o.name));
    }
  }
}

struct FreeBodyDrive::Impl {
  const GroundModel& model;
  HeightField initial;
  dWorldID world = nullptr;
  dSpaceID space = nullptr;
  dJointGroupID contacts = nullptr;
  dHeightfieldDataID field_data = nullptr;
  dGeomID field = nullptr;
  std::vector<double> samples;  // ODE's height samples, read in place
  std::vector<Driven> bodies;
  std::vector<dJointFeedback> feedback;  // one per field contact of the current ODE step
  std::vector<std::size_t> feedback_owner;  // index into bodies
  std::size_t feedback_used = 0;
  unsigned long random_seed = 0;

  Impl(const GroundModel& m, const HeightField& h) : model(m), initial(h) {}
  ~Impl() {
    if (field_data != nullptr) dGeomHeightfieldDataDestroy(field_data);
    if (contacts != nullptr) dJointGroupDestroy(contacts);
    if (space != nullptr) dSpaceDestroy(space);
    if (world != nullptr) dWorldDestroy(world);
  }

  void build_world();
  void add_field();
  void add_body(int object);
  void fill_samples(const HeightField& h);
  void collide_pair(dGeomID a, dGeomID b);
  void ode_step(double dt_s);
  Pose press(Driven& d, const HeightField& ground);
};

void FreeBodyDrive::Impl::build_world() {
  const FreeBodySpec& spec = model.free_bodies;
  init_ode_once();
  world = dWorldCreate();
  dWorldSetGravity(world, 0, 0, -spec.gravity_m_s2);
  dWorldSetERP(world, spec.erp);
  dWorldSetCFM(world, spec.cfm);
  dWorldSetQuickStepNumIterations(world, spec.solver_iterations);
  dWorldSetAutoDisableFlag(world, 0);
  space = dSimpleSpaceCreate(nullptr);
  contacts = dJointGroupCreate(0);
}

// ODE's height field samples the ground at cell corners, each the lowest of
// the (up to four) cells sharing it: a body resting in its imprint then
// meets the imprint's floor out to the footprint's edge, where samples at
// cell centres would make a ramp from the floor up to the displaced rim
// across the edge cells, on which ODE lifts the body (measured before this
// rule: a box ended up to 0.7 mm above its imprint's floor). ODE's ground
// lies at most one half-cell's slope below the heuristic's.
// The geom: local y up, samples [z * (nx + 1) + x] centred on the geom,
// turned +90 deg about x (local y -> world z, local z -> world -y), so
// sample row z is corner row ny - z.
void FreeBodyDrive::Impl::add_field() {
  const Grid& g = model.grid;
  samples.assign(static_cast<std::size_t>(g.nx + 1) * static_cast<std::size_t>(g.ny + 1), 0.0);
  fill_samples(initial);
  field_data = dGeomHeightfieldDataCreate();
  const double h = g.cell_size_m;
  // thickness: a body pushed through the surface meets solid ground below it, not a shell
  dGeomHeightfieldDataBuildDouble(field_data, samples.data(), 0, g.nx * h, g.ny * h, g.nx + 1, g.ny + 1, 1.0, 0.0,
                                  1.0, 0);
  field = dCreateHeightfield(space, field_data, 1);
  dGeomSetPosition(field, g.origin_x_m + 0.5 * g.nx * h, g.origin_y_m + 0.5 * g.ny * h, 0.0);
  dMatrix3 turn;
  dRFromAxisAndAngle(turn, 1, 0, 0, M_PI / 2);
  dGeomSetRotation(field, turn);
  fill_samples(initial);  // sets the bounds
}

void FreeBodyDrive::Impl::fill_samples(const HeightField& h) {
  const Grid& g = model.grid;
  for (int z = 0; z <= g.ny; ++z) {
    const int j = g.ny - z;  // corner row: cells j - 1 and j share it
    for (int i = 0; i <= g.nx; ++i) {
      double lowest = std::numeric_limits<double>::infinity();
      for (int cj = std::max(j - 1, 0); cj <= std::min(j, g.ny - 1); ++cj) {
        for (int ci = std::max(i - 1, 0); ci <= std::min(i, g.nx - 1); ++ci) lowest = std::min(lowest, h.at(ci, cj));
      }
      samples[static_cast<std::size_t>(z) * (g.nx + 1) + i] = lowest;
    }
  }
  if (field_data == nullptr) return;
  const auto [lo, hi] = std::minmax_element(samples.begin(), samples.end());
  dGeomHeightfieldDataSetBounds(field_data, *lo, *hi);
}

void FreeBodyDrive::Impl::add_body(int object) {
  const ObjectSpec& o = model.objects[static_cast<std::size_t>(object)];
  Driven d;
  d.object = object;
  REPOSE_DEMAND(body_shape(o, &d.shape) && "check_free_bodies refuses other shapes");
  d.mass_kg = o.mass_kg();
  d.torque_n_m = o.dynamic->torque_n_m;
  d.body = dBodyCreate(world);
  dMass mass;
  const BodyShape& s = d.shape;
  const Eigen::Vector3d size = 2.0 * s.half_extents_m;
  dGeomID geom = nullptr;
  switch (s.kind) {
    case ObjectSpec::Shape::kBox:
      dMassSetBoxTotal(&mass, d.mass_kg, size.x(), size.y(), size.z());
      geom = dCreateBox(space, size.x(), size.y(), size.z());
      break;
    case ObjectSpec::Shape::kCylinder:
      dMassSetCylinderTotal(&mass, d.mass_kg, 3, s.radius_m, 2.0 * s.half_height_m);
      geom = dCreateCylinder(space, s.radius_m, 2.0 * s.half_height_m);
      break;
    case ObjectSpec::Shape::kCapsule:
      dMassSetCapsuleTotal(&mass, d.mass_kg, 3, s.radius_m, 2.0 * s.half_height_m);
      geom = dCreateCapsule(space, s.radius_m, 2.0 * s.half_height_m);
      break;
    default:
      dMassSetSphereTotal(&mass, d.mass_kg, s.radius_m);
      geom = dCreateSphere(space, s.radius_m);
  }
  dBodySetMass(d.body, &mass);
  dGeomSetBody(geom, d.body);
  d.geom = geom;
  const Pose p = o.keyframes.front().pose;
  dBodySetPosition(d.body, p.position_m.x(), p.position_m.y(), p.position_m.z());
  const dQuaternion q = {p.orientation.w(), p.orientation.x(), p.orientation.y(), p.orientation.z()};
  dBodySetQuaternion(d.body, q);
  const Eigen::Vector3d& v = o.dynamic->velocity_m_s;
  const Eigen::Vector3d& w = o.dynamic->angular_velocity_rad_s;
  dBodySetLinearVel(d.body, v.x(), v.y(), v.z());
  dBodySetAngularVel(d.body, w.x(), w.y(), w.z());
  bodies.push_back(d);
}

// Contacts of a body with the field (body first, so that a joint's f1 is the
// field's force on the body) or with another body.
void FreeBodyDrive::Impl::collide_pair(dGeomID a, dGeomID b) {
  if (b != field && a == field) std::swap(a, b);
  dContactGeom geoms[kMaxContactsPerPair];
  const int n = dCollide(a, b, kMaxContactsPerPair, geoms, sizeof(dContactGeom));
  const dBodyID body_a = dGeomGetBody(a), body_b = b == field ? nullptr : dGeomGetBody(b);
  std::size_t owner = 0;
  while (owner < bodies.size() && bodies[owner].body != body_a) ++owner;
  for (int k = 0; k < n; ++k) {
    dContact contact{};
    contact.geom = geoms[k];
    contact.surface.mode = dContactApprox1;
    contact.surface.mu = model.free_bodies.friction;
    dJointID joint = dJointCreateContact(world, contacts, &contact);
    dJointAttach(joint, body_a, body_b);
    if (b != field) continue;
    REPOSE_DEMAND(feedback_used < feedback.size() && owner < bodies.size());
    dJointSetFeedback(joint, &feedback[feedback_used]);
    feedback_owner[feedback_used++] = owner;
  }
}

// One ODE step; a body that meets the field after a ground step in the air
// brings the kinetic energy of its downward speed into it (the impact the
// bearing rule takes up).
void FreeBodyDrive::Impl::ode_step(double dt_s) {
  feedback_used = 0;
  dSpaceCollide(space, this, [](void* self, dGeomID a, dGeomID b) {
    static_cast<FreeBodyDrive::Impl*>(self)->collide_pair(a, b);
  });
  std::vector<double> falling_m_s(bodies.size());
  for (std::size_t k = 0; k < bodies.size(); ++k) falling_m_s[k] = std::max(0.0, -dBodyGetLinearVel(bodies[k].body)[2]);
  // ODE zeroes the accumulators after each step
  for (const Driven& d : bodies) dBodyAddTorque(d.body, d.torque_n_m.x(), d.torque_n_m.y(), d.torque_n_m.z());
  dRandSetSeed(random_seed);
  dWorldQuickStep(world, dt_s);
  random_seed = dRandGetSeed();
  std::vector<char> touching(bodies.size(), 0);
  for (std::size_t k = 0; k < feedback_used; ++k) {
    bodies[feedback_owner[k]].impulse_n_s += feedback[k].f1[2] * dt_s;
    touching[feedback_owner[k]] = 1;
  }
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    Driven& d = bodies[k];
    if (touching[k] && !d.touching && d.airborne) {
      d.impact_energy_j += 0.5 * d.mass_kg * falling_m_s[k] * falling_m_s[k];
    }
    d.touching = touching[k] != 0;
    d.touched = d.touched || d.touching;
  }
  dJointGroupEmpty(contacts);
}

namespace {

// How far the body's underside lies below the ground's cells under it.
double intersection_m(const DepthImage& underside, const Footprint& fp, const HeightField& ground) {
  double depth = 0.0;
  for (int j = 0; j < fp.nj; ++j) {
    for (int i = 0; i < fp.ni; ++i) {
      if (underside.is_covered(i, j)) depth = std::max(depth, ground.at(fp.i0 + i, fp.j0 + j) - underside.z(i, j));
    }
  }
  return depth;
}

}  // namespace

// The bearing rule: a body shallower than its load's Bekker sinkage, or
// than where the ground's work takes up the energy of an impact this step
// (impact_sinkage_m), moves down to it, in ODE and for the ground step. The
// static load is the field's mean force over the step, at most the weight:
// an impact's share of that force is counted by its energy, and the
// solver's jitter about the weight must not ratchet a resting body down.
// The ground yields only there: otherwise the ground step gets the body
// lifted out of whatever it intersects of the ground (ODE's soft contact and
// jitter; ODE holds the body out of the rest, its field being rigid), as
// cutting that away every step let a resting body creep down (measured: an
// 8 kg box 1.4 mm below its bearing depth after 1 s). Returns the body's
// pose for the ground step.
Pose FreeBodyDrive::Impl::press(Driven& d, const HeightField& ground) {
  const ObjectSpec& o = model.objects[static_cast<std::size_t>(d.object)];
  Pose pose = pose_of(d.body);
  const TriangleMesh mesh = transformed(o.body, pose);
  const Aabb box = bounding_box(mesh);
  const Footprint fp = footprint_of(box, model.grid);
  d.bearing_sinkage_m = 0.0;
  if (fp.empty()) return pose;
  const DepthImage underside = depth_image_cpu(mesh, fp.sub_grid(model.grid), ViewFrom::kBelow);
  pose.position_m.z() += intersection_m(underside, fp, ground);
  const double surface = initial.sample(pose.position_m.x(), pose.position_m.y());
  const double sinkage = surface - lowest_z(d.shape, pose.position_m, pose.orientation.toRotationMatrix());
  const double weight_n = d.mass_kg * model.free_bodies.gravity_m_s2, height_m = box.max.z() - box.min.z();
  const BekkerBearing& bearing = model.free_bodies.bearing;
  d.bearing_sinkage_m = bearing_sinkage_m(bearing, underside, height_m, std::clamp(d.load_n, 0.0, weight_n));
  const double target = std::max(d.bearing_sinkage_m, impact_sinkage_m(bearing, underside, height_m,
                                                                       std::max(sinkage, 0.0), weight_n,
                                                                       d.impact_energy_j));
  // a body that did not touch the field this step is not pressed (nor pulled down to it)
  if (!d.touched || sinkage >= target) return pose;
  pose.position_m.z() -= target - sinkage;
  dBodySetPosition(d.body, pose.position_m.x(), pose.position_m.y(), pose.position_m.z());
  return pose;
}

FreeBodyDrive::FreeBodyDrive(const GroundModel& model, const HeightField& initial)
    : impl_(std::make_unique<Impl>(model, initial)) {
  check_free_bodies(model, "scene");
  REPOSE_DEMAND(initial.grid().nx == model.grid.nx && initial.grid().ny == model.grid.ny);
  impl_->build_world();
  impl_->add_field();
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    if (model.objects[o].dynamic) impl_->add_body(static_cast<int>(o));
  }
  impl_->feedback.resize(impl_->bodies.size() * kMaxContactsPerPair);
  impl_->feedback_owner.resize(impl_->feedback.size());
}

FreeBodyDrive::~FreeBodyDrive() = default;

void FreeBodyDrive::advance(const GroundState& state, GroundModel* driven) {
  const double dt = impl_->model.time.step_s;
  const int ode_steps = std::max(1, static_cast<int>(std::lround(dt / impl_->model.free_bodies.ode_step_s)));
  for (Driven& d : impl_->bodies) {
    d.impulse_n_s = d.impact_energy_j = 0.0;
    d.touched = false;
  }
  for (int k = 0; k < ode_steps; ++k) impl_->ode_step(dt / ode_steps);
  for (Driven& d : impl_->bodies) d.airborne = !d.touched;
  const double t0 = state.step_index * dt;
  for (Driven& d : impl_->bodies) {
    d.load_n = d.impulse_n_s / dt;
    d.max_load_n = std::max(d.max_load_n, d.load_n);
    const Pose pose = impl_->press(d, state.height);
    const auto o = static_cast<std::size_t>(d.object);
    driven->objects[o].keyframes = {Keyframe{t0, state.previous_poses[o]}, Keyframe{t0 + dt, pose}};
  }
}

void FreeBodyDrive::refresh_field(const HeightField& ground) { impl_->fill_samples(ground); }

std::vector<FreeBodyReport> FreeBodyDrive::reports() const {
  std::vector<FreeBodyReport> out;
  for (const Driven& d : impl_->bodies) {
    const Pose pose = pose_of(d.body);
    const dReal* v = dBodyGetLinearVel(d.body);
    const ObjectSpec& object = impl_->model.objects[static_cast<std::size_t>(d.object)];
    FreeBodyReport r;
    r.name = object.name;
    r.mass_kg = d.mass_kg;
    r.weight_n = d.mass_kg * impl_->model.free_bodies.gravity_m_s2;
    r.resting_depth_m = impl_->initial.sample(pose.position_m.x(), pose.position_m.y()) -
                        lowest_z(d.shape, pose.position_m, pose.orientation.toRotationMatrix());
    r.final_speed_m_s = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    r.travel_m = (pose.position_m - object.keyframes.front().pose.position_m).head<2>().norm();
    r.final_load_n = d.load_n;
    r.max_load_n = d.max_load_n;
    r.bearing_sinkage_m = d.bearing_sinkage_m;
    r.final_position_m = pose.position_m;
    out.push_back(r);
  }
  return out;
}

}  // namespace repose
