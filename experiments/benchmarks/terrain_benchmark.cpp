// Key contours to terrain (issue 14's target: 10 key contours to a
// 100k-triangle mesh in under 2 s): a 1 km hill foot holding three hills,
// each holding two peaks, generated at several sample spacings; the counter
// "triangles" says which rung reaches 100k.
// Run: bin/terrain_benchmark --benchmark_repetitions=3 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "models/terrain/terrain.h"

namespace repose {
namespace {

Polygon2 star(const Point2& centre, double r_min_m, double r_max_m, int sides, std::mt19937_64* rng) {
  std::uniform_real_distribution<double> r(r_min_m, r_max_m);
  Polygon2 p;
  for (int k = 0; k < sides; ++k) {
    const double a = 2.0 * std::numbers::pi * k / sides;
    const double rk = r(*rng);
    p.emplace_back(centre.x() + rk * std::cos(a), centre.y() + rk * std::sin(a));
  }
  return p;
}

// ten nested key contours: a foot, three hills, two peaks on each hill
std::vector<KeyContour> ten_key_contours() {
  std::mt19937_64 rng(2024);
  std::vector<KeyContour> keys = {{"foot", star(Point2(0, 0), 350.0, 500.0, 40, &rng), 100.0}};
  for (int h = 0; h < 3; ++h) {
    const double a = 2.0 * std::numbers::pi * h / 3;
    const Point2 centre(200.0 * std::cos(a), 200.0 * std::sin(a));
    keys.push_back({"hill", star(centre, 40.0, 80.0, 12, &rng), 180.0 + 20.0 * h});
    const Point2 tangent(-std::sin(a), std::cos(a));
    for (int side : {-1, 1}) {
      keys.push_back({"peak", star(centre + 25.0 * side * tangent, 8.0, 10.0, 16, &rng), 230.0 + 20.0 * h + 10.0 * side});
    }
  }
  return keys;
}

void BM_TerrainFromKeyContours(benchmark::State& state) {
  TerrainOptions options;
  options.contour_interval_m = 5.0;
  options.slope_rad = 30.0 * std::numbers::pi / 180.0;
  options.sample_spacing_m = static_cast<double>(state.range(0)) / 10.0;
  options.smoothing_tolerance_m = 2.0;
  options.cell_size_m = 2.0;
  const std::vector<KeyContour> keys = ten_key_contours();
  int triangles = 0;
  for (auto _ : state) {
    const Terrain terrain = build_terrain(keys, options);
    triangles = terrain.summary.triangle_count;
    benchmark::DoNotOptimize(terrain.mesh.V.data());
  }
  state.counters["triangles"] = triangles;
  state.counters["sample_spacing_m"] = options.sample_spacing_m;
}
BENCHMARK(BM_TerrainFromKeyContours)->Arg(80)->Arg(40)->Arg(20)->Arg(12)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace repose

BENCHMARK_MAIN();
