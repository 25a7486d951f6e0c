// The experiment runner: experiment files (strict, with scene overrides and
// sweeps), and the folder run_experiment writes (runs, summary, manifest,
// figures), atomically. Also `repose experiment` as a subprocess.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "experiments/solvers/solver_registry.h"
#include "models/ground/ground_section.h"
#include "models/ground/ground_solver.h"
#include "experiments/runner/experiment.h"
#include "experiments/runner/run_experiment.h"
#include "experiments/runner/scene_override.h"
#include "models/core/base/error.h"
#include "models/core/io/npy_io.h"
#include "models/core/base/sha256.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

using test_support::read_all;
using test_support::TempDir;

void write(const fs::path& path, const std::string& text) {
  fs::create_directories(path.parent_path());
  std::ofstream(path, std::ios::binary) << text;
}

// A small ground scene: a sphere pressed 2 cm into sand on a 24 x 24 grid.
const char* const kScene = R"(name: press
seed: 3
time: {step_s: 0.02, duration_s: 0.1}
ground:
  extent_m: [0.24, 0.24]
  cell_size_m: 0.01
  initial_height: {kind: flat, height_m: 0.05}
  material: sand
objects:
  - name: ball
    shape: sphere
    radius_m: 0.04
    motion:
      - {time_s: 0, position_m: [0, 0, 0.1]}
      - {time_s: 0.1, position_m: [0, 0, 0.07]}
ground_model: {sweep: true, substeps: 1}
)";

// A folder with scenes/press.yaml and the experiment file `name` holding `text`.
struct ExperimentDir {
  TempDir dir;
  fs::path experiment;
  ExperimentDir(const std::string& text, const std::string& name = "exp.yaml") {
    write(dir.path / "scenes" / "press.yaml", kScene);
    experiment = dir.path / name;
    write(experiment, text);
  }
};

Experiment load(const fs::path& path) { return load_experiment(path.string(), solver_registry()); }

// The InputError message of loading, or "" when it loads.
std::string load_error(const fs::path& path) {
  try {
    load(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

ExperimentOptions quiet_options(const fs::path& out) {
  ExperimentOptions options;
  options.out_dir = out.string();
  options.command_line = {"experiment_runner_test"};
  options.log = nullptr;
  options.solver_progress = false;
  return options;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// ---- scene overrides



// ---- experiment files

TEST(ExperimentFile, RunsAndSweepsExpandWithTheirOverridesApplied) {
  ExperimentDir setup(R"(name: small
runs:
  - {name: plain, scene: scenes/press.yaml}
  - name: no_sweep
    scene: scenes/press.yaml
    solver: initial
    overrides: {ground_model.sweep: false, ground.material: mud}
sweeps:
  - name: sub
    scene: scenes/press.yaml
    overrides: {ground_model.sweep: false}
    sweep: {key: ground_model.substeps, values: [2, 5]}
measures: [steps]
)");
  const Experiment e = load(setup.experiment);
  EXPECT_EQ(e.name, "small");
  EXPECT_EQ(e.repeat, 1);
  ASSERT_EQ(e.runs.size(), 4u);
  EXPECT_EQ(e.runs[0].name, "plain");
  EXPECT_EQ(e.runs[0].solver, "ground");  // the default solver
  EXPECT_TRUE(ground_model_section(e.runs[0].scene).options.sweep);
  EXPECT_EQ(e.runs[1].solver, "initial");
  EXPECT_FALSE(ground_model_section(e.runs[1].scene).options.sweep);
  EXPECT_EQ(e.runs[1].scene.ground.material, "mud");
  EXPECT_EQ(e.runs[0].scene.ground.material, "sand");
  EXPECT_EQ(e.runs[2].name, "sub_2");
  EXPECT_EQ(e.runs[3].name, "sub_5");
  EXPECT_EQ(ground_model_section(e.runs[2].scene).options.substeps, 2);
  EXPECT_EQ(ground_model_section(e.runs[3].scene).options.substeps, 5);
  EXPECT_FALSE(ground_model_section(e.runs[3].scene).options.sweep);
  EXPECT_EQ(e.runs[0].scene_path, (setup.dir.path / "scenes" / "press.yaml").lexically_normal().string());
  // The resolved experiment names every run and its overrides.
  const std::string resolved = experiment_to_yaml(e);
  for (const char* text : {"sub_5", "ground_model.substeps", "ground.material"}) {
    EXPECT_NE(resolved.find(text), std::string::npos) << resolved;
  }
}

// A manifest committed under data/ must not hold the absolute paths of the
// machine that made it: a shipped experiment's resolved YAML names its
// scenes and plot relative to the repository.
TEST(ExperimentFile, TheResolvedExperimentNamesShippedFilesRelativeToTheRepository) {
  const std::string root = REPOSE_SOURCE_DIR;
  const Experiment e =
      load_experiment(root + "/experiments/dem_column_collapse_l30_wide_large.yaml", solver_registry());
  const std::string resolved = experiment_to_yaml(e);
  EXPECT_EQ(resolved.find(root), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("scene: experiments/scenes/dem_column_slot.yaml"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("plot: experiments/plots/dem_column_collapse.py"), std::string::npos) << resolved;
}

TEST(ExperimentFile, UnknownKeysAreErrorsAtTheirLine) {
  ExperimentDir top("runs: [{name: a, scene: scenes/press.yaml}]\ncolour: red\n");
  const std::string top_error = load_error(top.experiment);
  EXPECT_NE(top_error.find("exp.yaml:2:1: colour"), std::string::npos) << top_error;
  ExperimentDir run("runs:\n  - {name: a, scene: scenes/press.yaml, colour: red}\n");
  const std::string run_error = load_error(run.experiment);
  EXPECT_NE(run_error.find("exp.yaml:2:"), std::string::npos) << run_error;
  EXPECT_NE(run_error.find("runs[0].colour"), std::string::npos) << run_error;
}

TEST(ExperimentFile, AnOverrideTheSceneRejectsNamesTheExperimentTheOverrideAndTheScene) {
  ExperimentDir setup(R"(runs:
  - name: a
    scene: scenes/press.yaml
    overrides:
      ground_model.sweep: true
      ground_model.colour: red
)");
  const std::string error = load_error(setup.experiment);
  EXPECT_NE(error.find("exp.yaml:6:"), std::string::npos) << error;
  EXPECT_NE(error.find("runs[0].overrides.ground_model.colour"), std::string::npos) << error;
  EXPECT_NE(error.find("press.yaml"), std::string::npos) << error;
  EXPECT_NE(error.find("colour"), std::string::npos) << error;
}

TEST(ExperimentFile, AnOverrideWithABadValueOrPathIsRejected) {
  ExperimentDir value("runs:\n  - name: a\n    scene: scenes/press.yaml\n    overrides:\n      time.step_s: -1\n");
  const std::string value_error = load_error(value.experiment);
  EXPECT_NE(value_error.find("runs[0].overrides.time.step_s"), std::string::npos) << value_error;
  EXPECT_NE(value_error.find("> 0"), std::string::npos) << value_error;
  ExperimentDir index("runs:\n  - name: a\n    scene: scenes/press.yaml\n    overrides:\n      objects[4].radius_m: 1\n");
  const std::string index_error = load_error(index.experiment);
  EXPECT_NE(index_error.find("the list has 1 item"), std::string::npos) << index_error;
  ExperimentDir sweep(R"(sweeps:
  - name: s
    scene: scenes/press.yaml
    sweep: {key: ground_model.substeps, values: [1, 0]}
)");
  const std::string sweep_error = load_error(sweep.experiment);
  EXPECT_NE(sweep_error.find("exp.yaml:4:"), std::string::npos) << sweep_error;  // at the value 0
  EXPECT_NE(sweep_error.find("substeps"), std::string::npos) << sweep_error;
}

TEST(ExperimentFile, AMissingSceneIsAnErrorAtItsKey) {
  ExperimentDir setup("runs:\n  - name: a\n    scene: scenes/missing.yaml\n");
  const std::string error = load_error(setup.experiment);
  EXPECT_NE(error.find("exp.yaml:3:12: runs[0].scene"), std::string::npos) << error;
  EXPECT_NE(error.find("missing.yaml"), std::string::npos) << error;
}

TEST(ExperimentFile, RejectsBadNamesDuplicatesNoRunsAndUnknownSolvers) {
  ExperimentDir duplicate("runs:\n  - {name: a, scene: scenes/press.yaml}\n  - {name: a, scene: scenes/press.yaml}\n");
  EXPECT_NE(load_error(duplicate.experiment).find("'a' twice"), std::string::npos);
  ExperimentDir folder("runs:\n  - {name: ../up, scene: scenes/press.yaml}\n");
  EXPECT_NE(load_error(folder.experiment).find("runs[0].name"), std::string::npos);
  ExperimentDir none("name: empty\n");
  EXPECT_NE(load_error(none.experiment).find("at least one run"), std::string::npos);
  ExperimentDir solver("runs:\n  - {name: a, scene: scenes/press.yaml, solver: magic}\n");
  EXPECT_NE(load_error(solver.experiment).find("runs[0].solver"), std::string::npos);
  ExperimentDir repeat("repeat: 0\nruns:\n  - {name: a, scene: scenes/press.yaml}\n");
  EXPECT_NE(load_error(repeat.experiment).find("repeat"), std::string::npos);
  ExperimentDir plot("plot: plots/none.py\nruns:\n  - {name: a, scene: scenes/press.yaml}\n");
  EXPECT_NE(load_error(plot.experiment).find("plot"), std::string::npos);
  EXPECT_NE(load_error(plot.experiment / "nothing.yaml").find("no such experiment file"), std::string::npos);
}

// ---- running

TEST(RunExperiment, WritesEveryRunTheSummaryTheManifestAndTheFigures) {
  ExperimentDir setup(R"(name: small
repeat: 2
runs:
  - {name: press, scene: scenes/press.yaml}
  - {name: start, scene: scenes/press.yaml, solver: initial}
sweeps:
  - name: sub
    scene: scenes/press.yaml
    overrides: {ground_model.sweep: false}
    sweep: {key: ground_model.substeps, values: [1, 3]}
measures: [steps, volume.initial_m3]
plot: plots/figure.py
)");
  // The plot script reads the summary and writes a figure (a text file stands in for it).
  write(setup.dir.path / "plots" / "figure.py", R"(import os, sys
folder = sys.argv[1]
assert os.environ["MPLBACKEND"] == "Agg"
rows = open(os.path.join(folder, "summary.csv")).read().splitlines()
open(os.path.join(folder, "figure.txt"), "w").write(str(len(rows) - 1))
)");
  const fs::path out = setup.dir.path / "out";
  const Experiment e = load(setup.experiment);
  const ExperimentOutcome outcome = run_experiment(e, solver_registry(), quiet_options(out));
  EXPECT_EQ(fs::path(outcome.folder), out);
  ASSERT_EQ(outcome.runs.size(), 4u);
  for (const auto& run : outcome.runs) {
    EXPECT_EQ(run.wall_s.size(), 2u) << run.name;  // repeat: 2
    EXPECT_TRUE(fs::is_regular_file(out / run.name / "manifest.json")) << run.name;
    EXPECT_TRUE(fs::is_regular_file(out / run.name / "height_initial.npy")) << run.name;
  }
  for (const char* ground_run : {"press", "sub_1", "sub_3"}) {
    EXPECT_TRUE(fs::is_regular_file(out / ground_run / "height_final.npy")) << ground_run;
  }
  // the initial solver does not step: its final surface is its initial one
  EXPECT_EQ(read_all(out / "start" / "height_final.npy"), read_all(out / "start" / "height_initial.npy"));
  // steps is a result of the ground solver only: 5 steps of 0.02 s.
  EXPECT_EQ(outcome.runs[0].measures[0], 5.0);
  EXPECT_FALSE(outcome.runs[1].measures[0].has_value());
  // The initial volume is the same for every ground run: 0.24 m x 0.24 m x 0.05 m.
  ASSERT_TRUE(outcome.runs[2].measures[1].has_value());
  EXPECT_NEAR(*outcome.runs[2].measures[1], 0.24 * 0.24 * 0.05, 1e-12);

  const auto summary = lines_of(read_all(out / "summary.csv"));
  ASSERT_EQ(summary.size(), 5u);
  EXPECT_EQ(summary[0], "name,solver,wall_s,steps,volume.initial_m3");
  EXPECT_EQ(summary[1].rfind("press,ground,", 0), 0u) << summary[1];
  EXPECT_EQ(summary[2].rfind("start,initial,", 0), 0u) << summary[2];
  EXPECT_EQ(summary[2].substr(summary[2].size() - 2), ",,") << summary[2];  // no results: empty measures
  EXPECT_EQ(read_all(out / "figure.txt"), "4");

  const YAML::Node manifest = YAML::LoadFile((out / "manifest.json").string());
  EXPECT_EQ(manifest["format"].as<std::string>(), "repose-experiment-manifest");
  EXPECT_EQ(manifest["experiment"]["sha256"].as<std::string>(), sha256_hex_of_file(setup.experiment.string()));
  EXPECT_EQ(manifest["build"]["git_commit"].as<std::string>().empty(), false);
  ASSERT_EQ(manifest["runs"].size(), 4u);
  EXPECT_EQ(manifest["runs"][3]["name"].as<std::string>(), "sub_3");
  EXPECT_EQ(manifest["runs"][3]["seed"].as<int>(), 3);
  EXPECT_EQ(manifest["runs"][3]["wall_s"].size(), 2u);
  bool lists_figure = false;
  for (const auto& file : manifest["files"]) lists_figure |= file.as<std::string>() == "figure.txt";
  EXPECT_TRUE(lists_figure);
  // The run's own manifest holds the scene with its overrides.
  const YAML::Node run_manifest = YAML::LoadFile((out / "sub_3" / "manifest.json").string());
  const YAML::Node resolved = YAML::Load(run_manifest["scene"]["resolved_yaml"].as<std::string>());
  EXPECT_EQ(resolved["ground_model"]["substeps"].as<int>(), 3);
  EXPECT_FALSE(resolved["ground_model"]["sweep"].as<bool>());
  // No temporaries are left beside or inside the folder.
  for (const auto& entry : fs::recursive_directory_iterator(setup.dir.path)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
  }
}

// A solver that compiles every scene and fails when it runs.
class FailingSolver final : public Solver {
 public:
  std::string name() const override { return "failing"; }
  std::string description() const override { return "fails when it runs (tests)"; }
  std::unique_ptr<CompiledSolver> compile(const Scene&) const override {
    class Compiled final : public CompiledSolver {
     public:
      const std::vector<ParameterInfo>& parameters() const override { return parameters_; }
      Run run(const std::vector<double>&, const RunOptions&) const override { throw InputError("the run went wrong"); }

     private:
      std::vector<ParameterInfo> parameters_;
    };
    return std::make_unique<Compiled>();
  }
};

TEST(ExperimentFile, ASolverThatCannotRunItsSceneIsRefusedWhenLoading) {
  // The liggghts solver needs the scene's dem section (or a terrain section), which press.yaml lacks.
  ExperimentDir setup("runs:\n  - {name: fine, scene: scenes/press.yaml}\n  - {name: broken, scene: scenes/press.yaml, "
              "solver: liggghts}\n");
  const std::string error = load_error(setup.experiment);
  EXPECT_NE(error.find("runs[1].solver: expected a solver that can run"), std::string::npos) << error;
  EXPECT_NE(error.find("'dem' section"), std::string::npos) << error;
}

TEST(RunExperiment, AFailedRunFailsTheExperimentNamingItAndWritesNothing) {
  SolverRegistry registry;
  registry.add(std::make_shared<GroundSolver>()).add(std::make_shared<FailingSolver>());
  ExperimentDir setup("runs:\n  - {name: fine, scene: scenes/press.yaml}\n  - {name: broken, scene: scenes/press.yaml, "
              "solver: failing}\n");
  const fs::path out = setup.dir.path / "out";
  const Experiment e = load_experiment(setup.experiment.string(), registry);
  try {
    run_experiment(e, registry, quiet_options(out));
    FAIL() << "the experiment should fail";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("run 'broken' failed: the run went wrong"), std::string::npos)
        << error.what();
  }
  EXPECT_FALSE(fs::exists(out));
  for (const auto& entry : fs::directory_iterator(setup.dir.path)) {
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
  }
}

TEST(RunExperiment, AFailingPlotOrAnUnknownMeasureLeavesAnOldFolderAsItWas) {
  ExperimentDir setup("plot: plots/fail.py\nruns:\n  - {name: a, scene: scenes/press.yaml, solver: initial}\n");
  write(setup.dir.path / "plots" / "fail.py", "import sys\nsys.exit(3)\n");
  const fs::path out = setup.dir.path / "out";
  write(out / "old.txt", "old");
  ExperimentOptions options = quiet_options(out);
  options.force = true;
  EXPECT_THROW(run_experiment(load(setup.experiment), solver_registry(), options), std::runtime_error);
  EXPECT_EQ(read_all(out / "old.txt"), "old");

  ExperimentDir measure("measures: [no_such_result]\nruns:\n  - {name: a, scene: scenes/press.yaml}\n");
  try {
    run_experiment(load(measure.experiment), solver_registry(), options);
    FAIL() << "an unknown measure should fail";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("no_such_result"), std::string::npos) << error.what();
  }
  EXPECT_EQ(read_all(out / "old.txt"), "old");
  EXPECT_FALSE(fs::exists(out / "a"));
}

// ---- the command line

struct Result {
  int exit_code = -1;
  std::string err;
};

Result run_repose(const std::vector<std::string>& args, const fs::path& cwd) {
  TempDir capture;
  const std::string err_path = (capture.path / "err").string();
  std::string command = "cd '" + cwd.string() + "' && '" + REPOSE_BINARY + "'";
  for (const auto& a : args) command += " '" + a + "'";
  command += " >/dev/null 2>'" + err_path + "'";
  const int status = std::system(command.c_str());
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read_all(err_path)};
}

TEST(ExperimentCommand, RunsAnExperimentAndRefusesABadOneWithOneLine) {
  ExperimentDir setup("runs:\n  - {name: a, scene: scenes/press.yaml}\nmeasures: [steps]\n");
  const Result ok = run_repose({"experiment", "exp.yaml", "--out", "out"}, setup.dir.path);
  EXPECT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_TRUE(fs::is_regular_file(setup.dir.path / "out" / "summary.csv"));
  EXPECT_TRUE(fs::is_regular_file(setup.dir.path / "out" / "a" / "height_final.npy"));
  EXPECT_NE(ok.err.find("[1/1] a"), std::string::npos) << ok.err;  // a progress line per run
  // Not empty: refused without --force, replaced with it.
  EXPECT_EQ(run_repose({"experiment", "exp.yaml", "--out", "out"}, setup.dir.path).exit_code, 2);
  EXPECT_EQ(run_repose({"experiment", "exp.yaml", "--out", "out", "--force"}, setup.dir.path).exit_code, 0);

  write(setup.dir.path / "bad.yaml", "runs:\n  - name: b\n    scene: scenes/press.yaml\n    overrides: {ground.nope: 1}\n");
  const Result bad = run_repose({"experiment", "bad.yaml", "--out", "bad_out"}, setup.dir.path);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_EQ(std::count(bad.err.begin(), bad.err.end(), '\n'), 1) << bad.err;
  EXPECT_EQ(bad.err.rfind("bad.yaml:4:", 0), 0u) << bad.err;
  EXPECT_FALSE(fs::exists(setup.dir.path / "bad_out"));
}

}  // namespace
}  // namespace repose
