// Speed of the height-span model (issue 12): one step of a scoop on a
// 512 x 512 ground (5 mm cells, a 5 cm bed) with the scoop scenes' bucket
// scaled to 64 x 64 cells (32 cm across, 20 cm high). Target: at most 2 ms
// median per step on one core. Cases:
//   Scoop: tilted 80 deg (mouth forward), its lowest edge 4 cm deep, dragged
//          one cell per step: collision, take-up, displacement, ground and
//          span erosion every step, the load growing;
//   Carry: the same bucket, loaded by a scoop, lifted and carried level one
//          cell per step (span erosion on a settled load, no contact);
//   Tip:   the loaded bucket turning 5 deg per step past the angle of repose
//          (peeled again every step, material re-sampled, particles);
//   ScoopGroundPath: the Scoop case with the bucket marked holds_material:
//          false, so that only the ground model's collision, displacement
//          and erosion run: the cost the height-span model adds is the
//          difference;
//   Scoop20Passes: the Scoop case with 20 erosion passes per step (En = 20)
//          instead of the default material's 5, as the fitted scoop scenes
//          run (experiments/scenes/ref_scoop*.yaml);
//   ScoopPath: the Scoop case's 199 steps once, for instruction counts:
//          valgrind --tool=callgrind --toggle-collect='repose::step(repose::HeightSpanModel*'
//          build/bin/heightspan_benchmark --benchmark_filter=BM_ScoopPath
//   TipOsmesa: the Tip case with the span maps peeled by OSMesa
//          (heightspan.span_maps: osmesa) instead of the CPU;
//   ScoopOnePass, ScoopOnePassPath: the Scoop and ScoopPath cases with the
//          heap beside the bucket laid in one pass (ground_model.heap_laying:
//          one_pass) instead of the default portions.
// Run:
//   build/bin/heightspan_benchmark --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
// The state is rebuilt outside the timing when a case runs out of path.
//
// Measured (session 18, 2026-11-27, 2 cores shared, load 6-8): BM_ScoopStep
// CPU median a step, main e3ee8bd's binary and commit dde4e67's in turn, two
// sets of 5 rounds of 5 repetitions: 1.89 -> 1.85 ms and 1.79 -> 1.73 ms
// (per-round ratios 0.92-1.04); wall medians 2.7-3.8 ms (the load). Under
// the 2 ms target in CPU time on this machine before and after; dde4e67's
// own gain is instructions, BM_ScoopPath 4,592.8 -> 4,482.4 M (-2.4 %).
// Against LIGGGHTS on the scoop scene itself (experiments/scenes/ref_scoop.yaml,
// the fitted values of heightspan_scoop_fitted.yaml, frames off with
// --set heightspan.frame_interval_s=10; same machine, same hour):
// LIGGGHTS seed 1 run_cpu_s 166.9 (bed settled apart, 12.7 s); the
// height-span run's run.cpu_s median of 5: 0.0175 s at 5 mm cells (9,540x;
// fastest 0.0163 s, 10,240x), 0.122 s at the scene's 2.5 mm (1,370x).
// Again on a quiet machine (16:07-16:22, load ~1; main at 18ad0f9):
// BM_ScoopStep CPU medians of 10 rounds (5 repetitions each), e3ee8bd's
// binary and 18ad0f9's in turn: 1.65 -> 1.64 ms (ratio median 0.984; wall
// = CPU): the 2 ms target is met, and was before. LIGGGHTS seed 1 run_cpu_s
// 118.9 (the load above inflated it 1.4x); the height-span run 0.0152 to
// 0.0231 s at 5 mm (10 runs, median 0.0192: 6,200x; fastest 7,800x) and
// median 0.109 s at 2.5 mm (5 runs: 1,090x). So 10^4x is not met.
// Session 19 (2026-11-27, branch scoop-speed-2 on main ab49db8): span and
// ground erosion and CPU peeling made cheaper with byte-identical outputs
// (13 heightspan scene runs, manifests' measures too). Instructions of the
// 5 mm run (valgrind --tool=callgrind --toggle-collect=
// 'repose::(anonymous namespace)::CompiledHeightSpan::run*' build/bin/repose
// run experiments/scenes/ref_scoop.yaml --solver heightspan $S, $S the
// fitted values, frames off, --set ground.cell_size_m=0.005): 201.0 ->
// 171.8 M (-14.5 %; erode_spans 94.7 -> 71.4 M, erode 55.6 -> 50.1 M,
// peel_spans 9.7 -> 9.0 M); at the scene's 2.5 mm 1,623.6 -> 1,368.6 M
// (-15.7 %); BM_ScoopPath 4,492.2 -> 4,154.1 M (-7.5 %). run.cpu_s of the
// 5 mm run, 10 runs of each binary in turn (18:33 UTC, load 1.3-1.4):
// medians 0.01581 -> 0.01399 s (-11.5 %): 7,520x -> 8,500x LIGGGHTS'
// 118.9 s. 10^4x (<= 0.0119 s) is still not met.
// The same window for both (18:35-18:41 UTC, load 1.0-1.6, main's binary
// before and after the branch, 15 rounds each in turn, LIGGGHTS seed 1
// twice between them: 5 rounds, LIGGGHTS, 5 rounds,
// LIGGGHTS, 5 rounds): the height-span run 5 mm median 0.01598 -> 0.01399 s,
// 2.5 mm 0.1137 -> 0.0985 s (per-round ratios 0.879 / 0.870). LIGGGHTS
// run_cpu_s 157.4 and 119.9 s: the first ran in a slow phase of the shared
// host (the model's rounds right after it took 1.2-1.5x their median), the
// second in a normal one. At 5 mm the model is 8,570x (normal phase) to
// 11,250x LIGGGHTS; at 2.5 mm 1,220-1,600x. 10^4x is at the line at 5 mm,
// not met robustly.
// Session 29 (2026-11-29): the ladder now scores each rung's held mass too
// (experiments/heightspan_scoop_fit.yaml, runs/paper/heightspan_scoop_fit/
// report.md). At the fitted values the 5 mm run carries about 20 % less
// than the seeds' mean (the 2.5 mm run, the fit's cells, within 6 % at every
// stage), so the 5 mm ratios above are not at an accuracy the issue accepts:
// the ratio that counts is the 2.5 mm one, about 1,300x.

#include <benchmark/benchmark.h>

#include <memory>
#include <string>

#include "models/core/config/scene.h"
#include "models/core/io/mesh_io.h"
#include "models/ground/collision.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_section.h"
#include "models/heightspan/heightspan_model.h"
#include "models/heightspan/heightspan_section.h"
#include "models/heightspan/heightspan_state.h"
#include "models/heightspan/heightspan_step.h"

namespace repose {
namespace {

constexpr double kCell = 0.005;
constexpr int kCells = 512;
constexpr double kBed = 0.05;
constexpr double kScale = 4.0;  // the 8 cm bucket to 32 cm: 64 cells

Keyframe key(double t, double x, double z, double pitch_deg) {
  Keyframe k;
  k.time_s = t;
  k.pose.position_m = Eigen::Vector3d(x, 0.5 * kCells * kCell, z);
  k.pose.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(pitch_deg * M_PI / 180.0, Eigen::Vector3d::UnitY()));
  return k;
}

enum class Case { kScoop, kCarry, kTip, kScoopGroundPath, kTipOsmesa, kScoop20Passes, kScoopOnePass };

class ScoopRun {
 public:
  explicit ScoopRun(Case c) {
    const bool holds = c != Case::kScoopGroundPath, osmesa = c == Case::kTipOsmesa;
    const int passes = c == Case::kScoop20Passes ? 20 : 0;  // 0: the default material's
    GroundModelSpec ground_options;
    if (c == Case::kScoopOnePass) ground_options.heap_laying = GroundModelSpec::HeapLaying::kOnePass;
    if (!holds || passes > 0 || c == Case::kScoopOnePass) c = Case::kScoop;
    if (osmesa) c = Case::kTip;
    Scene scene;
    scene.seed = 1;
    scene.ground.grid = Grid{kCells, kCells, kCell, 0.0, 0.0};
    scene.ground.initial.height_m = kBed;
    ObjectSpec bucket;
    bucket.name = "bucket";
    bucket.shape = ObjectSpec::Shape::kMesh;
    bucket.body = scaled(read_mesh(std::string(REPOSE_SOURCE_DIR) + "/experiments/meshes/bucket.obj"),
                         Eigen::Vector3d::Constant(kScale));
    // tilted 80 deg the lowest edge is 0.159 m below the centre
    const double dig_z = kBed - 0.04 + 0.159, high_z = kBed + 0.3;
    const double x0 = 0.4, t_scoop = 200, t_lift = t_scoop + 20, t_carry = t_lift + 200;
    bucket.keyframes = {key(0, x0, dig_z, 80), key(t_scoop, x0 + t_scoop * kCell, dig_z, 80),
                        key(t_lift, x0 + t_scoop * kCell, high_z, 0),
                        key(t_carry, x0 + (t_scoop + 200) * kCell, high_z, 0),
                        key(t_carry + 36, x0 + (t_scoop + 200) * kCell, high_z, 180)};
    scene.objects = {bucket};
    scene.time.step_s = 1.0;
    scene.time.duration_s = t_carry + 36;
    HeightSpanSection section;
    section.holds_material["bucket"] = holds;
    if (osmesa) section.options.span_maps = HeightSpanSpec::SpanMaps::kOsmesa;
    section.options.max_substep_angle_rad = 10 * M_PI / 180.0;  // one substep per tipping step
    scene = with_heightspan(with_ground_options(std::move(scene), ground_options), section);
    model_ = build_heightspan_model(scene);
    params_ = default_params(model_.ground);
    if (passes > 0) params_.materials.front().erosion_iterations = passes;
    renderer_ = make_cpu_underside_renderer();
    first_ = c == Case::kScoop ? 1 : c == Case::kCarry ? static_cast<int>(t_lift) : static_cast<int>(t_carry);
    last_ = c == Case::kScoop ? static_cast<int>(t_scoop) : c == Case::kCarry ? static_cast<int>(t_carry)
                                                                               : static_cast<int>(t_carry + 36);
    reset();
  }
  void reset() {
    if (!start_) {  // run up to the case's first step once, then start every pass from there
      HeightSpanState state = make_heightspan_state(model_, HeightField(model_.ground.grid, kBed));
      while (state.ground.step_index < first_) step(model_, params_, *renderer_, &state);
      start_ = std::make_unique<HeightSpanState>(std::move(state));
    }
    state_ = *start_;
  }
  void run(benchmark::State& bench) {
    double pair_visits = 0.0, steps = 0.0, passes = 0.0, remembered = 0.0, moves = 0.0;  // ground erosion's neighbour pairs examined per step
    for (auto _ : bench) {
      if (state_.ground.step_index >= last_) {
        bench.PauseTiming();
        reset();
        bench.ResumeTiming();
      }
      const HeightSpanStepReport r = step(model_, params_, *renderer_, &state_);
      pair_visits += static_cast<double>(r.ground_erosion.pair_visits);
      ++steps;
      passes += r.ground_erosion.passes;
      moves += static_cast<double>(r.ground_erosion.moves);
      remembered += static_cast<double>(state_.ground.erosion.cells().size());
    }
    bench.counters["held_m3"] = held_m3(state_);
    bench.counters["ground_pairs"] = steps > 0 ? pair_visits / steps : 0.0;
    bench.counters["ground_passes"] = steps > 0 ? passes / steps : 0.0;
    bench.counters["ground_moves"] = steps > 0 ? moves / steps : 0.0;
    bench.counters["remembered"] = steps > 0 ? remembered / steps : 0.0;
    if (!state_.held.empty()) bench.counters["spans"] = static_cast<double>(state_.held[0].map.spans.size());
  }

 private:
  HeightSpanModel model_;
  GroundParams params_;
  std::unique_ptr<UndersideRenderer> renderer_;
  std::unique_ptr<HeightSpanState> start_;
  HeightSpanState state_;
  int first_ = 0, last_ = 0;
};

template <Case kCase>
void BM_Step(benchmark::State& bench) {
  ScoopRun run(kCase);
  run.run(bench);
}

BENCHMARK(BM_Step<Case::kScoop>)->Name("BM_ScoopStep")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step<Case::kScoop20Passes>)->Name("BM_Scoop20PassesStep")->Unit(benchmark::kMillisecond);
// The whole scoop path once (199 steps, the same ones every run): a fixed
// workload for instruction counts (valgrind --tool=callgrind), which a
// shared machine's load does not change.
BENCHMARK(BM_Step<Case::kScoop>)->Name("BM_ScoopPath")->Iterations(199)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step<Case::kScoopOnePass>)->Name("BM_ScoopOnePassStep")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step<Case::kScoopOnePass>)->Name("BM_ScoopOnePassPath")->Iterations(199)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step<Case::kScoopGroundPath>)->Name("BM_ScoopGroundPathStep")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step<Case::kCarry>)->Name("BM_CarryStep")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step<Case::kTip>)->Name("BM_TipStep")->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Step<Case::kTipOsmesa>)->Name("BM_TipOsmesaStep")->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace repose

BENCHMARK_MAIN();
