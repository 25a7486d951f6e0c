// Randomized invariant tests of the ground model: seeded random scenes
// (random objects, sizes, keyframed presses, drags and rolls, materials
// within their valid ranges, grid sizes) run through the model, checking
// what must hold for every scene:
//   - volume balance: initial = final + compressed + left the grid, to round-off;
//   - no NaN or infinite height;
//   - no cell above a (fine-grid) object's underside at the end of a step;
//   - after the objects have left and the slopes settled, no slope steeper
//     than its material's tan(theta) + kErosionToleranceFraction (erosion.h);
//   - determinism: the same scene twice gives bit-identical heights.
// Every failure names its seed. Replay one: REPOSE_SEED=123 repose_ground_tests
// --gtest_filter='RandomizedInvariants.*'. REPOSE_RANDOM_CASES sets how many
// seeds run (scripts/test-sanitized.sh lowers it under the sanitizers).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "models/core/geometry/depth_image.h"
#include "models/core/config/scene.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/ground/collision.h"
#include "models/ground/erosion.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"
#include "models/ground/ground_step.h"

namespace repose {
namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr int kDefaultCases = 300;  // about 6 s in Release
// Steps allowed for the slopes to settle once every object has left.
constexpr int kMaxSettleSteps = 50000;
// Heights may exceed an underside by round-off only (swept and end-pose
// meshes are transformed separately; times differ by an ulp).
constexpr double kCeilingToleranceM = 1e-9;

int case_count() {
  const char* text = std::getenv("REPOSE_RANDOM_CASES");
  if (text == nullptr) return kDefaultCases;
  return std::max(1, std::atoi(text));
}

std::vector<std::uint64_t> seeds_to_run() {
  if (const char* replay = std::getenv("REPOSE_SEED")) return {std::strtoull(replay, nullptr, 10)};
  std::vector<std::uint64_t> seeds;
  for (int k = 0; k < case_count(); ++k) seeds.push_back(1000 + static_cast<std::uint64_t>(k));
  return seeds;
}

double uniform(std::mt19937_64& rng, double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
int uniform_int(std::mt19937_64& rng, int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); }
bool coin(std::mt19937_64& rng, double p_true) { return std::bernoulli_distribution(p_true)(rng); }

// A material anywhere in the valid ranges of validate() (ground_params.h),
// theta kept above 10 degrees so that settling takes a bounded number of steps.
Material random_material(std::mt19937_64& rng) {
  Material m;
  m.name = "random";
  m.alpha = coin(rng, 0.2) ? (coin(rng, 0.5) ? 0.0 : 1.0) : uniform(rng, 0.0, 1.0);
  m.repose_angle_rad = coin(rng, 0.1) ? std::numbers::pi / 2 : uniform(rng, 10.0, 89.0) * kDegree;
  m.sigma = coin(rng, 0.1) ? kSigmaMax : uniform(rng, 0.02, kSigmaMax);
  m.erosion_iterations = uniform_int(rng, 1, 8);
  return m;
}

Eigen::Quaterniond random_orientation(std::mt19937_64& rng) {
  const Eigen::Vector3d axis = Eigen::Vector3d(uniform(rng, -1, 1), uniform(rng, -1, 1), uniform(rng, -1, 1));
  if (axis.norm() < 1e-3) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(uniform(rng, 0, 2 * std::numbers::pi), axis.normalized()));
}

// A primitive with a size between 1.5 cells and a third of the grid.
ObjectSpec random_object(std::mt19937_64& rng, const Grid& grid, int index) {
  const double h = grid.cell_size_m;
  const double max_size = std::max(2.0 * h, std::min(grid.extent_x_m(), grid.extent_y_m()) / 3.0);
  auto size = [&] { return uniform(rng, 1.5 * h, max_size); };
  ObjectSpec o;
  o.name = "object" + std::to_string(index);
  switch (uniform_int(rng, 0, 3)) {
    case 0:
      o.shape = ObjectSpec::Shape::kSphere;
      o.radius_m = 0.5 * size();
      o.body = make_sphere(o.radius_m, 16);
      break;
    case 1:
      o.shape = ObjectSpec::Shape::kBox;
      o.half_extents_m = 0.5 * Eigen::Vector3d(size(), size(), size());
      o.body = make_box(o.half_extents_m);
      break;
    case 2:
      o.shape = ObjectSpec::Shape::kCapsule;
      o.radius_m = 0.25 * size();
      o.half_height_m = 0.5 * size();
      o.body = make_capsule(o.radius_m, o.half_height_m, 16);
      break;
    default:
      o.shape = ObjectSpec::Shape::kCylinder;
      o.radius_m = 0.25 * size();
      o.half_height_m = 0.5 * size();
      o.body = make_cylinder(o.radius_m, o.half_height_m, 16);
      break;
  }
  return o;
}

// Keyframes: start above the ground, then a press (down and up in place),
// a drag (down, along the ground, up) or a roll (a drag that also turns);
// the last keyframe lifts the object clear so that the ground can settle.
std::vector<Keyframe> random_motion(std::mt19937_64& rng, const ObjectSpec& object, const Grid& grid, double ground_m,
                                    double step_s, int steps) {
  const Aabb box = bounding_box(object.body);
  const double reach = (box.max - box.min).norm();  // clears the ground in any orientation
  auto random_xy = [&] {
    // a little beyond the grid too, so that material is pushed off its edge
    const double margin = 0.2 * grid.extent_x_m();
    return Eigen::Vector2d(uniform(rng, grid.origin_x_m - margin, grid.origin_x_m + grid.extent_x_m() + margin),
                           uniform(rng, grid.origin_y_m - 0.2 * grid.extent_y_m(),
                                   grid.origin_y_m + 1.2 * grid.extent_y_m()));
  };
  const double depth = uniform(rng, 0.0, 0.8) * (box.max.z() - box.min.z());
  const double high_z = ground_m + reach + grid.cell_size_m;
  const double low_z = ground_m - box.min.z() - depth;  // the body's lowest point `depth` below the surface
  const Eigen::Quaterniond start = coin(rng, 0.5) ? Eigen::Quaterniond::Identity() : random_orientation(rng);
  const int kind = uniform_int(rng, 0, 2);
  const Eigen::Vector2d a = random_xy(), b = random_xy();
  const double duration_s = step_s * steps;

  std::vector<Keyframe> keys;
  auto key = [&](double fraction, const Eigen::Vector2d& xy, double z, const Eigen::Quaterniond& q) {
    Keyframe k;
    k.time_s = fraction * duration_s;
    k.pose.position_m = Eigen::Vector3d(xy.x(), xy.y(), z);
    k.pose.orientation = q;
    keys.push_back(k);
  };
  key(0.0, a, high_z, start);
  if (kind == 0) {  // press
    key(uniform(rng, 0.2, 0.5), a, low_z, start);
    key(uniform(rng, 0.55, 0.8), a, low_z, start);
  } else {  // drag, or roll: turning about the horizontal axis across the motion
    const Eigen::Vector2d d = b - a;
    const Eigen::Vector3d across = d.norm() > 0 ? Eigen::Vector3d(-d.y(), d.x(), 0).normalized() : Eigen::Vector3d::UnitX();
    const Eigen::Quaterniond end =
        kind == 2 ? Eigen::Quaterniond(Eigen::AngleAxisd(uniform(rng, 0.5, 3.0), across)) * start : start;
    key(uniform(rng, 0.1, 0.3), a, low_z, start);
    key(uniform(rng, 0.5, 0.8), b, low_z, end);
  }
  key(0.9, keys.back().pose.position_m.head<2>(), high_z, keys.back().pose.orientation);
  return keys;
}

struct RandomCase {
  Scene scene;
  double ground_m = 0.0;
  std::string summary;  // printed with every failure
};

RandomCase random_case(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  RandomCase c;
  Scene& s = c.scene;
  s.name = "random_" + std::to_string(seed);
  s.seed = seed;
  s.ground.grid.nx = uniform_int(rng, 4, 48);
  s.ground.grid.ny = uniform_int(rng, 4, 48);
  s.ground.grid.cell_size_m = uniform(rng, 0.002, 0.02);
  s.ground.grid.origin_x_m = uniform(rng, -1.0, 0.0) * s.ground.grid.extent_x_m();
  s.ground.grid.origin_y_m = uniform(rng, -1.0, 0.0) * s.ground.grid.extent_y_m();
  c.ground_m = uniform(rng, 0.0, 0.1);
  s.ground.initial.height_m = c.ground_m;
  Material ground_material = random_material(rng);
  ground_material.name = "random_ground";
  s = with_material(std::move(s), ground_material);
  s.ground.material = ground_material.name;
  const int regions = uniform_int(rng, 0, 2);
  for (int r = 0; r < regions; ++r) {
    MaterialRegion region;
    Material region_material = random_material(rng);
    region_material.name = "random_region_" + std::to_string(r);
    s = with_material(std::move(s), region_material);
    region.material = region_material.name;
    const Grid& g = s.ground.grid;
    const double x0 = uniform(rng, g.origin_x_m, g.origin_x_m + g.extent_x_m());
    const double y0 = uniform(rng, g.origin_y_m, g.origin_y_m + g.extent_y_m());
    region.x_min_m = x0;
    region.x_max_m = x0 + uniform(rng, 0.0, g.extent_x_m());
    region.y_min_m = y0;
    region.y_max_m = y0 + uniform(rng, 0.0, g.extent_y_m());
    s.ground.regions.push_back(region);
  }
  s.time.step_s = uniform(rng, 0.01, 0.1);
  const int steps = uniform_int(rng, 3, 12);
  s.time.duration_s = s.time.step_s * steps;
  GroundModelSpec options;
  options.sweep = coin(rng, 0.7);
  options.substeps = uniform_int(rng, 1, 3);
  options.max_substep_angle_rad = uniform(rng, 2.0, 20.0) * kDegree;
  options.erosion_memory_steps = 65000;  // cells keep settling until they are settled
  options.coarse_factor = uniform_int(rng, 1, 3);
  s = with_ground_options(std::move(s), options);
  const int objects = uniform_int(rng, 1, 3);
  for (int o = 0; o < objects; ++o) {
    ObjectSpec object = random_object(rng, s.ground.grid, o);
    object.simple = coin(rng, 0.15);
    object.keyframes = random_motion(rng, object, s.ground.grid, c.ground_m, s.time.step_s, steps);
    s.objects.push_back(std::move(object));
  }
  std::ostringstream text;
  text << "seed " << seed << " (replay: REPOSE_SEED=" << seed << "): grid " << s.ground.grid.nx << "x"
       << s.ground.grid.ny << " cell " << s.ground.grid.cell_size_m << " m, " << objects << " objects, " << steps
       << " steps, sweep " << options.sweep << ", " << regions << " regions";
  c.summary = text.str();
  return c;
}

// Where a cell stands highest above a (fine-grid) object's underside at
// the objects' poses at `time_s`.
struct CeilingExcess {
  double excess_m = -std::numeric_limits<double>::infinity();
  int object = -1, i = -1, j = -1;
  std::string describe() const {
    std::ostringstream text;
    text << "cell (" << i << ", " << j << ") stands " << excess_m << " m above object " << object << "'s underside";
    return text.str();
  }
};

CeilingExcess worst_ceiling_excess(const GroundModel& model, const HeightField& height, double time_s) {
  CeilingExcess worst;
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const Pose pose = model.objects[o].pose_at(time_s);
    if (uses_coarse_grid(model, static_cast<int>(o), pose)) continue;  // coarse contact: a coarser ceiling
    const DepthImage under = depth_image_cpu({transformed(model.objects[o].body, pose)}, model.grid, ViewFrom::kBelow);
    for (int j = 0; j < model.grid.ny; ++j) {
      for (int i = 0; i < model.grid.nx; ++i) {
        if (under.is_covered(i, j) && height.at(i, j) - under.z(i, j) > worst.excess_m) {
          worst = {height.at(i, j) - under.z(i, j), static_cast<int>(o), i, j};
        }
      }
    }
  }
  return worst;
}

// Largest excess of a neighbour pair's slope over tan(theta) of the higher
// cell's material (the pair's material, erosion.h).
double worst_slope_excess(const GroundModel& model, const GroundParams& params, const HeightField& height) {
  const Grid& g = model.grid;
  double worst = -std::numeric_limits<double>::infinity();
  auto pair = [&](int i0, int j0, int i1, int j1) {
    const double a = height.at(i0, j0), b = height.at(i1, j1);
    const std::int64_t high = a >= b ? model.cell(i0, j0) : model.cell(i1, j1);
    const Material& m = params.materials[static_cast<std::size_t>(model.material_at(high))];
    if (m.repose_angle_rad >= std::numbers::pi / 2) return;  // vertical walls allowed
    worst = std::max(worst, std::abs(a - b) / g.cell_size_m - std::tan(m.repose_angle_rad));
  };
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      if (i + 1 < g.nx) pair(i, j, i + 1, j);
      if (j + 1 < g.ny) pair(i, j, i, j + 1);
    }
  }
  return worst;
}

struct Outcome {
  HeightField final_height;
  bool settled = false;
};

// Runs the scene's steps, checking after each the invariants that hold at
// every step, then keeps stepping (objects lifted clear, erosion memory
// long) until erosion moves nothing. check_ceiling: also that no cell stands
// above an object's underside after a step.
Outcome run_and_check(const RandomCase& c, bool check_ceiling) {
  const GroundModel model = build_ground_model(c.scene);
  const GroundParams params = default_params(model);
  validate(params, model);
  GroundState state = make_ground_state(model, HeightField(model.grid, c.ground_m));
  auto renderer = make_cpu_underside_renderer();
  const double volume_scale = std::abs(state.ledger.initial_m3) + 1e-15;
  auto check_state = [&](const char* when) {
    const std::string where = c.summary + ", " + when + " step " + std::to_string(state.step_index);
    EXPECT_TRUE(state.height.all_finite()) << where;
    EXPECT_NEAR(state.ledger.imbalance_m3(state.height.volume_m3()), 0.0, 1e-11 * volume_scale)
        << where << ": initial " << state.ledger.initial_m3 << " final " << state.height.volume_m3() << " compressed "
        << state.ledger.compressed_m3 << " left " << state.ledger.left_grid_m3;
    EXPECT_GE(state.ledger.compressed_m3, 0.0) << where;
    EXPECT_GE(state.ledger.left_grid_m3, 0.0) << where;
    if (check_ceiling) {
      const CeilingExcess e = worst_ceiling_excess(model, state.height, state.time_s);
      EXPECT_LE(e.excess_m, kCeilingToleranceM) << where << ": " << e.describe();
    }
  };
  const int steps = model.time.step_count();
  for (int s = 0; s < steps; ++s) {
    step(model, params, *renderer, &state);
    check_state("after scripted");
    if (::testing::Test::HasFailure()) return {state.height, false};
  }
  Outcome outcome;
  for (int s = 0; s < kMaxSettleSteps && !outcome.settled; ++s) {
    const StepReport r = step(model, params, *renderer, &state);
    outcome.settled = r.erosion.moves == 0 && r.contact_cells == 0;
  }
  check_state("after settling,");
  outcome.final_height = state.height;
  return outcome;
}

// Volume balance, finite heights, the slope bound once settled, determinism.
TEST(RandomizedInvariants, RandomScenesBalanceSettleAndRepeat) {
  for (const std::uint64_t seed : seeds_to_run()) {
    const RandomCase c = random_case(seed);
    const Outcome first = run_and_check(c, false);
    if (::testing::Test::HasFailure()) return;  // the failure names the seed
    ASSERT_TRUE(first.settled) << c.summary << ": slopes still moving after " << kMaxSettleSteps << " steps";
    const GroundModel model = build_ground_model(c.scene);
    EXPECT_LE(worst_slope_excess(model, default_params(model), first.final_height), 1.01 * kErosionToleranceFraction)
        << c.summary << ": a settled slope is steeper than its material's angle of repose";
    // determinism: the same scene again, bit for bit
    const Outcome second = run_and_check(c, false);
    EXPECT_TRUE((first.final_height.heights() == second.final_height.heights()).all())
        << c.summary << ": two runs of the same scene differ";
    if (::testing::Test::HasFailure()) return;
  }
}

// Never above an object (displacement.h, erosion.h): after every step, no
// cell stands above the underside of a fine-grid object at its pose then.
TEST(RandomizedInvariants, RandomScenesStayBelowObjectUndersides) {
  for (const std::uint64_t seed : seeds_to_run()) {
    run_and_check(random_case(seed), true);
    if (::testing::Test::HasFailure()) return;  // the failure names the seed
  }
}

// The generator itself: the same seed makes the same scene, so a printed
// seed replays the failure it came from.
TEST(RandomizedInvariants, SameSeedSameScene) {
  const RandomCase a = random_case(77), b = random_case(77), other = random_case(78);
  auto first_path = [](const RandomCase& c) {
    std::vector<double> xyz;
    for (const Keyframe& k : c.scene.objects.front().keyframes) {
      for (int d = 0; d < 3; ++d) xyz.push_back(k.pose.position_m[d]);
    }
    return xyz;
  };
  EXPECT_EQ(a.scene.ground.grid.nx, b.scene.ground.grid.nx);
  EXPECT_EQ(a.scene.ground.grid.cell_size_m, b.scene.ground.grid.cell_size_m);
  EXPECT_TRUE(ground_model_section(a.scene).material(a.scene.ground.material) ==
              ground_model_section(b.scene).material(b.scene.ground.material));
  ASSERT_EQ(a.scene.objects.size(), b.scene.objects.size());
  for (std::size_t o = 0; o < a.scene.objects.size(); ++o) {
    EXPECT_TRUE(a.scene.objects[o].body.V == b.scene.objects[o].body.V);
  }
  EXPECT_EQ(first_path(a), first_path(b));
  EXPECT_NE(first_path(a), first_path(other));
}

}  // namespace
}  // namespace repose
