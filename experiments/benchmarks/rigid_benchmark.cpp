// Speed of the rigid-body references (issue 11, item 5): grain-steps per
// CPU second of Bullet (double) and ODE (double) stepping the same settled
// beds of r = 2 mm +-10 % grains, 2 cm deep, 1k to 10k grains, at their
// default options (step 1/600 s, rolling friction on; Bullet 10 solver
// iterations, ODE 20). Each bed is settled once (cached under the reference
// cache, as a run would) outside the timing; the timing is of plain steps
// of the settled bed, no object. Run:
//   build/bin/rigid_benchmark --benchmark_counters_tabular=true
// items_per_second is grain-steps per CPU second (Google Benchmark's default
// clock is the CPU time of the thread).

#include <benchmark/benchmark.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "validation/bullet/bullet_engine.h"
#include "validation/liggghts/liggghts_bed.h"
#include "validation/liggghts/liggghts_script.h"
#include "validation/ode/ode_engine.h"
#include "validation/rigid/rigid_bed_cache.h"
#include "validation/rigid/rigid_setup.h"

namespace repose {
namespace {

// A square bed holding about `grains` grains.
RigidInputs bed_of(long grains) {
  RigidInputs in;
  in.dem.bed_depth_m = 0.02;
  const double cell = 0.004;
  const double area = static_cast<double>(grains) * mean_grain_volume_m3(in.dem) / (in.dem.bed_depth_m * 0.6);
  const int n = static_cast<int>(std::lround(std::sqrt(area) / cell));
  in.grid = Grid{n, n, cell, 0.0, 0.0};
  in.seed = 1;
  return in;
}

RigidEngine engine_named(int which) { return which == 0 ? bullet_engine({}) : ode_engine({}); }

void BM_SettledBedStep(benchmark::State& state) {
  const RigidEngine engine = engine_named(static_cast<int>(state.range(0)));
  const RigidInputs in = bed_of(state.range(1));
  const RigidBed bed = settled_rigid_bed(engine, in, default_cache_dir());
  const auto world = engine.make_world(run_world(in, bed.grains));
  for (auto _ : state) world->step();
  state.SetItemsProcessed(state.iterations() * bed.grains.size());
  state.SetLabel(engine.version);
  state.counters["grains"] = static_cast<double>(bed.grains.size());
  state.counters["cpu_s_per_simulated_s"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * engine.rigid.time_step_s, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

BENCHMARK(BM_SettledBedStep)
    ->ArgNames({"engine", "grains"})
    ->ArgsProduct({{0, 1}, {1000, 2500, 5000, 10000}})
    ->Unit(benchmark::kMillisecond)
    ->MinTime(2.0);

}  // namespace
}  // namespace repose

BENCHMARK_MAIN();
