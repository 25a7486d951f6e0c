// repose render SCENE.yaml|FIELD.npy -o IMAGE.png [camera options]: a picture
// of a scene's initial ground with its objects at t = 0, or of a height field
// from a .npy file.
// repose render RUN_DIR -o PREFIX.png [--frames N --size WxH --azimuth-deg A
// --elevation-deg E]: a debris run's collapse in 3-D as a figure series,
// PREFIX_NNN.png per frame drawn (experiments/debris/debris_render.h).
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "experiments/cli/commands.h"
#include "experiments/debris/debris_render.h"
#include "experiments/figures/render_height.h"
#include "models/core/base/error.h"
#include "models/core/config/initial_height.h"
#include "models/core/io/npy_io.h"
#include "models/core/config/scene_loader.h"

namespace repose::cli {
namespace {

struct RenderOptions {
  std::string input_path;
  std::string image_path;
  std::string camera_position;  // "x,y,z" in metres
  std::string camera_target;    // "x,y,z" in metres
  double fov_deg = 0.0;         // 0: the scene's or the default
  std::string size;             // "WxH" in pixels
  double cell_size_m = 0.0;     // .npy only; 0: the field is 1 m wide
  DebrisRenderOptions debris;   // a debris run folder only: frames, camera direction
};

double parse_number(const std::string& text, const std::string& option, const std::string& expected) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
    throw InputError(fmt::format("{}: expected {}, got '{}'", option, expected, text));
  }
  return value;
}

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts(1);
  for (char c : text) {
    if (c == separator) {
      parts.emplace_back();
    } else {
      parts.back().push_back(c);
    }
  }
  return parts;
}

Eigen::Vector3d parse_point(const std::string& text, const std::string& option) {
  const std::string expected = "x,y,z (three numbers, metres)";
  const auto parts = split(text, ',');
  if (parts.size() != 3) throw InputError(fmt::format("{}: expected {}, got '{}'", option, expected, text));
  return {parse_number(parts[0], option, expected), parse_number(parts[1], option, expected),
          parse_number(parts[2], option, expected)};
}

CameraOverrides camera_overrides(const RenderOptions& options) {
  CameraOverrides overrides;
  if (!options.camera_position.empty()) overrides.position_m = parse_point(options.camera_position, "--camera-position");
  if (!options.camera_target.empty()) overrides.target_m = parse_point(options.camera_target, "--camera-target");
  if (options.fov_deg != 0.0) {
    if (!(options.fov_deg > 0.0 && options.fov_deg < 180.0)) {
      throw InputError(fmt::format("--fov-deg: expected an angle in (0, 180) degrees, got {}", options.fov_deg));
    }
    overrides.fov_y_deg = options.fov_deg;
  }
  if (!options.size.empty()) {
    const std::string expected = "WxH (two whole numbers of pixels, 1 to 8192)";
    const auto parts = split(options.size, 'x');
    if (parts.size() != 2) throw InputError(fmt::format("--size: expected {}, got '{}'", expected, options.size));
    const double width = parse_number(parts[0], "--size", expected);
    const double height = parse_number(parts[1], "--size", expected);
    const auto valid = [](double v) { return v >= 1 && v <= 8192 && v == std::floor(v); };
    if (!valid(width) || !valid(height)) {
      throw InputError(fmt::format("--size: expected {}, got '{}'", expected, options.size));
    }
    overrides.width_px = static_cast<int>(width);
    overrides.height_px = static_cast<int>(height);
  }
  return overrides;
}

bool has_extension(const std::string& path, std::initializer_list<const char*> extensions) {
  const std::string extension = std::filesystem::path(path).extension().string();
  for (const char* e : extensions) {
    if (extension == e) return true;
  }
  return false;
}

// A height field from .npy, centred on the origin, nx columns over 1 m unless
// the cell size is given.
HeightField field_from_npy(const std::string& path, double cell_size_m) {
  ArrayXXdR heights = read_npy_2d(path);
  if (heights.size() == 0) throw InputError(fmt::format("{}: the array is empty", path));
  if (!heights.allFinite()) throw InputError(fmt::format("{}: the array holds NaN or infinite heights", path));
  Grid grid;
  grid.nx = static_cast<int>(heights.cols());
  grid.ny = static_cast<int>(heights.rows());
  grid.cell_size_m = cell_size_m > 0.0 ? cell_size_m : 1.0 / grid.nx;
  grid.origin_x_m = -0.5 * grid.extent_x_m();
  grid.origin_y_m = -0.5 * grid.extent_y_m();
  return HeightField(grid, std::move(heights));
}

// A debris run folder as a series PREFIX_NNN.png, framed by its own camera.
void render_debris(const RenderOptions& options, const CameraOverrides& overrides) {
  if (overrides.position_m || overrides.target_m || overrides.fov_y_deg || options.cell_size_m != 0.0) {
    throw InputError(
        "--camera-position, --camera-target, --fov-deg, --cell-size-m: not for a debris run folder "
        "(use --azimuth-deg, --elevation-deg)");
  }
  DebrisRenderOptions debris = options.debris;
  if (overrides.width_px) debris.width_px = *overrides.width_px;
  if (overrides.height_px) debris.height_px = *overrides.height_px;
  std::string prefix = options.image_path;
  prefix.resize(prefix.size() - 4);  // ".png"
  for (const std::string& path : write_debris_renders(options.input_path, prefix, debris)) fmt::print("{}\n", path);
}

void render(const RenderOptions& options, const SolverRegistry& registry) {
  const CameraOverrides overrides = camera_overrides(options);  // checked before anything is read
  if (!has_extension(options.image_path, {".png"})) {
    throw InputError(fmt::format("{}: expected an output file name ending in .png", options.image_path));
  }
  if (!has_extension(options.input_path, {".npy", ".yaml", ".yml"}) && std::filesystem::is_directory(options.input_path)) {
    render_debris(options, overrides);
    return;
  }
  if (options.cell_size_m < 0.0 || !std::isfinite(options.cell_size_m)) {
    throw InputError(fmt::format("--cell-size-m: expected a positive length in metres, got {}", options.cell_size_m));
  }
  if (has_extension(options.input_path, {".npy"})) {
    render_height_png(options.image_path, field_from_npy(options.input_path, options.cell_size_m), nullptr, 0.0,
                      overrides);
  } else if (has_extension(options.input_path, {".yaml", ".yml"})) {
    if (options.cell_size_m != 0.0) {
      throw InputError("--cell-size-m: only for .npy inputs; a scene gives its own cell size");
    }
    const Scene scene = load_scene(options.input_path, registry.sections());
    render_height_png(options.image_path, make_initial_height(scene), &scene, 0.0, overrides);
  } else {
    throw InputError(fmt::format("{}: expected a scene (.yaml, .yml), a height field (.npy) or a debris run folder",
                                 options.input_path));
  }
}

}  // namespace

void add_render_command(CLI::App& app, const SolverRegistry& registry) {
  CLI::App* command = app.add_subcommand("render", "Render a scene's initial ground or a .npy height field to PNG");
  auto options = std::make_shared<RenderOptions>();
  command->add_option("input", options->input_path,
                      "Scene file (.yaml), height field (.npy, metres) or debris run folder (frames/)")
      ->required();
  command->add_option("-o,--output", options->image_path, "Image to write (.png)")->required();
  command->add_option("--camera-position", options->camera_position, "Camera position x,y,z (m)");
  command->add_option("--camera-target", options->camera_target, "Point the camera looks at x,y,z (m)");
  command->add_option("--fov-deg", options->fov_deg, "Vertical field of view (degrees)");
  command->add_option("--size", options->size, "Image size WxH (pixels)");
  command->add_option("--cell-size-m", options->cell_size_m, ".npy only: cell size (m); default: the field is 1 m wide");
  command->add_option("--frames", options->debris.frames, "Debris run: frames drawn, first to last (PREFIX_NNN.png)");
  command->add_option("--azimuth-deg", options->debris.azimuth_deg, "Debris run: camera direction from +x towards +y");
  command->add_option("--elevation-deg", options->debris.elevation_deg, "Debris run: camera above the horizontal");
  command->callback([options, &registry] { render(*options, registry); });
}

}  // namespace repose::cli
