#include "models/core/solver/initial_solver.h"

#include "models/core/base/cpu_time.h"
#include "models/core/config/initial_height.h"
#include "models/core/config/scene.h"

namespace repose {

namespace {

class CompiledInitial final : public CompiledSolver {
 public:
  explicit CompiledInitial(const Scene& scene) : scene_(scene) {}
  const std::vector<ParameterInfo>& parameters() const override { return parameters_; }
  Run run(const std::vector<double>& values_si, const RunOptions&) const override {
    check_values(parameters_, values_si, "initial");
    const Stopwatch clock;
    Run run;
    run.solver = "initial";
    const HeightField initial = make_initial_height(scene_);
    run.fields["height_initial"] = initial;
    run.fields["height_final"] = initial;
    run.wall_s = clock.wall_s();
    run.cpu_s = clock.cpu_s();
    return run;
  }

 private:
  Scene scene_;
  std::vector<ParameterInfo> parameters_;
};

}  // namespace

std::unique_ptr<CompiledSolver> InitialSolver::compile(const Scene& scene) const {
  return std::make_unique<CompiledInitial>(scene);
}

}  // namespace repose
