#pragma once
// An object's span map follows the object (the height-span paper, 2.1: the
// HS map is rebuilt as the object moves; the material on a span moves with
// it).
//
// Translation: the map's grid moves with the object's horizontal position
// (heightspan_model.h), so the spans and their material keep their cells
// and only shift in z; no material is re-sampled, at any speed.
// Rotation: the map is peeled again at the new pose, and the material of
// every old span is carried as a column: the centre of its material
// (cell centre, top + material / 2) is moved rigidly with the object and its
// volume lands in the new cell holding that point, on the span it rests on;
// a point that the re-sampling put inside a span's solid leaves it by the
// nearer end (over the top onto it, or out of its bottom); where no span is
// under it, it is in the air and becomes a particle there, moving as the
// object's point there moves (rigid_velocity.h). Then
// material that would reach into the span above is pushed onto it. Volume
// is conserved exactly; the surface is re-sampled at the nearest cell, so a
// turn roughens it, and erosion smooths it again.

#include <random>

#include <Eigen/Core>

#include "models/core/geometry/triangle_mesh.h"
#include "models/heightspan/rigid_velocity.h"

namespace repose {

struct HeightSpanModel;
struct HeldObject;
struct ObjectSpans;
struct ParticleSystem;
class SpanPeeler;

struct MotionReport {
  bool resampled = false;    // the object turned: peeled again
  double released_m3 = 0.0;  // material left in the air by the turn
};

// Rotations below this (rad) count as none: keyframes of one orientation
// interpolate to it only to round-off.
inline constexpr double kNoRotationRad = 1e-9;

MotionReport move_spans(const HeightSpanModel& model, const HeldObject& held, const Pose& to,
                        const RigidVelocity& velocity, SpanPeeler& peeler, ObjectSpans* spans,
                        ParticleSystem* particles, std::mt19937_64* rng);

}  // namespace repose
