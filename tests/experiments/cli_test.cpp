// The `repose` program, run as a subprocess: exit codes, one-line errors,
// nothing written on bad input, run folders and their manifests.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/core/config/initial_height.h"
#include "experiments/solvers/solver_registry.h"
#include "models/core/io/npy_io.h"
#include "models/core/io/png_io.h"
#include "models/core/config/scene_loader.h"
#include "models/core/base/sha256.h"
#include "tests/support/run_repose.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

const char* const kPython = "/usr/bin/python3";

using test_support::read_all;
using test_support::run_repose;
using Result = test_support::ProgramResult;

struct TempDir : test_support::TempDir {
  TempDir() : test_support::TempDir("repose_cli") {}
};

bool is_one_line(const std::string& text) {
  return !text.empty() && text.back() == '\n' && std::count(text.begin(), text.end(), '\n') == 1;
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) return files;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.is_regular_file()) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// The scene files of a folder (other files there are meshes and height maps they use).
std::vector<fs::path> scene_files_in(const fs::path& dir) {
  std::vector<fs::path> scenes;
  for (const auto& path : files_in(dir)) {
    if (path.extension() == ".yaml" || path.extension() == ".yml") scenes.push_back(path);
  }
  return scenes;
}

// A small scene with seeded noise, so that determinism means something.
const char* const kNoiseScene = R"(name: cli_test
seed: 7
time: {step_s: 0.01, duration_s: 0.1}
ground:
  extent_m: [0.5, 0.4]
  cell_size_m: 0.01
  initial_height: {kind: noise, mean_m: 0.05, amplitude_m: 0.01, correlation_m: 0.02}
  material: sand
objects:
  - name: ball
    shape: sphere
    radius_m: 0.05
    motion:
      - {time_s: 0, position_m: [0, 0, 0.2], orientation_deg: [0, 0, 0]}
)";

fs::path write_scene(const fs::path& dir) {
  const fs::path path = dir / "scene.yaml";
  std::ofstream(path) << kNoiseScene;
  return path;
}

TEST(Cli, VersionAndHelpExitZero) {
  TempDir cwd;
  const Result version = run_repose({"--version"}, cwd.path);
  EXPECT_EQ(version.exit_code, 0) << version.err;
  EXPECT_NE(version.out.find("repose "), std::string::npos) << version.out;
  EXPECT_NE(version.out.find("git commit"), std::string::npos) << version.out;
  EXPECT_NE(version.out.find("Eigen"), std::string::npos) << version.out;
  const Result help = run_repose({"--help"}, cwd.path);
  EXPECT_EQ(help.exit_code, 0) << help.err;
  for (const char* command : {"check", "render", "run"}) {
    EXPECT_NE(help.out.find(command), std::string::npos) << help.out;
  }
  EXPECT_TRUE(fs::is_empty(cwd.path));
}

TEST(Cli, CommandLineErrorsExitTwoWithOneLine) {
  TempDir cwd;
  const fs::path scene = write_scene(cwd.path);
  const std::vector<std::vector<std::string>> bad = {
      {"--no-such-option"},
      {},                                          // no subcommand
      {"frobnicate"},                              // unknown subcommand
      {"check"},                                   // missing scene
      {"run", scene.string()},                     // missing --out
      {"run", scene.string(), "--out", "x", "--solver", "no-such-solver"},
      {"run", scene.string(), "--out", "x", "--bogus"},
      {"render", scene.string(), "-o", "x.png", "--size", "12by3"},
      {"render", scene.string(), "-o", "x.png", "--camera-position", "1,2"},
  };
  for (const auto& args : bad) {
    const Result r = run_repose(args, cwd.path);
    std::string joined;
    for (const auto& a : args) joined += a + " ";
    EXPECT_EQ(r.exit_code, 2) << joined << r.err;
    EXPECT_TRUE(is_one_line(r.err)) << joined << "stderr: [" << r.err << "]";
    EXPECT_EQ(files_in(cwd.path), std::vector<fs::path>{scene}) << joined;  // wrote nothing
    EXPECT_FALSE(fs::exists(cwd.path / "x")) << joined;
  }
}

// Each malformed scene says what it should fail with: `# expect: FRAGMENT` on its first line.
TEST(Cli, CheckRejectsEveryBadSceneWithOneLocatedLineAndWritesNothing) {
  const fs::path bad_dir = fs::path(REPOSE_SOURCE_DIR) / "tests/data/scenes/bad";
  const std::vector<fs::path> scenes = scene_files_in(bad_dir);
  ASSERT_FALSE(scenes.empty()) << "no malformed scenes in " << bad_dir;
  const std::regex expect_line("^#\\s*expect:\\s*(.*\\S)\\s*$");
  for (const fs::path& scene : scenes) {
    std::ifstream in(scene);
    std::string first_line;
    std::getline(in, first_line);
    std::smatch match;
    ASSERT_TRUE(std::regex_match(first_line, match, expect_line)) << scene << ": first line is not '# expect: ...'";
    const std::string fragment = match[1];

    TempDir cwd;
    const Result r = run_repose({"check", scene.string()}, cwd.path);
    EXPECT_EQ(r.exit_code, 2) << scene << "\n" << r.err;
    EXPECT_TRUE(is_one_line(r.err)) << scene << "\nstderr: [" << r.err << "]";
    // FILE:LINE:COL: ...
    const std::string prefix = scene.string() + ":";
    ASSERT_EQ(r.err.compare(0, prefix.size(), prefix), 0) << scene << "\nstderr: " << r.err;
    EXPECT_TRUE(std::regex_search(r.err.substr(prefix.size()), std::regex("^[0-9]+:[0-9]+: ")))
        << scene << "\nstderr: " << r.err;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << scene << "\nexpected: " << fragment << "\nstderr: " << r.err;
    EXPECT_TRUE(fs::is_empty(cwd.path)) << scene;
  }
}

TEST(Cli, CheckAcceptsEveryGoodScene) {
  const fs::path good_dir = fs::path(REPOSE_SOURCE_DIR) / "tests/data/scenes/good";
  const std::vector<fs::path> scenes = scene_files_in(good_dir);
  ASSERT_FALSE(scenes.empty()) << "no scenes in " << good_dir;
  for (const fs::path& scene : scenes) {
    TempDir cwd;
    const Result r = run_repose({"check", scene.string()}, cwd.path);
    EXPECT_EQ(r.exit_code, 0) << scene << "\n" << r.err;
    EXPECT_FALSE(r.out.empty()) << scene;
    EXPECT_TRUE(fs::is_empty(cwd.path)) << scene;
  }
}

// The run folder holds a manifest that Python's json module reads, with the
// scene file's hash and seed, and the initial heights exactly as the library makes them.
TEST(Cli, RunWritesManifestAndInitialHeights) {
  TempDir cwd;
  const fs::path scene_path = write_scene(cwd.path);
  const Result r = run_repose({"run", scene_path.string(), "--out", "out"}, cwd.path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const fs::path out = cwd.path / "out";
  ASSERT_TRUE(fs::exists(out / "manifest.json"));
  ASSERT_TRUE(fs::exists(out / "height_initial.npy"));
  EXPECT_TRUE(fs::exists(out / "height_initial.png"));

  const Scene scene = load_scene(scene_path.string(), solver_registry().sections());
  const ArrayXXdR written = read_npy_2d((out / "height_initial.npy").string());
  const HeightField expected = make_initial_height(scene);
  ASSERT_EQ(written.rows(), expected.ny());
  ASSERT_EQ(written.cols(), expected.nx());
  EXPECT_TRUE((written == expected.heights()).all());

  if (!fs::exists(kPython)) GTEST_SKIP() << "no " << kPython << " to parse the manifest";
  const fs::path fields = cwd.path / "fields.txt";
  const std::string script =
      "import json,sys; m=json.load(open(sys.argv[1], encoding='utf-8')); "
      "stages=[s['name'] for s in m['stages']]; "
      "assert all(s['wall_s'] >= 0 for s in m['stages']); "
      "assert m['start_time_utc'].endswith('Z'); "
      "assert 'height_initial.npy' in m['files']; "
      "assert len(m['build']['git_commit']) > 0 and 'Eigen' in m['build']['libraries']; "
      "assert 'seed: 7' in m['scene']['resolved_yaml']; "
      "open(sys.argv[2], 'w').write('\\n'.join([m['scene']['sha256'], str(m['scene']['seed']), "
      "m['command_line'][1], ','.join(stages)]))";
  const std::string command = std::string(kPython) + " -c \"" + script + "\" " + (out / "manifest.json").string() +
                              " " + fields.string();
  ASSERT_EQ(std::system(command.c_str()), 0) << read_all(out / "manifest.json");
  std::ifstream lines(fields);
  std::string sha, seed, subcommand, stages;
  std::getline(lines, sha);
  std::getline(lines, seed);
  std::getline(lines, subcommand);
  std::getline(lines, stages);
  EXPECT_EQ(sha, sha256_hex_of_file(scene_path.string()));
  EXPECT_EQ(seed, "7");
  EXPECT_EQ(subcommand, "run");
  EXPECT_NE(stages.find("load_scene"), std::string::npos) << stages;
  EXPECT_NE(stages.find("compile_ground"), std::string::npos) << stages;
  EXPECT_NE(stages.find("write_height_initial_npy"), std::string::npos) << stages;
}

// A run's manifest is committed with the reference data under data/: the
// resolved scene names the mesh it loaded by its path in the repository, not
// by the absolute path of the machine that ran it.
TEST(Cli, TheManifestsResolvedSceneNamesRepositoryFilesRelativeToTheRepository) {
  TempDir cwd;
  const std::string mesh = std::string(REPOSE_SOURCE_DIR) + "/experiments/meshes/bucket.obj";
  const fs::path scene_path = cwd.path / "mesh.yaml";
  std::ofstream(scene_path) << "name: mesh_manifest\nseed: 1\ntime: {step_s: 0.05, duration_s: 0.1}\n"
                               "ground: {extent_m: [0.2, 0.1], cell_size_m: 0.01, initial_height: {kind: flat, "
                               "height_m: 0.02}, material: sand}\n"
                               "objects:\n  - {name: bucket, shape: mesh, mesh: " + mesh +
                               ", motion: [{time_s: 0, position_m: [0.1, 0.05, 0.1]}]}\n";
  const Result r = run_repose({"run", scene_path.string(), "--out", "out"}, cwd.path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string manifest = read_all(cwd.path / "out" / "manifest.json");
  EXPECT_NE(manifest.find("mesh: experiments/meshes/bucket.obj"), std::string::npos) << manifest;
  EXPECT_EQ(manifest.find(std::string(REPOSE_SOURCE_DIR) + "/experiments"), std::string::npos) << manifest;
}

TEST(Cli, RunRefusesNonEmptyFolderUnlessForced) {
  TempDir cwd;
  const fs::path scene = write_scene(cwd.path);
  fs::create_directory(cwd.path / "out");
  std::ofstream(cwd.path / "out" / "old.txt") << "old";

  const Result refused = run_repose({"run", scene.string(), "--out", "out"}, cwd.path);
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_TRUE(is_one_line(refused.err)) << refused.err;
  EXPECT_NE(refused.err.find("--force"), std::string::npos) << refused.err;
  EXPECT_EQ(files_in(cwd.path / "out"), std::vector<fs::path>{cwd.path / "out" / "old.txt"});
  EXPECT_EQ(read_all(cwd.path / "out" / "old.txt"), "old");

  const Result forced = run_repose({"run", scene.string(), "--out", "out", "--force"}, cwd.path);
  EXPECT_EQ(forced.exit_code, 0) << forced.err;
  EXPECT_FALSE(fs::exists(cwd.path / "out" / "old.txt"));
  EXPECT_TRUE(fs::exists(cwd.path / "out" / "manifest.json"));
  // nothing left beside the run folder (temporaries, the old folder)
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(cwd.path)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"out", "scene.yaml"}));
}

TEST(Cli, RunWithBadSceneWritesNothing) {
  TempDir cwd;
  std::ofstream(cwd.path / "bad.yaml") << "name: x\nno_such_key: 1\n";
  const Result r = run_repose({"run", "bad.yaml", "--out", "out"}, cwd.path);
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_TRUE(is_one_line(r.err)) << r.err;
  EXPECT_EQ(files_in(cwd.path), std::vector<fs::path>{cwd.path / "bad.yaml"});
  EXPECT_EQ(std::distance(fs::directory_iterator(cwd.path), fs::directory_iterator()), 1);
}

TEST(Cli, RunTwiceGivesBitIdenticalInitialHeights) {
  TempDir cwd;
  const fs::path scene = write_scene(cwd.path);
  ASSERT_EQ(run_repose({"run", scene.string(), "--out", "a"}, cwd.path).exit_code, 0);
  ASSERT_EQ(run_repose({"run", scene.string(), "--out", "b"}, cwd.path).exit_code, 0);
  const std::string a = read_all(cwd.path / "a" / "height_initial.npy");
  EXPECT_FALSE(a.empty());
  EXPECT_EQ(a, read_all(cwd.path / "b" / "height_initial.npy"));
}

// --set changes a scene key before the scene is checked: another seed is
// another random surface, the file's own seed the same one; a malformed or
// unknown override is refused in one line before anything is written.
TEST(Cli, RunSetOverridesASceneKeyAndIsCheckedLikeTheFile) {
  TempDir cwd;
  const fs::path scene = write_scene(cwd.path);
  ASSERT_EQ(run_repose({"run", scene.string(), "--out", "a"}, cwd.path).exit_code, 0);
  ASSERT_EQ(run_repose({"run", scene.string(), "--out", "same", "--set", "seed=7"}, cwd.path).exit_code, 0);
  ASSERT_EQ(run_repose({"run", scene.string(), "--out", "other", "--set", "seed=8"}, cwd.path).exit_code, 0);
  const std::string a = read_all(cwd.path / "a" / "height_initial.npy");
  EXPECT_EQ(a, read_all(cwd.path / "same" / "height_initial.npy"));
  EXPECT_NE(a, read_all(cwd.path / "other" / "height_initial.npy"));
  for (const char* bad : {"seed", "no_such_key=1", "seed=-1"}) {
    const Result r = run_repose({"run", scene.string(), "--out", "bad", "--set", bad}, cwd.path);
    EXPECT_EQ(r.exit_code, 2) << bad << ": " << r.err;
    EXPECT_TRUE(is_one_line(r.err)) << r.err;
    EXPECT_FALSE(fs::exists(cwd.path / "bad")) << bad;
  }
}

TEST(Cli, RenderWritesAPngOfTheAskedSize) {
  TempDir cwd;
  const fs::path scene = write_scene(cwd.path);
  const Result from_scene = run_repose({"render", scene.string(), "-o", "scene.png", "--size", "64x48"}, cwd.path);
  ASSERT_EQ(from_scene.exit_code, 0) << from_scene.err;
  const RgbImage image = read_png_rgb((cwd.path / "scene.png").string());
  EXPECT_EQ(image.width, 64);
  EXPECT_EQ(image.height, 48);

  ArrayXXdR field(20, 30);
  for (int j = 0; j < 20; ++j) {
    for (int i = 0; i < 30; ++i) field(j, i) = 0.01 * i + 0.02 * j;
  }
  write_npy_2d((cwd.path / "field.npy").string(), field);
  const Result from_npy = run_repose(
      {"render", "field.npy", "-o", "field.png", "--size", "40x30", "--camera-position", "0,-2,2", "--fov-deg", "50"},
      cwd.path);
  ASSERT_EQ(from_npy.exit_code, 0) << from_npy.err;
  EXPECT_EQ(read_png_rgb((cwd.path / "field.png").string()).width, 40);
}

// A debris run folder (a short ODE run of the debris scene) renders as a
// 3-D figure series, PREFIX_NNN.png, one per frame drawn.
TEST(Cli, RenderDrawsADebrisRunFolderAsASeries) {
  TempDir cwd;
  const fs::path scene = fs::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes" / "terrain_debris.yaml";
  const Result run = run_repose(
      {"run", scene.string(), "--solver", "ode", "--set", "time.duration_s=0.2", "--out", "debris"}, cwd.path);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Result r = run_repose({"render", "debris", "-o", "debris_3d.png", "--frames", "2", "--size", "80x60"}, cwd.path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_png_rgb((cwd.path / "debris_3d_000.png").string()).width, 80);
  EXPECT_EQ(read_png_rgb((cwd.path / "debris_3d_020.png").string()).height, 60);
  EXPECT_NE(r.out.find("debris_3d_020.png"), std::string::npos) << r.out;
  const Result bad = run_repose({"render", "debris", "-o", "x.png", "--camera-position", "1,2,3"}, cwd.path);
  EXPECT_EQ(bad.exit_code, 2) << bad.err;
  EXPECT_TRUE(is_one_line(bad.err)) << bad.err;
}

}  // namespace
}  // namespace repose
