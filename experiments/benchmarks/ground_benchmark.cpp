// Speed of the ground model (issue 3): step time against grid size at a
// fixed contact, against contact size, CPU against OSMesa collision, local
// against whole-grid erosion, sweep against substeps (the paper's Table 1),
// and multi-resolution levels. Run:
//   build/bin/ground_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// The step cases drag a sphere across a flat sand ground (cell 1 cm, 5 cm
// deep) at a steady depth, so every step collides, displaces and erodes; when
// the sphere reaches the far side the state is rebuilt outside the timing.
// BM_RunIndentDeep times a whole run of the calibration ladder's press scene.

#include <benchmark/benchmark.h>

#include <memory>

#include "models/core/config/scene.h"
#include "models/ground/erosion.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"
#include "models/ground/ground_step.h"
#include "models/ground/simulate_ground.h"

namespace repose {
namespace {

constexpr double kCell = 0.01;
constexpr double kGround = 0.05;

struct DragCase {
  int grid_cells = 256;
  double radius_m = 0.08;          // contact ~11 cells across at 2 cm deep: a footprint
  double depth_m = 0.02;
  double cells_per_step = 1.0;
  bool sweep = true;
  int substeps = 1;
  bool simple = false;
  int coarse_factor = 2;
  GroundModelSpec::Collision collision = GroundModelSpec::Collision::kCpu;
};

class DragRun {
 public:
  explicit DragRun(const DragCase& c) {
    Scene scene;
    scene.ground.grid = Grid{c.grid_cells, c.grid_cells, kCell, -0.5 * c.grid_cells * kCell, -0.5 * c.grid_cells * kCell};
    scene.ground.material = "sand";
    ObjectSpec ball;
    ball.name = "ball";
    ball.radius_m = c.radius_m;
    ball.body = make_sphere(c.radius_m, 32);
    ball.simple = c.simple;
    // across the middle 80 % of the grid (at most 2 m), at a steady depth
    const double span = std::min(0.8 * c.grid_cells * kCell, 2.0);
    steps_ = static_cast<int>(span / (c.cells_per_step * kCell));
    const double z = kGround + c.radius_m - c.depth_m;
    Keyframe a, b;
    a.pose.position_m = Eigen::Vector3d(-0.5 * span, 0, z);
    b.time_s = steps_;
    b.pose.position_m = Eigen::Vector3d(0.5 * span, 0, z);
    ball.keyframes = {a, b};
    scene.objects = {ball};
    scene.time.step_s = 1.0;
    scene.time.duration_s = steps_;
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.sweep = c.sweep; });
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.substeps = c.substeps; });
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.coarse_factor = c.coarse_factor; });
    scene = with_ground_options_changed(std::move(scene), [&](GroundModelSpec& o) { o.collision = c.collision; });
    model_ = build_ground_model(scene);
    params_ = default_params(model_);
    renderer_ = c.collision == GroundModelSpec::Collision::kCpu ? make_cpu_underside_renderer()
                                                                 : make_osmesa_underside_renderer();
    reset();
  }
  void reset() {
    state_ = make_ground_state(model_, HeightField(model_.grid, kGround));
    step(model_, params_, *renderer_, &state_);  // the first press
  }
  void run(benchmark::State& bench) {
    for (auto _ : bench) {
      if (state_.step_index >= steps_) {
        bench.PauseTiming();
        reset();
        bench.ResumeTiming();
      }
      const StepReport r = step(model_, params_, *renderer_, &state_);
      benchmark::DoNotOptimize(r.contact_cells);
    }
  }

 private:
  GroundModel model_;
  GroundParams params_;
  std::unique_ptr<UndersideRenderer> renderer_;
  GroundState state_;
  int steps_ = 0;
};

void BM_StepVsGridSize(benchmark::State& bench) {
  DragCase c;
  c.grid_cells = static_cast<int>(bench.range(0));
  DragRun(c).run(bench);
}
BENCHMARK(BM_StepVsGridSize)->RangeMultiplier(2)->Range(128, 2048)->Unit(benchmark::kMicrosecond);

void BM_StepVsContactSize(benchmark::State& bench) {
  DragCase c;
  c.grid_cells = 1024;
  c.radius_m = bench.range(0) * 1e-3;
  c.depth_m = 0.25 * c.radius_m;
  DragRun(c).run(bench);
}
BENCHMARK(BM_StepVsContactSize)->Arg(20)->Arg(40)->Arg(80)->Arg(160)->Arg(320)->Unit(benchmark::kMicrosecond);

void BM_StepCollisionBackend(benchmark::State& bench) {
  DragCase c;
  c.grid_cells = 1024;
  c.collision = bench.range(0) ? GroundModelSpec::Collision::kOsmesa : GroundModelSpec::Collision::kCpu;
  bench.SetLabel(bench.range(0) ? "osmesa" : "cpu");
  DragRun(c).run(bench);
}
BENCHMARK(BM_StepCollisionBackend)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// The paper's Table 1: a sphere dragged 10 cells per frame on a 256^2 field.
void BM_Table1(benchmark::State& bench) {
  DragCase c;
  c.radius_m = 0.1;
  c.depth_m = 0.03;
  c.cells_per_step = 10;
  const int mode = static_cast<int>(bench.range(0));
  c.sweep = mode == 2;
  c.substeps = mode == 1 ? 10 : 1;
  bench.SetLabel(mode == 0 ? "no sweep" : mode == 1 ? "10 substeps" : "sweep");
  DragRun(c).run(bench);
}
BENCHMARK(BM_Table1)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kMicrosecond);

void BM_StepMultiResolution(benchmark::State& bench) {
  DragCase c;
  c.grid_cells = 512;
  c.radius_m = 0.16;
  c.depth_m = 0.04;
  c.simple = bench.range(0) > 1;
  c.coarse_factor = static_cast<int>(bench.range(0));
  bench.SetLabel(c.simple ? "coarse" : "full");
  DragRun(c).run(bench);
}
BENCHMARK(BM_StepMultiResolution)->Arg(1)->Arg(2)->Arg(4)->Unit(benchmark::kMicrosecond);

// Erosion alone after a press: over the remembered cells, or over every cell.
void BM_ErosionLocalVsWholeGrid(benchmark::State& bench) {
  const bool whole = bench.range(0) != 0;
  bench.SetLabel(whole ? "whole grid" : "local");
  Material sand;
  material_preset("sand", &sand);
  const GroundModel model = make_plain_ground_model(Grid{512, 512, kCell, 0, 0}, sand);
  const GroundParams params{{sand}};
  GroundState state = make_ground_state(model, HeightField(model.grid, kGround));
  for (int j = 250; j < 262; ++j) {
    for (int i = 250; i < 262; ++i) {
      state.height.at(i, j) += 0.05;
      state.erosion.touch(model.cell(i, j));
    }
  }
  if (whole) {
    for (std::int64_t c = 0; c < static_cast<std::int64_t>(model.grid.cell_count()); ++c) state.erosion.touch(c);
  }
  const GroundState start = state;
  for (auto _ : bench) {
    bench.PauseTiming();
    state = start;
    bench.ResumeTiming();
    const ErosionResult r = erode(model, params, Ceiling{}, &state);
    benchmark::DoNotOptimize(r.moves);
  }
}
BENCHMARK(BM_ErosionLocalVsWholeGrid)->Arg(0)->Arg(1)->Unit(benchmark::kMicrosecond);

// A whole run of the calibration ladder's timed scene (issue 10;
// experiments/scenes/ref_indent_deep.yaml): a sphere of 3 cm pressed
// vertically 10 mm into flat sand on 5 mm cells and lifted out again, 40
// steps, as the ladder times it (simulate_ground, renderer and state included).
void BM_RunIndentDeep(benchmark::State& bench) {
  Scene scene;
  scene.ground.grid = Grid{27, 27, 0.005, 0.0, 0.0};
  scene.ground.material = "sand";
  ObjectSpec ball;
  ball.name = "ball";
  ball.radius_m = 0.03;
  ball.body = make_sphere(ball.radius_m, 32);
  Keyframe a, b, c;
  a.pose.position_m = Eigen::Vector3d(0.0675, 0.0675, 0.060);
  b.time_s = 0.2;
  b.pose.position_m = Eigen::Vector3d(0.0675, 0.0675, 0.045);
  c.time_s = 0.4;
  c.pose.position_m = a.pose.position_m;
  ball.keyframes = {a, b, c};
  scene.objects = {ball};
  scene.time.step_s = 0.01;
  scene.time.duration_s = 0.4;
  const GroundModel model = build_ground_model(scene);
  const GroundParams params = default_params(model);
  const HeightField initial(model.grid, 0.025);
  for (auto _ : bench) {
    const GroundRun run = simulate_ground(model, params, initial);
    benchmark::DoNotOptimize(run.final_volume_m3);
  }
}
BENCHMARK(BM_RunIndentDeep)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace repose

BENCHMARK_MAIN();
