#pragma once
// The height-span model's fixed description (the height-span paper, 2):
// the ground model's (grid, materials, all objects, options; models/ground),
// which objects hold material and get a span map, and the model's options.
// Nothing here changes while the model runs; the changing part is
// HeightSpanState, the fitted part the ground's GroundParams (the spans
// carry the ground's base material: its theta, sigma and En rule erosion on
// the spans; departure: the paper names one material).
//
// A span map lives on a grid of the ground's cell size that moves with its
// object's horizontal position (it coincides with the ground's grid at time
// 0), so material on the spans moves with a translating object exactly,
// cell for cell, whatever the speed; only a rotation re-samples it
// (span_motion.h). The grid is square, wide enough for the body turned any
// way: 2 * (radius of the body around its origin) plus a ring of cells.

#include <cstdint>
#include <vector>

#include "models/core/config/scene.h"
#include "models/ground/ground_model.h"
#include "models/heightspan/heightspan_section.h"

namespace repose {

struct HeldObject {
  int object = 0;          // index into ground.objects
  Grid grid0;              // the map's grid at time 0
  Eigen::Vector2d position0_xy = Eigen::Vector2d::Zero();  // the object's position at time 0
};

struct HeightSpanModel {
  GroundModel ground;             // every object of the scene
  std::vector<HeldObject> held;   // objects with a span map
  std::vector<int> ground_path;   // the other objects: the ground model's collision and displacement only
  HeightSpanSpec options;
  std::uint64_t seed = 0;         // the particles' generator

  // The grid of a held object's map when the object is at `pose`.
  Grid map_grid(const HeldObject& held, const Pose& pose) const;
};

// Throws InputError when an object that holds material has a mesh that is
// not closed (its spans would be undefined).
HeightSpanModel build_heightspan_model(const Scene& scene);

}  // namespace repose
