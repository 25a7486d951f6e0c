// The snow paper's Table 1, measured: the snow probability of every map cell
// from shadow maps (CPU and OSMesa) against ray casting (Embree) with the
// same directions, on a 1 m x 1 m scene: a flat ground of n x n cells, a
// table top, and a sphere of s segments (about s^2 triangles) above it.
// Arguments: {n, s}. 16 directions, 10 deg spread around a 20 deg tilt.
//
// Wall time (llvmpipe rasterises on its own threads). Equal N, not equal
// error: at equal N the shadow maps add their pixel error to the sampling
// error both share, so they need more directions or pixels for the same
// error; snow_table1_benchmark.cpp measures both at equal error against a
// high-N reference, over triangle count and map size.
// Run: bin/snow_benchmark --benchmark_repetitions=3 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <numbers>
#include <vector>

#include "models/snow/ray_cast_probability.h"
#include "models/snow/shadow_map.h"
#include "models/snow/snow_model.h"
#include "models/snow/snow_probability.h"

namespace repose {
namespace {

constexpr int kDirections = 16;

struct BenchScene {
  HeightField ground;
  SnowModel model;
  std::vector<Eigen::Vector3d> directions;
  long long triangles = 0;
};

BenchScene make_scene(int n, int segments, SnowRenderer renderer) {
  BenchScene s;
  s.ground = HeightField(Grid{n, n, 1.0 / n, -0.5, -0.5}, 0.0);
  Pose table, ball;
  table.position_m = Eigen::Vector3d(-0.15, -0.1, 0.3);
  ball.position_m = Eigen::Vector3d(0.2, 0.15, 0.25);
  std::vector<SnowGroupGeometry> groups = {{"ground", &s.ground, {}},
                                           {"table", nullptr, {transformed(make_box({0.2, 0.15, 0.01}), table)}},
                                           {"ball", nullptr, {transformed(make_sphere(0.15, segments), ball)}}};
  SnowOptions o;
  o.groups = {{"ground", true, {}}, {"table", false, {"table"}}, {"ball", false, {"ball"}}};
  o.direction_count = kDirections;
  o.main_direction = {20 * std::numbers::pi / 180, 0.5};
  o.renderer = renderer;
  s.model = build_snow_model(groups, s.ground.grid(), o, TimeSpec{}, 1);
  s.directions = snowfall_directions(s.model, SnowParams{0.7, 10 * std::numbers::pi / 180});
  for (const TriangleMesh& m : s.model.occluders) s.triangles += m.F.rows();
  return s;
}

void report(benchmark::State& state, const BenchScene& s) {
  state.counters["triangles"] = static_cast<double>(s.triangles);
  state.counters["directions"] = kDirections;
  state.counters["cells"] = static_cast<double>(s.model.grid.cell_count());
}

void BM_SnowProbabilityShadowMapsCpu(benchmark::State& state) {
  const BenchScene s = make_scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), SnowRenderer::kCpu);
  TopDownRenderer renderer(SnowRenderer::kCpu);
  for (auto _ : state) benchmark::DoNotOptimize(snow_probability_shadow_maps(s.model, s.directions, &renderer));
  report(state, s);
}

void BM_SnowProbabilityShadowMapsOsmesa(benchmark::State& state) {
  const BenchScene s = make_scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), SnowRenderer::kCpu);
  TopDownRenderer renderer(SnowRenderer::kOsmesa);
  for (auto _ : state) benchmark::DoNotOptimize(snow_probability_shadow_maps(s.model, s.directions, &renderer));
  report(state, s);
}

void BM_SnowProbabilityRayCastEmbree(benchmark::State& state) {
  const BenchScene s = make_scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), SnowRenderer::kCpu);
  for (auto _ : state) benchmark::DoNotOptimize(snow_probability_ray_cast(s.model, s.directions));
  report(state, s);
}

// The method's own floor: rendering the shadow maps alone, without the
// per-cell comparisons (the target: the probability within 2x of it).
void BM_ShadowMapRenderOnlyCpu(benchmark::State& state) {
  const BenchScene s = make_scene(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)), SnowRenderer::kCpu);
  TopDownRenderer renderer(SnowRenderer::kCpu);
  for (auto _ : state) {
    for (const Eigen::Vector3d& d : s.directions) {
      benchmark::DoNotOptimize(render_shadow_map(s.model.occluders, s.model.maps, d, shadow_pixel_m(s.model),
                                                 s.model.options.shadow_bias_cells, &renderer));
    }
  }
  report(state, s);
}

void Sizes(benchmark::internal::Benchmark* b) {
  for (int n : {128, 256, 512}) b->Args({n, 32});
  for (int segments : {128, 512}) b->Args({256, segments});
}

BENCHMARK(BM_SnowProbabilityShadowMapsCpu)->Apply(Sizes)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SnowProbabilityShadowMapsOsmesa)->Apply(Sizes)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_ShadowMapRenderOnlyCpu)->Apply(Sizes)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SnowProbabilityRayCastEmbree)->Apply(Sizes)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace repose

BENCHMARK_MAIN();
