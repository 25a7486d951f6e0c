#include "models/heightspan/span_motion.h"

#include "models/heightspan/heightspan_model.h"
#include "models/heightspan/heightspan_state.h"

namespace repose {

namespace {

void translate(const HeightSpanModel& model, const HeldObject& held, const Pose& to, ObjectSpans* spans) {
  const double dz = to.position_m.z() - spans->pose.position_m.z();
  for (Span& s : spans->map.spans) {
    s.bottom_m += dz;
    s.top_m += dz;
  }
  spans->map.grid = model.map_grid(held, to);
  spans->pose.position_m = to.position_m;  // the orientation it was peeled at stays
}

// The span material at `at` rests on (index in its cell), or -1 when it
// is in the air. Material re-sampled into a solid span leaves it by the
// nearer end: over the top onto it, or out of the bottom (onto the span
// below, or into the air under it: `at` is moved there).
int resting_span(const SpanMap& map, std::int64_t cell, Eigen::Vector3d* at) {
  const int k = span_under(map, cell, at->z());
  if (k < 0) return k;
  const Span& s = map.begin(cell)[k];
  if (at->z() >= s.top_m || s.top_m - at->z() <= at->z() - s.bottom_m) return k;
  at->z() = s.bottom_m;
  return k - 1;
}

// The old map's material carried rigidly onto the new map.
double carry_material(const SpanMap& old_map, const Pose& from, const Pose& to, const RigidVelocity& velocity,
                      double spread_m_s, SpanMap* map, ParticleSystem* particles, std::mt19937_64* rng) {
  const Eigen::Matrix3d turn = (to.orientation * from.orientation.conjugate()).toRotationMatrix();
  const double area = old_map.grid.cell_area_m2();
  double released = 0.0;
  for (int j = 0; j < old_map.grid.ny; ++j) {
    for (int i = 0; i < old_map.grid.nx; ++i) {
      const std::int64_t c = old_map.cell(i, j);
      const Span* s = old_map.begin(c);
      for (int k = 0; k < old_map.count(c); ++k) {
        if (!(s[k].material_m > 0.0)) continue;
        const Eigen::Vector3d p(old_map.grid.centre_x(i), old_map.grid.centre_y(j),
                                s[k].top_m + 0.5 * s[k].material_m);
        const Eigen::Vector3d q = turn * (p - from.position_m) + to.position_m;
        int ni, nj;
        Eigen::Vector3d at = q;
        const int under = map->cell_at(q.x(), q.y(), &ni, &nj) ? resting_span(*map, map->cell(ni, nj), &at) : -1;
        if (under >= 0) {
          map->begin(map->cell(ni, nj))[under].material_m += s[k].material_m;
          continue;
        }
        particles->release({at, velocity.at(at), s[k].material_m * area}, spread_m_s, rng);
        released += s[k].material_m * area;
      }
    }
  }
  return released;
}

}  // namespace

MotionReport move_spans(const HeightSpanModel& model, const HeldObject& held, const Pose& to,
                        const RigidVelocity& velocity, SpanPeeler& peeler, ObjectSpans* spans,
                        ParticleSystem* particles, std::mt19937_64* rng) {
  MotionReport report;
  if (spans->pose.orientation.angularDistance(to.orientation) <= kNoRotationRad) {
    translate(model, held, to, spans);
    return report;
  }
  const ObjectSpec& object = model.ground.objects[static_cast<std::size_t>(held.object)];
  SpanMap map = peeler.peel(transformed(object.body, to), model.map_grid(held, to));
  report.resampled = true;
  report.released_m3 = carry_material(spans->map, spans->pose, to, velocity, model.options.particle_spread_m_s,
                                      &map, particles, rng);
  for (std::int64_t c = 0; c < static_cast<std::int64_t>(map.grid.cell_count()); ++c) push_overflow_up(&map, c);
  spans->map = std::move(map);
  spans->pose = to;
  return report;
}

}  // namespace repose
