// Prints the figures of issue 11, item 4 (an experiment, no assertions): a
// box driven by ODE over the ground heuristic's height field, the field
// updated from the ground model every frame, so the box sinks and leaves its
// imprint. A 10 cm x 10 cm x 5 cm box is dropped flat from 1 cm above a 5 cm
// sand bed (0.4 m square, 4 mm cells, the ground paper's sand: alpha 1,
// theta 30 deg, sigma 0.2); ODE steps at 1/600 s (QuickStep, 20 iterations,
// ERP 0.2, the ode: section's defaults), the ground model at 1/60 s with the
// box's ODE pose as its object. For each load (box mass) and ODE CFM it
// prints the box bottom's sinkage below the initial surface at 0.25, 0.5,
// 1 and 2 s, and the same without the ground model (ODE's own penetration).
// Run: build/tests/ode_ground_sinkage
//
// Measured (2026-11-22, deterministic): sinkage does not follow load. ODE
// holds the box on the field, its own penetration 0.01 / 0.04 / 0.16 mm at
// 0.5 / 2 / 8 kg (490-7850 Pa) with CFM 1e-3 (proportional to load; 0 at
// 1e-6), and the heuristic displaces only what the box's pose at a frame
// intersects, so the box ends within 0.7 mm of the initial surface, even
// above it (resting on the displaced rim, which ODE's height field
// interpolates under the box's edge). The impact's penetration is resolved
// by ODE between frames and never reaches the ground model. The heuristic
// has no bearing capacity: for a body to sink with its load it needs a
// load-dependent rule (a pressure-sinkage law pressing the object into the
// field before each ground step), not built here.
#include <ode/ode.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "models/ground/collision.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"
#include "models/ground/ground_step.h"
#include "models/ground/material.h"
#include "models/ground/swept_mesh.h"

namespace repose {
namespace {

constexpr double kCell = 0.004, kBed = 0.05, kOdeStep = 1.0 / 600.0, kFrame = 1.0 / 60.0;
constexpr int kCells = 100;
const Eigen::Vector3d kHalf(0.05, 0.05, 0.025);

// ODE's height field samples: local y up, [z * width + x], centred on the geom;
// the geom is turned +90 deg about x (local y -> world z, local z -> world -y), so rows run backwards.
void fill_samples(const HeightField& h, std::vector<double>& samples) {
  for (int z = 0; z < kCells; ++z) {
    for (int x = 0; x < kCells; ++x) samples[static_cast<std::size_t>(z * kCells + x)] = h.at(x, kCells - 1 - z);
  }
}

struct Contacts {
  dWorldID world;
  dJointGroupID group;
};

void near_callback(void* data, dGeomID a, dGeomID b) {
  auto* c = static_cast<Contacts*>(data);
  dContactGeom geoms[8];
  const int n = dCollide(a, b, 8, geoms, sizeof(dContactGeom));
  for (int k = 0; k < n; ++k) {
    dContact contact{};
    contact.geom = geoms[k];
    contact.surface.mode = dContactApprox1;
    contact.surface.mu = 0.5;
    dJointAttach(dJointCreateContact(c->world, c->group, &contact), dGeomGetBody(a), dGeomGetBody(b));
  }
}

// The ODE side: the box body and the height field geom reading `samples` in place.
struct OdeScene {
  dWorldID world = nullptr;
  dSpaceID space = nullptr;
  dJointGroupID group = nullptr;
  dHeightfieldDataID data = nullptr;
  dBodyID body = nullptr;
};

OdeScene make_ode_scene(double mass_kg, double cfm, const Eigen::Vector3d& start, std::vector<double>& samples) {
  OdeScene o;
  o.world = dWorldCreate();
  dWorldSetGravity(o.world, 0, 0, -9.81);
  dWorldSetERP(o.world, 0.2);
  dWorldSetCFM(o.world, cfm);
  dWorldSetQuickStepNumIterations(o.world, 20);
  o.space = dSimpleSpaceCreate(nullptr);
  o.group = dJointGroupCreate(0);
  o.data = dGeomHeightfieldDataCreate();
  const double span = (kCells - 1) * kCell;
  dGeomHeightfieldDataBuildDouble(o.data, samples.data(), 0, span, span, kCells, kCells, 1.0, 0.0, kBed, 0);
  dGeomHeightfieldDataSetBounds(o.data, 0.0, 2.0 * kBed);
  dGeomID field = dCreateHeightfield(o.space, o.data, 1);
  dMatrix3 turn;
  dRFromAxisAndAngle(turn, 1, 0, 0, M_PI / 2);
  dGeomSetRotation(field, turn);
  o.body = dBodyCreate(o.world);
  dMass mass;
  dMassSetBoxTotal(&mass, mass_kg, 2 * kHalf.x(), 2 * kHalf.y(), 2 * kHalf.z());
  dBodySetMass(o.body, &mass);
  dBodySetPosition(o.body, start.x(), start.y(), start.z());
  dGeomSetBody(dCreateBox(o.space, 2 * kHalf.x(), 2 * kHalf.y(), 2 * kHalf.z()), o.body);
  return o;
}

void destroy(OdeScene& o) {
  dGeomHeightfieldDataDestroy(o.data);
  dJointGroupDestroy(o.group);
  dSpaceDestroy(o.space);
  dWorldDestroy(o.world);
}

// The ground model with the box as its one object, at rest at `start`.
GroundModel box_ground_model(const Grid& grid, const Eigen::Vector3d& start) {
  GroundModel model = make_plain_ground_model(grid, Material{});  // the ground paper's sand (material.h)
  ObjectSpec box;
  box.name = "box";
  box.shape = ObjectSpec::Shape::kBox;
  box.half_extents_m = kHalf;
  box.body = make_box(kHalf);
  box.keyframes = {Keyframe{0.0, Pose{start, Eigen::Quaterniond::Identity()}}};
  model.objects = {box};
  model.swept_bodies = {make_swept_body(box.body)};
  model.time = TimeSpec{kFrame, 1.0};
  return model;
}

// The box bottom's sinkage below the initial surface at each time in `at_s`.
std::vector<double> sinkage(double mass_kg, double cfm, bool deform, const std::vector<double>& at_s) {
  const Grid grid{kCells, kCells, kCell, -0.5 * kCells * kCell, -0.5 * kCells * kCell};
  const Eigen::Vector3d start(0.0, 0.0, kBed + 0.01 + kHalf.z());
  GroundModel model = box_ground_model(grid, start);
  const GroundParams params = default_params(model);
  GroundState state = make_ground_state(model, HeightField(grid, kBed));
  const auto renderer = make_cpu_underside_renderer();
  std::vector<double> samples(kCells * kCells);
  fill_samples(state.height, samples);
  OdeScene ode = make_ode_scene(mass_kg, cfm, start, samples);
  Contacts contacts{ode.world, ode.group};
  std::vector<double> out;
  const int steps_per_frame = static_cast<int>(std::lround(kFrame / kOdeStep));
  for (std::size_t next = 0, k = 0; next < at_s.size(); ++k) {
    dSpaceCollide(ode.space, &contacts, near_callback);
    dWorldQuickStep(ode.world, kOdeStep);
    dJointGroupEmpty(ode.group);
    const dReal *p = dBodyGetPosition(ode.body), *q = dBodyGetQuaternion(ode.body);
    if (deform && (k + 1) % steps_per_frame == 0) {
      const Pose pose{Eigen::Vector3d(p[0], p[1], p[2]), Eigen::Quaterniond(q[0], q[1], q[2], q[3])};
      model.objects[0].keyframes = {Keyframe{0.0, pose}};
      step(model, params, *renderer, &state);
      fill_samples(state.height, samples);
    }
    if (static_cast<double>(k + 1) * kOdeStep >= at_s[next] - 1e-9) {
      out.push_back(kBed - (p[2] - kHalf.z()));
      ++next;
    }
  }
  destroy(ode);
  return out;
}

}  // namespace
}  // namespace repose

int main() {
  dInitODE2(0);
  const std::vector<double> at = {0.25, 0.5, 1.0, 2.0};
  std::printf("mass_kg pressure_pa cfm   ground  sinkage_mm at 0.25 0.5 1 2 s\n");
  for (double cfm : {1e-3, 1e-6}) {
    for (double m : {0.5, 2.0, 8.0}) {
      for (bool deform : {false, true}) {
        const std::vector<double> s = repose::sinkage(m, cfm, deform, at);
        std::printf("%7.1f %11.0f %5.0e %6s ", m, m * 9.81 / 0.01, cfm, deform ? "yes" : "no");
        for (double x : s) std::printf(" %8.2f", 1e3 * x);
        std::printf("\n");
      }
    }
  }
  dCloseODE();
  return 0;
}
