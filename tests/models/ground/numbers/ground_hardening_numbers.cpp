// Prints the figures of issue 16 for the ground model (no assertions; the
// invariants are asserted by the tests in tests/models/ground/):
//   drag:   a sphere of radius 5 cm pressed 2 cm into a 5 cm sand bed of
//           0.4 m x 0.4 m at 2 mm cells, dragged 0.2 m along +x (and -x, +y,
//           the diagonal): the largest difference between the field and its
//           mirror about the drag's axis, the volume on each side, the
//           highest cell at any step (and where), at t = 1.0 s and at the end;
//   settle: the same sphere pressed 3 cm into the same bed and lifted out,
//           then left alone: the steepest neighbour slope over time, and the
//           time it takes to come within the stated tolerance of 30 deg.
// Run: build/tests/ground_hardening_numbers [uv|octa [drag|settle]] (default: both bodies, all).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>

#include "models/ground/erosion.h"
#include "tests/models/ground/ground_fixtures.h"

namespace repose {
namespace {

using namespace repose::testing;

constexpr double kBed = 0.05, kRadius = 0.05, kCell = 0.002;
constexpr int kCells = 200;
constexpr double kStep = 0.02;

// The largest |h - h mirrored| over the field, for a mirror about the drag's
// axis through the grid's centre: x = 0 (drag along y), y = 0 (along x), or the diagonal.
enum class Mirror { kAboutX, kAboutY, kAboutDiagonal };

double mirror_difference(const HeightField& h, Mirror m) {
  const int n = h.nx();
  double worst = 0.0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int mi = m == Mirror::kAboutY ? n - 1 - i : (m == Mirror::kAboutDiagonal ? j : i);
      const int mj = m == Mirror::kAboutX ? n - 1 - j : (m == Mirror::kAboutDiagonal ? i : j);
      worst = std::max(worst, std::abs(h.at(i, j) - h.at(mi, mj)));
    }
  }
  return worst;
}

// Volume on the +y side (drags along x), the +x side (along y) or above the
// diagonal, minus on the other side (m^3).
double side_imbalance(const HeightField& h, Mirror m) {
  const int n = h.nx();
  double plus = 0.0, minus = 0.0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const int k = m == Mirror::kAboutX ? 2 * j - (n - 1) : (m == Mirror::kAboutY ? 2 * i - (n - 1) : j - i);
      if (k > 0) plus += h.at(i, j);
      if (k < 0) minus += h.at(i, j);
    }
  }
  return (plus - minus) * kCell * kCell;
}

struct Highest {
  double height_m = 0.0, x_m = 0.0, y_m = 0.0, time_s = 0.0;
};

void track_highest(const GroundState& s, const GroundModel& model, Highest* best) {
  Eigen::Index r, c;
  const double top = s.height.heights().maxCoeff(&r, &c);
  if (top > best->height_m) {
    *best = {top, model.grid.centre_x(static_cast<int>(c)), model.grid.centre_y(static_cast<int>(r)), s.time_s};
  }
}

int cells_above(const HeightField& h, double z) { return static_cast<int>((h.heights() > z).count()); }

ObjectSpec ball(const std::string& body, std::vector<Keyframe> keys) {
  ObjectSpec o = sphere(kRadius, std::move(keys));
  if (body == "octa") o.body = make_octasphere(kRadius, 5);
  return o;
}

// Pressed 2 cm at `from` over 0.3 s, dragged 0.2 m along `dir` over 1 s, lifted over 0.2 s, 0.5 s more.
void drag(const std::string& body, const Eigen::Vector2d& dir, Mirror mirror, const char* label) {
  const double low = kBed + kRadius - 0.02, high = kBed + kRadius + 0.005;
  const Eigen::Vector2d a = -0.1 * dir, b = 0.1 * dir;
  ObjectSpec o = ball(body, {at(0, a.x(), a.y(), high), at(0.3, a.x(), a.y(), low), at(1.3, b.x(), b.y(), low),
                             at(1.5, b.x(), b.y(), 0.2)});
  Scene scene = flat_scene(centred_grid(kCells, kCells, kCell), kBed, sand(), {o}, 2);
  scene.time.step_s = kStep;
  const GroundModel model = build_ground_model(scene);
  const GroundParams params = default_params(model);
  GroundState state = make_ground_state(model, HeightField(model.grid, kBed));
  auto renderer = make_cpu_underside_renderer();
  Highest highest;
  double min_height = kBed;
  const int steps = model.time.step_count();
  for (int s = 0; s < steps; ++s) {
    step(model, params, *renderer, &state);
    track_highest(state, model, &highest);
    min_height = std::min(min_height, state.height.min_height_m());
    if (std::abs(state.time_s - 1.0) < 0.5 * kStep) {
      std::printf("  %-9s %s t=1.0 s: mirror difference %.3g mm, left-right %.3g m^3, highest %.4f m, "
                  "%d cells above 0.10 m\n",
                  label, body.c_str(), 1e3 * mirror_difference(state.height, mirror),
                  side_imbalance(state.height, mirror), state.height.max_height_m(), cells_above(state.height, 0.1));
    }
  }
  std::printf("  %-9s %s t=%.1f s: mirror difference %.3g mm, left-right %.3g m^3, highest %.4f m; "
              "highest at any step %.4f m at (%.3f, %.3f) t=%.2f s; lowest %.4f m; imbalance %.2g m^3\n",
              label, body.c_str(), state.time_s, 1e3 * mirror_difference(state.height, mirror),
              side_imbalance(state.height, mirror), state.height.max_height_m(), highest.height_m, highest.x_m,
              highest.y_m, highest.time_s, min_height, state.ledger.imbalance_m3(state.height.volume_m3()));
}

// Steepest 4-neighbour slope (deg) and the pairs steeper than tan(theta)
// beyond erosion's tolerance (erosion.h).
std::pair<double, int> steepest(const HeightField& h, double tan_theta) {
  const ArrayXXdR& a = h.heights();
  const ArrayXXdR dx = (a.rightCols(a.cols() - 1) - a.leftCols(a.cols() - 1)).abs() / kCell;
  const ArrayXXdR dy = (a.bottomRows(a.rows() - 1) - a.topRows(a.rows() - 1)).abs() / kCell;
  const double top = std::max(dx.maxCoeff(), dy.maxCoeff());
  const double limit = tan_theta + kErosionToleranceFraction;
  const int over = static_cast<int>((dx > limit).count() + (dy > limit).count());
  return {std::atan(top) * 180.0 / std::numbers::pi, over};
}

// Pressed 3 cm over 0.3 s, held 0.1 s, lifted over 0.2 s; then alone until
// the erosion memory is empty (at most 300 s).
void settle(const std::string& body, int memory_steps, int erosion_iterations) {
  const double low = kBed + kRadius - 0.03, high = kBed + kRadius + 0.005, lifted_s = 0.6;
  ObjectSpec o = ball(body, {at(0, 0, 0, high), at(0.3, 0, 0, low), at(0.4, 0, 0, low), at(lifted_s, 0, 0, 0.2)});
  Material m = sand();
  m.erosion_iterations = erosion_iterations;
  Scene scene = flat_scene(centred_grid(kCells, kCells, kCell), kBed, m, {o}, 300);
  scene.time.step_s = kStep;
  scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& spec) { spec.erosion_memory_steps = memory_steps; });
  const GroundModel model = build_ground_model(scene);
  const GroundParams params = default_params(model);
  GroundState state = make_ground_state(model, HeightField(model.grid, kBed));
  auto renderer = make_cpu_underside_renderer();
  const double tan_theta = std::tan(m.repose_angle_rad);
  const double tolerance_deg = 0.01;
  double within_s = -1.0;
  const auto start = std::chrono::steady_clock::now();
  const int steps = model.time.step_count();
  for (int s = 0; s < steps && (state.time_s < lifted_s || !state.erosion.empty()); ++s) {
    step(model, params, *renderer, &state);
    const auto [deg, over] = steepest(state.height, tan_theta);
    if (state.time_s > lifted_s && within_s < 0.0 && deg <= 30.0 + tolerance_deg) within_s = state.time_s;
    if (state.step_index == 90 || state.step_index == 240) {
      std::printf("  settle %s memory %d En %d t=%.1f s: steepest %.3f deg, %d pairs above tan(theta), "
                  "remembered %zu\n",
                  body.c_str(), memory_steps, erosion_iterations, state.time_s, deg, over, state.erosion.cells().size());
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const auto [deg, over] = steepest(state.height, tan_theta);
  std::printf("  settle %s memory %d En %d: within %.2f deg of 30 deg %.2f s after lift-out; memory empty %s "
              "%.2f s after lift-out, then steepest %.5f deg, %d pairs above tan(theta) + tolerance; "
              "lowest %.4f m; wall %.2f s\n",
              body.c_str(), memory_steps, erosion_iterations, tolerance_deg, within_s < 0 ? -1.0 : within_s - lifted_s,
              state.erosion.empty() ? "" : "NOT (run ended)", state.time_s - lifted_s, deg, over,
              state.height.min_height_m(), wall);
}

}  // namespace
}  // namespace repose

int main(int argc, char** argv) {
  using repose::Mirror;
  std::vector<std::string> bodies = {"uv", "octa"};
  if (argc > 1) bodies = {argv[1]};
  const std::string only = argc > 2 ? argv[2] : "";
  const double d = std::sqrt(0.5);
  for (const std::string& body : bodies) {
    std::printf("%s sphere:\n", body == "uv" ? "UV (scene loader's)" : "octahedral");
    if (only != "settle") {
      repose::drag(body, {1, 0}, Mirror::kAboutX, "+x");
      repose::drag(body, {-1, 0}, Mirror::kAboutX, "-x");
      repose::drag(body, {0, 1}, Mirror::kAboutY, "+y");
      repose::drag(body, {d, d}, Mirror::kAboutDiagonal, "diagonal");
    }
    if (only != "drag") {
      repose::settle(body, 30, 5);
      repose::settle(body, 5, 1);
      repose::settle(body, 1000, 200);
    }
  }
  return 0;
}
