#pragma once
// Erosion on an object's spans (the height-span paper, 2.4.2), with the
// ground model's slope rule (models/ground/erosion.h: sigma times the excess
// over cell_size * tan(theta), a Jacobi update per pass, stable for
// sigma <= 1/4, excess below kErosionToleranceFraction * cell ignored).
//
// A column of the map holds surfaces material can lie on: each span's top
// (its level: top + material) and the ground under the column where no
// span rests on it. Material at level L leaves a column sideways into the
// neighbouring column at height L: there it lands on the highest surface
// whose solid top is at or below L, unless L is inside the neighbour's solid
// (a wall), which blocks the pair. So pairs are found per span, as the
// paper asks ("per span, the neighbouring spans where collapse can occur"):
//   span to span:  material on one span slides onto a neighbouring span;
//   span to ground: off the edge of the object onto the ground beside it.
//     Where the span's top is at most near_ground_cells above that ground,
//     the material moves straight onto the ground; higher up it leaves as
//     a particle, released at the neighbour's cell centre at the level it
//     left, with the velocity of the object's point there (rigid_velocity.h,
//     particles.h);
//   ground to span: ground higher than a neighbouring span's level slides
//     onto it (a heap beside a buried or pressed bucket spills in);
//   ground to ground is the ground model's (models/ground/erosion.h).
// Unsupported material (a departure from the paper's rule, which moves only
// sigma times the excess per pass whatever the surface underneath): where a
// span's own solid top falls to a neighbour's surface (a span's top, the
// ground, or nothing: air) by more than cell_size * tan(theta), nothing can
// rest on it, so all of its material slides that way in the pass, shared
// among such neighbours by their drop (each drop counted up to one cell). A
// tipped bucket therefore empties at En cells per step on any cell size
// rather than by sigma's trickle, and at the tilt set by theta: the slope
// rule alone left a 45-degree wall of a bucket tipped by 135 deg holding
// sand for 0.4 s, where the DEM empties it in 0.25 s
// (experiments/heightspan_scoop_fit_deep_mean_bed.yaml). Material thinner than 1e-12 cell
// is round-off and stays put.
// A surface gives at most what it has (a span its material, the ground its
// height) and takes at most its room (up to the bottom of the span above
// it, where there is one): all of a pass's fluxes are scaled down together
// where they would exceed either. The map's own columns and one ring of
// ground around it are examined; En passes of the spans' material (the
// ground's base material, heightspan_model.h).

#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "models/heightspan/rigid_velocity.h"

namespace repose {

struct GroundParams;
struct HeightSpanModel;
struct ObjectSpans;
struct GroundState;
struct ParticleSystem;

namespace span_erosion_detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

enum class Kind : std::uint8_t { kSpan, kGround, kAir };

// One pass's move of material off a surface (a span or the ground beside
// the map) onto the surface it lands on (a span, the ground, or air: it
// leaves as a particle). Where material lies or lands: a span is its index in
// map.spans, the ground or air its column's local index (ring included: see
// Columns::local in span_erosion.cpp).
struct Flux {
  double amount_m;
  double room_or_z_m;   // to a span or the ground: the room it has (>= 0); to air: the height it leaves at
  double* from_m;       // what the source holds: a span's material or the ground's height
  double* to_m;         // the same of the target; nullptr for air
  std::int32_t to_key;  // the target's entry in the pass's inflow sums: a span's index, else span count + column
  std::int32_t from_local, to_local;  // the columns (local indices) of source and target
  Kind from_kind, to_kind;
};
}  // namespace span_erosion_detail

// What erode_spans reuses from call to call (no allocation per step once
// grown); its contents between calls mean nothing, except that `in` is all 0.
struct SpanErosionScratch {
  std::vector<span_erosion_detail::Flux> fluxes;
  std::vector<double> in, released_m, release_z;  // in: all 0 between passes
  std::vector<double> released_dx, released_dy;   // per column: the released material's sum of amount x its way (cells)
  std::vector<std::size_t> released_at;
  std::vector<char> changed;  // per column (ring included): it or a neighbour changed in the last pass
};

struct SpanErosionResult {
  int passes = 0;
  long long moves = 0;
  double to_ground_m3 = 0.0;
  double from_ground_m3 = 0.0;
  double to_particles_m3 = 0.0;
};

SpanErosionResult erode_spans(const HeightSpanModel& model, const GroundParams& params,
                              const RigidVelocity& velocity, ObjectSpans* spans, GroundState* ground,
                              ParticleSystem* particles, std::mt19937_64* rng);

}  // namespace repose
