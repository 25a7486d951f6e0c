#pragma once
// The collision shape of a scene object in a rigid-body engine: the
// engine's own primitive where the object is one (scaled exactly: a box by
// its three scales, a sphere or capsule by a uniform one, a cylinder by
// sx = sy), else the object's triangle mesh (the tessellated, scaled body,
// as for meshes and non-uniformly scaled primitives).

#include <Eigen/Core>

#include "models/core/config/scene.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {

struct RigidShape {
  enum class Kind { kSphere, kBox, kCylinder, kCapsule, kMesh };
  Kind kind = Kind::kMesh;
  double radius_m = 0.0;                                      // sphere, cylinder, capsule
  double half_height_m = 0.0;                                 // cylinder, capsule (straight part), along body z
  Eigen::Vector3d half_extents_m = Eigen::Vector3d::Zero();   // box
  const TriangleMesh* mesh = nullptr;                         // mesh: the object's body (outlives the shape)
};

RigidShape rigid_shape(const ObjectSpec& object);

}  // namespace repose
