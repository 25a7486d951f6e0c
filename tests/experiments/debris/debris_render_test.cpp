// The debris collapse in 3-D (experiments/debris/debris_render.h): a run
// folder in the layout every engine writes, drawn so that the terrain, the
// elements and the parts (in place or moved) show as their own colours; and
// a real ODE run of the debris scene, drawn the same way.
#include "experiments/debris/debris_render.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>

#include "experiments/solvers/solver_registry.h"
#include "models/core/base/error.h"
#include "models/core/config/scene_loader.h"
#include "models/core/io/mesh_io.h"
#include "models/core/io/npy_io.h"
#include "models/core/solver/solver.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

struct TempDir : test_support::TempDir {
  TempDir() : test_support::TempDir("debris_render") { fs::create_directories(path / "frames"); }
};

// A flat 40 m square at z = 0, one 4 x 4 x 3 m part at (10, 10), and two
// frames: elements (radius 1 m) near the origin, the part in place; then the
// elements moved 8 m along -y and the part pushed 1 m along +x.
void write_run(const fs::path& dir) {
  TriangleMesh terrain;
  terrain.V.resize(4, 3);
  terrain.V << -20, -20, 0, 20, -20, 0, 20, 20, 0, -20, 20, 0;
  terrain.F.resize(2, 3);
  terrain.F << 0, 1, 2, 0, 2, 3;
  write_obj((dir / "terrain.obj").string(), terrain);
  std::ofstream(dir / "parts.json") << R"({"buildings": ["house"], "parts": [{"building": 0, "mass_kg": 1.0,
    "hull_m": [[-2,-2,-1.5],[-2,-2,1.5],[2,-2,-1.5],[2,-2,1.5],[2,2,-1.5],[2,2,1.5],[-2,2,-1.5],[-2,2,1.5]]}]})";
  std::ofstream(dir / "front.csv") << "time_s,front_m,front_speed_m_s,mean_speed_m_s,joints_broken\n0,0,0,0,0\n1,8,8,8,1\n";
  for (int k = 0; k < 2; ++k) {
    ArrayXXdR e(9, 4);
    for (int i = 0; i < 9; ++i) e.row(i) << -4.0 + 2.0 * (i % 3), -2.0 + 2.0 * (i / 3) - 8.0 * k, 1.0, 1.0;
    write_npy_2d((dir / fmt::format("frames/elements_{:03d}.npy", k)).string(), e);
    ArrayXXdR p(1, 7);
    p << 10.0 + k, 10.0, 1.5, 1, 0, 0, 0;
    write_npy_2d((dir / fmt::format("frames/parts_{:03d}.npy", k)).string(), p);
  }
}

// Unlit, without antialiasing: every pixel is exactly one of the colours.
DebrisRenderOptions flat_options() {
  DebrisRenderOptions o;
  o.image.ambient = 1.0;
  o.image.supersample = 1;
  o.width_px = 160;
  o.height_px = 120;
  o.margin_m = 2.0;
  return o;
}

Eigen::Vector3i bytes(const Eigen::Vector3d& rgb01) { return (rgb01 * 255.0).array().round().cast<int>(); }

bool near(const RgbImage& img, std::size_t px, const Eigen::Vector3i& c) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(int(img.rgb[3 * px + static_cast<std::size_t>(k)]) - c[k]) > 2) return false;
  }
  return true;
}

std::size_t count(const RgbImage& img, const Eigen::Vector3d& rgb01) {
  std::size_t n = 0;
  for (std::size_t px = 0; px < img.rgb.size() / 3; ++px) n += near(img, px, bytes(rgb01)) ? 1 : 0;
  return n;
}

TEST(DebrisRender, TheFrameShowsTheTerrainTheElementsAndThePartInPlace) {
  TempDir dir;
  write_run(dir.path);
  const DebrisRunFrames run = read_debris_run_frames(dir.path.string());
  ASSERT_EQ(run.frames.size(), 2u);
  const DebrisRenderOptions o = flat_options();
  const RgbImage img = render_debris_frame(run, 0, debris_camera(run, {0, 1}, o), o);
  const double px = o.width_px * o.height_px;
  EXPECT_GT(count(img, (o.terrain_low_rgb + o.terrain_high_rgb) / 2) / px, 0.2);  // flat: the middle of the ramp
  EXPECT_GT(count(img, o.element_large_rgb) / px, 0.004);                         // one radius: the large end
  EXPECT_GT(count(img, o.part_rgb) / px, 0.005);
  EXPECT_EQ(count(img, o.moved_part_rgb), 0u);
}

TEST(DebrisRender, APartThatMovedIsDrawnRedAndTheElementsWhereTheyAre) {
  TempDir dir;
  write_run(dir.path);
  const DebrisRunFrames run = read_debris_run_frames(dir.path.string());
  const DebrisRenderOptions o = flat_options();
  const CameraSpec camera = debris_camera(run, {0, 1}, o);
  const RgbImage img = render_debris_frame(run, 1, camera, o);
  EXPECT_GT(count(img, o.moved_part_rgb), 0u);
  EXPECT_EQ(count(img, o.part_rgb), 0u);
  // the centre element's top: on an element now, on the terrain before it moved
  const auto at = [&](const Eigen::Vector3d& p) {
    const Eigen::Vector2d uv = *project_to_image(camera, p);
    return static_cast<std::size_t>(std::floor(uv.y())) * static_cast<std::size_t>(o.width_px) +
           static_cast<std::size_t>(std::floor(uv.x()));
  };
  EXPECT_TRUE(near(img, at({-2, -8, 2}), bytes(o.element_large_rgb)));
  EXPECT_FALSE(near(img, at({-2, 0, 2}), bytes(o.element_large_rgb)));
}

TEST(DebrisRender, WritesTheSeriesItPromises) {
  TempDir dir;
  write_run(dir.path);
  DebrisRenderOptions o = flat_options();
  const auto files = write_debris_renders(dir.path.string(), (dir.path / "out").string(), o);
  ASSERT_EQ(files.size(), 2u);
  EXPECT_EQ(files[1], (dir.path / "out_001.png").string());
  const RgbImage img = read_png_rgb(files[1]);
  EXPECT_EQ(img.width, o.width_px);
  EXPECT_GT(count(img, o.moved_part_rgb), 0u);
}

TEST(DebrisRender, PicksFramesEvenlyFromFirstToLast) {
  EXPECT_EQ(picked_frames(21, 6), (std::vector<int>{0, 4, 8, 12, 16, 20}));
  EXPECT_EQ(picked_frames(3, 6), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(picked_frames(5, 1), (std::vector<int>{4}));
}

TEST(DebrisRender, RefusesAFolderThatIsNotADebrisRunNamingTheFile) {
  TempDir dir;
  write_run(dir.path);
  ArrayXXdR two_parts(2, 7);
  two_parts.setZero();
  write_npy_2d((dir.path / "frames/parts_001.npy").string(), two_parts);
  try {
    read_debris_run_frames(dir.path.string());
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("parts_001.npy"), std::string::npos) << e.what();
  }
  fs::remove(dir.path / "parts.json");
  EXPECT_THROW(read_debris_run_frames(dir.path.string()), InputError);
  DebrisRenderOptions bad;
  bad.elevation_deg = 90.0;
  EXPECT_THROW(bad.validate(), InputError);
}

// A real engine: ODE runs the debris scene for 0.3 s into a folder (as the
// experiment does), and its last frame shows the elements and the buildings.
TEST(DebrisRender, DrawsARealOdeRunOfTheDebrisScene) {
  TempDir dir;
  const fs::path scene_path = fs::path(REPOSE_SOURCE_DIR) / "experiments" / "scenes" / "terrain_debris.yaml";
  std::ifstream in(scene_path);
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::size_t at = yaml.find("duration_s: 8.0");
  ASSERT_NE(at, std::string::npos);
  yaml.replace(at, 15, "duration_s: 0.3");
  const Scene scene = load_scene_from_string(yaml, scene_path.string(), solver_registry().sections());
  const auto compiled = solver_registry().get("ode").compile(scene);
  RunOptions run_options;
  run_options.output_dir = dir.path.string();
  compiled->run(compiled->default_values(), run_options);

  const DebrisRunFrames run = read_debris_run_frames(dir.path.string());
  ASSERT_GE(run.frames.size(), 2u);
  DebrisRenderOptions o = flat_options();
  const int last = static_cast<int>(run.frames.size()) - 1;
  const RgbImage img = render_debris_frame(run, last, debris_camera(run, {0, last}, o), o);
  const double px = o.width_px * o.height_px;
  // radii vary (a random bed): count the elements as any colour on the element ramp's hue
  std::size_t elements = 0, terrain = 0;
  for (std::size_t p = 0; p < img.rgb.size() / 3; ++p) {
    const int r = img.rgb[3 * p], g = img.rgb[3 * p + 1], b = img.rgb[3 * p + 2];
    const bool element = r > g + 40 && g > b + 20;  // brown to orange
    const bool background = r > 250 && g > 250 && b > 250;
    elements += element ? 1 : 0;
    terrain += (!element && !background && g > b) ? 1 : 0;  // green to pale (the parts are bluish, b > g)
  }
  EXPECT_GT(elements / px, 0.004);
  EXPECT_GT(terrain / px, 0.1);
  EXPECT_GT(count(img, o.part_rgb) + count(img, o.moved_part_rgb), 0u);
}

}  // namespace
}  // namespace repose
