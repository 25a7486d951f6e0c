// The snow paper's Table 1 at equal error: the time to compute the snow
// probability of every map cell by shadow maps (the paper's projection
// method, CPU rasterisation) and by ray casting (Embree BVH), against the
// triangle count (1k to 1M) and the map size (128^2 to 1024^2), each method
// run with as many snowfall directions as it needs to reach the same error
// against a high-N reference.
//
// Scene: a 1 m x 1 m flat ground (a 16 x 16 height field, 450 triangles,
// sampled onto the n x n snow grid), a table top, and a sphere of r 0.15 m
// whose segments bring the total to the triangle count; snow tilted 20 deg
// with a 15 deg spread (experiments/snow_convergence.yaml).
//
// Equal error. Reference: P at up to kSamplesPerMap seeded random covered
// cells of each map by ray casting kReferenceDirections directions of another
// seed (exact visibility). Error: RMS of P - P_ref over those cells. Target:
// the ray casting's error with 64 directions (the N). Each method then
// runs with the smallest N on kLadder whose error is within the target (found
// before timing, from the first N of one seeded sequence, as the model draws
// them); the error of the timed output itself is reported (rms_error). The
// shadow maps add their pixel error (shadow edges, and the curved sphere's
// grazing self-shadow), so they are tried at 1, 2 and 4 pixels per cell
// (shadow_oversampling, with the bias kept in metres); each that reaches the
// target is timed and the fastest marked.
//
// Timed: the whole computation from the snow-free model (transforming the
// meshes and rendering / building the BVH included), single-threaded
// (Embree threads=1, CPU rasteriser). Process CPU time and wall time.
// Methods: 0 Embree ray casting; 1, 2, 3 shadow maps at 1x, 2x, 4x
// oversampling (4x only up to 256^2: it is slower than 2x wherever both
// reach the target); 4 rendering the 2x shadow maps only, at 512^2 (the
// method's floor, the "within 2x" target).
//
// Grid: the map-size sweep at 10k triangles and the triangle sweep at 512^2,
// plus the corners 128^2 and 1024^2 at 1k and 1M (10 of the 16 points).
// At exit the medians and the ray/shadow ratios are printed as one table.
// Run (about 8 CPU min; wall about twice that on a loaded machine):
//   bin/snow_table1_benchmark --benchmark_repetitions=3 --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <tuple>
#include <vector>

#include "models/snow/ray_cast_probability.h"
#include "models/snow/shadow_map.h"
#include "models/snow/snow_model.h"
#include "models/snow/snow_probability.h"

namespace repose {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
constexpr int kSamplesPerMap = 4096;
constexpr int kReferenceDirections = 1024;
constexpr int kTargetDirections = 64;
const std::vector<int> kLadder = {8, 12, 16, 24, 32, 48, 64, 96, 128, 192};
const SnowParams kParams{0.7, 15 * kDeg, 1.0};

struct CellSample {
  int map, i, j;
};

// Shadow-map oversampling (pixel = cell / o) of the timed configurations.
constexpr int kOversampling[3] = {1, 2, 4};

// The directions a method needs to reach the target; 0 when it does not
// within the ladder.
struct EqualError {
  int directions = 0;
  double ladder_error = 0.0;
};

// A scene of one grid point with its reference and the equal-error N.
struct Table1Point {
  HeightField ground;
  SnowModel model;
  long long triangles = 0;
  std::vector<CellSample> samples;
  std::vector<double> reference;  // P_ref per sample
  double target_error = 0.0;
  EqualError ray_cast;
  EqualError shadow_maps[3];  // per kOversampling
};

std::unique_ptr<Table1Point> make_point_scene(int n, int triangles) {
  auto p = std::make_unique<Table1Point>();
  p->ground = HeightField(Grid{16, 16, 1.0 / 16, -0.5, -0.5}, 0.0);
  const int segments = std::max(4, static_cast<int>(std::lround(std::sqrt(std::max(0.0, (triangles - 462.0) / 2.0)))));
  Pose table, ball;
  table.position_m = Eigen::Vector3d(-0.15, -0.1, 0.3);
  ball.position_m = Eigen::Vector3d(0.2, 0.15, 0.25);
  std::vector<SnowGroupGeometry> groups = {{"ground", &p->ground, {}},
                                           {"table", nullptr, {transformed(make_box({0.2, 0.15, 0.01}), table)}},
                                           {"ball", nullptr, {transformed(make_sphere(0.15, segments), ball)}}};
  SnowOptions o;
  o.groups = {{"ground", true, {}}, {"table", false, {"table"}}, {"ball", false, {"ball"}}};
  o.direction_count = kReferenceDirections;
  o.main_direction = {20 * kDeg, 0.5};
  p->model = build_snow_model(groups, Grid{n, n, 1.0 / n, -0.5, -0.5}, o, TimeSpec{}, 1);
  for (const TriangleMesh& m : p->model.occluders) p->triangles += m.F.rows();
  return p;
}

// Up to kSamplesPerMap covered cells of each map, drawn without bias.
std::vector<CellSample> sample_cells(const SnowModel& model, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<CellSample> out;
  for (std::size_t m = 0; m < model.maps.size(); ++m) {
    std::vector<CellSample> covered;
    for (int j = 0; j < model.grid.ny; ++j) {
      for (int i = 0; i < model.grid.nx; ++i) {
        if (model.maps[m].covered(i, j)) covered.push_back({static_cast<int>(m), i, j});
      }
    }
    std::shuffle(covered.begin(), covered.end(), rng);
    if (covered.size() > kSamplesPerMap) covered.resize(kSamplesPerMap);
    out.insert(out.end(), covered.begin(), covered.end());
  }
  return out;
}

// The model with only the sampled cells covered (the rays are cast from those only).
SnowModel masked(const SnowModel& model, const std::vector<CellSample>& samples) {
  SnowModel out = model;
  for (SnowMap& m : out.maps) m.base.covered.setZero();
  for (const CellSample& s : samples) out.maps[s.map].base.covered(s.j, s.i) = 1;
  return out;
}

double rms_error(const SnowProbability& p, const Table1Point& point) {
  double sum = 0.0;
  for (std::size_t k = 0; k < point.samples.size(); ++k) {
    const CellSample& s = point.samples[k];
    sum += std::pow(p.per_map[s.map](s.j, s.i) - point.reference[k], 2);
  }
  return std::sqrt(sum / std::max<std::size_t>(1, point.samples.size()));
}

std::vector<Eigen::Vector3d> first(const std::vector<Eigen::Vector3d>& dirs, int n) {
  return {dirs.begin(), dirs.begin() + n};
}

// Ray casting: the smallest ladder N within the target (rays from the samples only).
void find_ray_cast_n(const SnowModel& sampled, const std::vector<Eigen::Vector3d>& dirs, Table1Point* p) {
  p->target_error = rms_error(snow_probability_ray_cast(sampled, first(dirs, kTargetDirections)), *p);
  for (int n : kLadder) {
    const double e = n == kTargetDirections ? p->target_error : rms_error(snow_probability_ray_cast(sampled, first(dirs, n)), *p);
    if (e <= p->target_error) {
      p->ray_cast = {n, e};
      return;
    }
  }
}

// The model with shadow maps of pixel cell / o and the same bias in metres
// (the bias is in pixels), so the reference's bias still holds.
SnowModel with_oversampling(const SnowModel& model, int o) {
  SnowModel out = model;
  out.options.shadow_oversampling = o;
  out.options.shadow_bias_cells = model.options.shadow_bias_cells * o;
  return out;
}

// Shadow maps: one map per direction, the lit samples counted as N grows;
// the smallest ladder N within the target.
EqualError find_shadow_map_n(const std::vector<Eigen::Vector3d>& dirs, const Table1Point& p, int o) {
  const SnowModel model = with_oversampling(p.model, o);
  TopDownRenderer renderer(SnowRenderer::kCpu);
  std::vector<int> lit(p.samples.size(), 0);
  std::size_t rung = 0;
  for (int d = 0; d < kLadder.back(); ++d) {
    const ShadowMap shadow = render_shadow_map(model.occluders, model.maps, dirs[d], shadow_pixel_m(model),
                                               model.options.shadow_bias_cells, &renderer);
    for (std::size_t k = 0; k < p.samples.size(); ++k) {
      const CellSample& s = p.samples[k];
      const SnowMap& map = model.maps[s.map];
      if (shadow.is_lit({model.grid.centre_x(s.i), model.grid.centre_y(s.j), map.base_z(s.i, s.j)})) ++lit[k];
    }
    if (d + 1 != kLadder[rung]) continue;
    double sum = 0.0;
    for (std::size_t k = 0; k < lit.size(); ++k) sum += std::pow(lit[k] / (d + 1.0) - p.reference[k], 2);
    const double e = std::sqrt(sum / std::max<std::size_t>(1, lit.size()));
    if (e <= p.target_error) return {d + 1, e};
    ++rung;
  }
  return {};
}

// The point's scene, reference and equal-error N, made once for its three benchmarks.
Table1Point& point(int n, int triangles) {
  static std::map<std::pair<int, int>, std::unique_ptr<Table1Point>> cache;
  std::unique_ptr<Table1Point>& p = cache[{n, triangles}];
  if (p) return *p;
  p = make_point_scene(n, triangles);
  p->samples = sample_cells(p->model, 7);
  const SnowModel sampled = masked(p->model, p->samples);
  std::mt19937_64 rng(1234567);
  const SnowProbability ref = snow_probability_ray_cast(
      sampled, draw_snowfall_directions(p->model.options.main_direction, kParams.direction_spread_rad,
                                        kReferenceDirections, &rng));
  for (const CellSample& s : p->samples) p->reference.push_back(ref.per_map[s.map](s.j, s.i));
  const std::vector<Eigen::Vector3d> dirs = snowfall_directions(p->model, kParams);
  find_ray_cast_n(sampled, dirs, p.get());
  for (int k = 0; k < 3; ++k) {
    if (kOversampling[k] <= 2 || n <= 256) p->shadow_maps[k] = find_shadow_map_n(dirs, *p, kOversampling[k]);
  }
  return *p;
}

// Args {n, triangles, method}: method 0 is ray casting, 1..3 shadow maps
// with oversampling kOversampling[method - 1], each at its equal-error N;
// 4 renders the shadow maps of method 2 only (the method's floor).
void BM_Table1(benchmark::State& state) {
  const int method = static_cast<int>(state.range(2));
  const Table1Point& p = point(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)));
  const int config = method == 4 ? 1 : method - 1;
  const EqualError& eq = method == 0 ? p.ray_cast : p.shadow_maps[config];
  if (eq.directions == 0) {
    state.SkipWithError("does not reach the target error within the ladder");
    for (auto _ : state) {
    }
    return;
  }
  const SnowModel model = method == 0 ? p.model : with_oversampling(p.model, kOversampling[config]);
  const std::vector<Eigen::Vector3d> dirs = first(snowfall_directions(model, kParams), eq.directions);
  TopDownRenderer renderer(SnowRenderer::kCpu);
  SnowProbability out;
  for (auto _ : state) {
    if (method == 0) out = snow_probability_ray_cast(model, dirs);
    if (method == 1 || method == 2 || method == 3) out = snow_probability_shadow_maps(model, dirs, &renderer);
    if (method != 4) continue;
    for (const Eigen::Vector3d& d : dirs) {
      benchmark::DoNotOptimize(render_shadow_map(model.occluders, model.maps, d, shadow_pixel_m(model),
                                                 model.options.shadow_bias_cells, &renderer));
    }
  }
  state.counters["triangles"] = static_cast<double>(p.triangles);
  state.counters["directions"] = eq.directions;
  state.counters["target_error"] = p.target_error;
  state.counters["rms_error"] = method == 4 ? 0.0 : rms_error(out, p);
}

void Grid16(benchmark::internal::Benchmark* b) {
  std::vector<std::pair<int, int>> points;
  for (int n : {128, 256, 512, 1024}) points.push_back({n, 10000});
  for (int t : {1000, 100000, 1000000}) points.push_back({512, t});
  for (int n : {128, 1024}) {
    for (int t : {1000, 1000000}) points.push_back({n, t});
  }
  for (const auto& [n, t] : points) {
    for (int method : {0, 1, 2}) b->Args({n, t, method});
    if (n <= 256) b->Args({n, t, 3});  // 4x oversampling: slower than 2x wherever both reach the target
    if (n == 512) b->Args({n, t, 4});
  }
}

BENCHMARK(BM_Table1)->Apply(Grid16)->Iterations(1)->MeasureProcessCPUTime()->Unit(benchmark::kMillisecond);

// Prints the console report, then the medians of each point side by side:
// per point the ray casting and each shadow-map oversampling that reaches the
// target ('*' the fastest by CPU time), with ray / shadow-map time ratios.
class Table1Reporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    ConsoleReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      int n = 0, triangles = 0, method = 0;  // args: "n/triangles/method"
      if (std::sscanf(r.run_name.args.c_str(), "%d/%d/%d", &n, &triangles, &method) != 3 || method > 4) continue;
      Cell& c = rows_[{n, triangles}][method];
      if (r.error_occurred) c.missed = true;
      if (r.error_occurred || (r.run_type == Run::RT_Aggregate && r.aggregate_name != "median")) continue;
      if (r.run_type == Run::RT_Iteration && r.repetitions > 1) continue;
      c = {true, false, r.GetAdjustedCPUTime(), r.GetAdjustedRealTime(), r.counters};
    }
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    std::printf("\nTable 1 at equal error: medians in ms; x = ray casting / shadow maps\n");
    std::printf("%-5s %9s %7s | %4s %7s %9s %9s | %2s %4s %7s %9s %9s %9s | %6s %6s %6s\n", "n", "triangles",
                "target", "N_rc", "err_rc", "cpu_rc", "wall_rc", "o", "N_sm", "err_sm", "cpu_sm", "wall_sm",
                "floor_cpu", "cpu_x", "wall_x", "/floor");
    for (auto& [key, row] : rows_) print_point(key.first, row);
  }

 private:
  struct Cell {
    bool seen = false, missed = false;
    double cpu_ms = 0.0, wall_ms = 0.0;
    benchmark::UserCounters counters;
  };
  using Row = std::array<Cell, 5>;

  static void print_point(int n, Row& row) {
    Cell& rc = row[0];
    if (!rc.seen) return;
    int best = 0;
    for (int m = 1; m < 4; ++m) {
      if (row[m].seen && (best == 0 || row[m].cpu_ms < row[best].cpu_ms)) best = m;
    }
    for (int m = 1; m < 4; ++m) {
      Cell& sm = row[m];
      if (!sm.seen && !sm.missed) continue;
      if (!sm.seen) {
        std::printf("%-5d %9.0f %7.4f | %4.0f %7.4f %9.1f %9.1f | %2d   not within the target by N = %d\n", n,
                    double(rc.counters["triangles"]), double(rc.counters["target_error"]),
                    double(rc.counters["directions"]), double(rc.counters["rms_error"]), rc.cpu_ms, rc.wall_ms,
                    kOversampling[m - 1], kLadder.back());
        continue;
      }
      std::printf("%-5d %9.0f %7.4f | %4.0f %7.4f %9.1f %9.1f | %2d %4.0f %7.4f %9.1f %9.1f %9.1f | %6.2f %6.2f %6.2f%s\n",
                  n, double(rc.counters["triangles"]), double(rc.counters["target_error"]),
                  double(rc.counters["directions"]), double(rc.counters["rms_error"]), rc.cpu_ms, rc.wall_ms,
                  kOversampling[m - 1], double(sm.counters["directions"]), double(sm.counters["rms_error"]), sm.cpu_ms,
                  sm.wall_ms, m == 2 && row[4].seen ? row[4].cpu_ms : NAN, rc.cpu_ms / sm.cpu_ms, rc.wall_ms / sm.wall_ms,
                  m == 2 && row[4].seen ? sm.cpu_ms / row[4].cpu_ms : NAN, m == best ? " *" : "");
    }
  }
  std::map<std::pair<int, int>, Row> rows_;
};

}  // namespace
}  // namespace repose

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  repose::Table1Reporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
