// The malformed-input corpus (tests/malformed/, written by make_malformed.py)
// through the real program: every malformed .npy, PNG, OBJ and STL file,
// referenced from a small scene, must make `repose check` and `repose run`
// (and `repose render FILE.npy`) exit 2 with exactly one line on stderr that
// names the scene with its line and column, the data file, and the reason
// (the fragment on the scene's `# expect:` first line); and nothing may be
// written in the output folder.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/support/run_repose.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

using test_support::read_all;
using test_support::run_repose;
using Result = test_support::ProgramResult;

struct TempDir : test_support::TempDir {
  TempDir() : test_support::TempDir("repose_malformed") {}
};

bool is_one_line(const std::string& text) {
  return !text.empty() && text.back() == '\n' && std::count(text.begin(), text.end(), '\n') == 1;
}

struct MalformedCase {
  fs::path scene;
  fs::path data;          // the malformed file the scene names
  std::string fragment;   // from `# expect:`
};

const fs::path kCorpus = fs::path(REPOSE_SOURCE_DIR) / "tests/malformed";

MalformedCase read_case(const fs::path& scene) {
  const std::string text = read_all(scene);
  static const std::regex expect("^#\\s*expect:\\s*(.*\\S)\\s*\n");
  static const std::regex data("(?:path|mesh):\\s*([^,}\\s]+)");
  std::smatch m;
  MalformedCase c;
  c.scene = scene;
  if (std::regex_search(text, m, expect)) c.fragment = m[1];
  if (std::regex_search(text, m, data)) c.data = scene.parent_path() / std::string(m[1]);
  return c;
}

std::vector<MalformedCase> corpus() {
  std::vector<MalformedCase> cases;
  for (const auto& e : fs::directory_iterator(kCorpus)) {
    if (e.path().extension() == ".yaml") cases.push_back(read_case(e.path()));
  }
  std::sort(cases.begin(), cases.end(), [](const auto& a, const auto& b) { return a.scene < b.scene; });
  return cases;
}

// The checks every malformed input must pass, for one command.
void expect_rejected(const Result& r, const fs::path& cwd, const MalformedCase& c, const std::string& command,
                     bool names_scene) {
  const std::string where = c.scene.filename().string() + " (" + command + ")\nstderr: " + r.err;
  EXPECT_EQ(r.exit_code, 2) << where;
  EXPECT_TRUE(is_one_line(r.err)) << where;
  EXPECT_NE(r.err.find(c.fragment), std::string::npos) << where << "expected: " << c.fragment;
  EXPECT_NE(r.err.find(c.data.filename().string()), std::string::npos) << where << "does not name the data file";
  if (names_scene) {
    // FILE:LINE:COL of the scene key that names the data file
    const std::regex located(std::regex_replace(c.scene.filename().string(), std::regex("\\."), "\\.") + ":\\d+:\\d+: ");
    EXPECT_TRUE(std::regex_search(r.err, located)) << where << "does not name the scene's line and column";
  }
  EXPECT_TRUE(fs::is_empty(cwd)) << where << "wrote into the output folder";
}

TEST(MalformedInputs, CorpusIsComplete) {
  const std::vector<MalformedCase> cases = corpus();
  EXPECT_GE(cases.size(), 30u) << "the issue asks for at least 30 malformed inputs besides the scenes";
  for (const MalformedCase& c : cases) {
    EXPECT_FALSE(c.fragment.empty()) << c.scene << ": first line is not '# expect: ...'";
    EXPECT_TRUE(fs::exists(c.data)) << c.scene << ": names no existing data file (run make_malformed.py)";
  }
}

TEST(MalformedInputs, CheckAndRunRejectEachWithOneLocatedLineAndWriteNothing) {
  for (const MalformedCase& c : corpus()) {
    TempDir cwd;
    expect_rejected(run_repose({"check", c.scene.string()}, cwd.path), cwd.path, c, "check", true);
    expect_rejected(run_repose({"run", c.scene.string(), "--out", "out"}, cwd.path), cwd.path, c, "run", true);
  }
}

TEST(MalformedInputs, RenderRejectsEachMalformedNpy) {
  int rendered = 0;
  for (const MalformedCase& c : corpus()) {
    if (c.data.extension() != ".npy") continue;
    TempDir cwd;
    expect_rejected(run_repose({"render", c.data.string(), "-o", "out.png"}, cwd.path), cwd.path, c, "render", false);
    ++rendered;
  }
  EXPECT_GT(rendered, 10);
}

// An unreadable mesh file: chmod 000 on a copy of a good mesh. Root reads
// any file whatever its mode, so the case cannot be made when run as root.
TEST(MalformedInputs, UnreadableMeshFile) {
  if (::geteuid() == 0) GTEST_SKIP() << "running as root: a chmod 000 file is still readable";
  TempDir dir;
  const fs::path mesh = dir.path / "locked.obj";
  fs::copy_file(fs::path(REPOSE_SOURCE_DIR) / "tests/data/meshes/cube.obj", mesh);
  fs::permissions(mesh, fs::perms::none);
  const fs::path scene = dir.path / "unreadable.yaml";
  std::ofstream(scene) << "time: {step_s: 0.1, duration_s: 0.2}\n"
                          "ground: {extent_m: [0.4, 0.4], cell_size_m: 0.01, initial_height: {kind: flat, height_m: 0.05}}\n"
                          "objects:\n  - {name: thing, shape: mesh, mesh: locked.obj, motion: [{time_s: 0, position_m: [0, 0, 0.1]}]}\n";
  const MalformedCase c{scene, mesh, "cannot be read"};
  TempDir cwd;
  expect_rejected(run_repose({"check", scene.string()}, cwd.path), cwd.path, c, "check", true);
  expect_rejected(run_repose({"run", scene.string(), "--out", "out"}, cwd.path), cwd.path, c, "run", true);
}

}  // namespace
}  // namespace repose
