// Depth images of a sphere (~2k triangles) over n x n grids: OpenGL through
// OSMesa (llvmpipe) against the CPU ray reference. The sphere spans 80 % of
// the grid, seen from below (the ground model's collision test).
//
// Wall time (llvmpipe rasterises on its own threads, so CPU time of the
// calling thread undercounts it).
// Run: bin/depth_image_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <vector>

#include "models/core/geometry/depth_image.h"
#include "models/core/gl/osmesa_depth_renderer.h"
#include "models/core/geometry/triangle_mesh.h"

namespace repose {
namespace {

// A 1 m x 1 m grid of n x n cells and a sphere of radius 0.4 m in its middle.
Grid unit_grid(int n) { return Grid{n, n, 1.0 / n, -0.5, -0.5}; }

std::vector<TriangleMesh> sphere_scene() {
  Pose pose;
  pose.position_m = Eigen::Vector3d(0.0, 0.0, 0.1);
  return {transformed(make_sphere(0.4, 32), pose)};  // 32 segments: 1,984 triangles
}

void BM_DepthImageOsmesa(benchmark::State& state) {
  const Grid grid = unit_grid(static_cast<int>(state.range(0)));
  const std::vector<TriangleMesh> meshes = sphere_scene();
  OsmesaDepthRenderer renderer;
  for (auto _ : state) {
    DepthImage img = renderer.render(meshes, grid, ViewFrom::kBelow, DepthRange{-1.0, 1.0});
    benchmark::DoNotOptimize(img.z_m.data());
  }
  state.counters["triangles"] = static_cast<double>(meshes[0].F.rows());
  state.counters["cells/s"] = benchmark::Counter(static_cast<double>(grid.cell_count()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_DepthImageCpu(benchmark::State& state) {
  const Grid grid = unit_grid(static_cast<int>(state.range(0)));
  const std::vector<TriangleMesh> meshes = sphere_scene();
  for (auto _ : state) {
    DepthImage img = depth_image_cpu(meshes, grid, ViewFrom::kBelow);
    benchmark::DoNotOptimize(img.z_m.data());
  }
  state.counters["triangles"] = static_cast<double>(meshes[0].F.rows());
  state.counters["cells/s"] = benchmark::Counter(static_cast<double>(grid.cell_count()), benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(BM_DepthImageOsmesa)->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DepthImageCpu)->Arg(64)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace repose

BENCHMARK_MAIN();
