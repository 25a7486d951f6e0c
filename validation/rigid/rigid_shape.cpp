#include "validation/rigid/rigid_shape.h"

namespace repose {

RigidShape rigid_shape(const ObjectSpec& o) {
  const Eigen::Vector3d& s = o.scale;
  const bool uniform = s.x() == s.y() && s.y() == s.z();
  RigidShape shape;
  switch (o.shape) {
    case ObjectSpec::Shape::kBox:
      shape.kind = RigidShape::Kind::kBox;
      shape.half_extents_m = o.half_extents_m.cwiseProduct(s);
      return shape;
    case ObjectSpec::Shape::kSphere:
      if (!uniform) break;
      shape.kind = RigidShape::Kind::kSphere;
      shape.radius_m = o.radius_m * s.x();
      return shape;
    case ObjectSpec::Shape::kCylinder:
      if (s.x() != s.y()) break;
      shape.kind = RigidShape::Kind::kCylinder;
      shape.radius_m = o.radius_m * s.x();
      shape.half_height_m = o.half_height_m * s.z();
      return shape;
    case ObjectSpec::Shape::kCapsule:
      if (!uniform) break;
      shape.kind = RigidShape::Kind::kCapsule;
      shape.radius_m = o.radius_m * s.x();
      shape.half_height_m = o.half_height_m * s.x();
      return shape;
    case ObjectSpec::Shape::kMesh:
      break;
  }
  shape.kind = RigidShape::Kind::kMesh;
  shape.mesh = &o.body;
  return shape;
}

}  // namespace repose
