#include "models/heightspan/particles.h"

#include <cmath>
#include <limits>

#include "models/ground/ground_model.h"
#include "models/ground/ground_state.h"

namespace repose {

namespace {

struct Landing {
  double level_m = -std::numeric_limits<double>::infinity();
  SpanMap* map = nullptr;
  std::int64_t cell = -1;
  int span = -1;  // within the cell; -1: the ground
};

// The highest span surface the particle crossed from z0 down to z1 at (x, y).
void land_on_spans(std::vector<SpanMap*>& maps, const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, Landing* best) {
  for (SpanMap* map : maps) {
    int i, j;
    if (!map->cell_at(p1.x(), p1.y(), &i, &j)) continue;
    const std::int64_t c = map->cell(i, j);
    const Span* s = map->begin(c);
    for (int k = map->count(c) - 1; k >= 0; --k) {
      const double level = s[k].level_m();
      if (level <= p0.z() && level >= p1.z() && level > best->level_m) *best = {level, map, c, k};
    }
  }
}

}  // namespace

double ParticleSystem::in_flight_m3() const {
  double sum = 0.0;
  for (const Particle& p : particles) sum += p.volume_m3;
  return sum;
}

void ParticleSystem::release(Particle p, double spread_m_s, std::mt19937_64* rng) {
  if (spread_m_s > 0.0) {
    std::normal_distribution<double> spread(0.0, spread_m_s);
    p.velocity_m_s.x() += spread(*rng);
    p.velocity_m_s.y() += spread(*rng);
  }
  built = true;
  ++released;
  particles.push_back(p);
}

void advance_particles(double dt_s, const GroundModel& model, std::vector<SpanMap*> maps, ParticleSystem* system,
                       GroundState* ground) {
  if (system->particles.empty()) return;
  const Grid& g = model.grid;
  const Eigen::Vector3d gravity(0.0, 0.0, -kGravityMs2);
  std::vector<Particle> flying;
  flying.reserve(system->particles.size());
  for (Particle p : system->particles) {
    const Eigen::Vector3d p0 = p.position_m;
    const Eigen::Vector3d p1 = p0 + p.velocity_m_s * dt_s + 0.5 * gravity * dt_s * dt_s;
    p.position_m = p1;
    p.velocity_m_s += gravity * dt_s;
    const int gi = static_cast<int>(std::floor((p1.x() - g.origin_x_m) / g.cell_size_m));
    const int gj = static_cast<int>(std::floor((p1.y() - g.origin_y_m) / g.cell_size_m));
    if (!(std::isfinite(p1.x()) && std::isfinite(p1.y())) || !g.contains(gi, gj)) {
      ground->ledger.left_grid_m3 += p.volume_m3;  // gone sideways off the grid
      ++system->left_grid;
      continue;
    }
    Landing best;
    land_on_spans(maps, p0, p1, &best);
    const double height = ground->height.at(gi, gj);
    if (p1.z() <= height && height >= best.level_m) best = {height, nullptr, -1, -1};
    if (best.level_m == -std::numeric_limits<double>::infinity()) {
      flying.push_back(p);
      continue;
    }
    if (best.map != nullptr) {
      best.map->begin(best.cell)[best.span].material_m += p.volume_m3 / g.cell_area_m2();
      push_overflow_up(best.map, best.cell);
      ++system->landed_on_spans;
    } else {
      ground->height.at(gi, gj) += p.volume_m3 / g.cell_area_m2();
      ground->erosion.touch(model.cell(gi, gj));
      ++system->landed_on_ground;
    }
  }
  system->particles = std::move(flying);
}

}  // namespace repose
