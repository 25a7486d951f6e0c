#include "models/core/config/scene_loader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include "models/core/io/input_file.h"
#include "models/core/io/mesh_io.h"
#include "models/core/io/npy_io.h"
#include "models/core/io/png_io.h"
#include "models/core/config/dynamic_body.h"
#include "models/core/config/fields.h"
#include "models/core/config/scene_fields.h"
#include "models/core/config/yaml_reader.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

constexpr double kDeg = kRadPerDeg;
constexpr int kSegments = 32;  // tessellation of round primitives

// ---- the pieces of a scene

struct Context {
  std::string file;      // as given, for messages
  fs::path directory;    // absolute folder of the scene file, for relative paths
};

std::string resolve(const Context& ctx, const std::string& path) {
  const fs::path p(path);
  return (p.is_absolute() ? p : ctx.directory / p).lexically_normal().string();
}

// A file named by a scene key: must exist and not be a folder.
std::string existing_file(const Context& ctx, const YamlValue& value, const std::string& what) {
  const std::string path = resolve(ctx, value.string());
  std::error_code ec;
  if (!fs::exists(path, ec)) value.fail(what, fmt::format("'{}', which does not exist ({})", value.string(), path));
  if (fs::is_directory(path, ec)) value.fail(what, fmt::format("'{}', which is a directory ({})", value.string(), path));
  return path;
}

// FILE:LINE:COL of a value, for rules checked later by a solver's section.
std::string location_of(const YamlValue& value) {
  return fmt::format("{}:{}:{}", value.file(), value.node().Mark().line + 1, value.node().Mark().column + 1);
}

Grid read_grid(const YamlMap& ground) {
  const Eigen::Vector2d extent = ground.vec2("extent_m", kLength);
  const auto cell_size = ground.get("cell_size_m");
  const auto resolution = ground.get("resolution");
  if (cell_size && resolution) resolution->fail("either cell_size_m or resolution, not both", "both");
  if (!cell_size && !resolution) ground.fail_missing("cell_size_m", "either cell_size_m or resolution");
  const std::string huge = fmt::format("at most {} cells per side and {} cells in all (memory)", kMaxCellsPerSide,
                                       static_cast<std::int64_t>(kMaxCells));
  Grid g;
  if (cell_size) {
    const double h = cell_size->number(Range::positive());
    const double nx = extent.x() / h, ny = extent.y() / h;
    if (nx > kMaxCellsPerSide + 0.5 || ny > kMaxCellsPerSide + 0.5 || nx * ny > kMaxCells) {
      cell_size->fail("a cell size giving " + huge, fmt::format("{} ({:.0f} x {:.0f} cells)", h, nx, ny));
    }
    g.nx = static_cast<int>(std::llround(nx));
    g.ny = static_cast<int>(std::llround(ny));
    if (g.nx < 1 || g.ny < 1 || std::abs(nx - g.nx) > 1e-6 || std::abs(ny - g.ny) > 1e-6) {
      cell_size->fail("a cell size that divides extent_m into whole cells", fmt::format("{} ({} x {} cells)", h, nx, ny));
    }
    g.cell_size_m = h;
  } else {
    const std::string what = "a list of 2 integers [nx, ny] in [1, " + std::to_string(kMaxCellsPerSide) + "]";
    if (!resolution->is_list() || resolution->node().size() != 2) resolution->fail(what);
    const auto items = resolution->list();
    const IntRange side{1, kMaxCellsPerSide};
    const auto nx = items[0].integer(side), ny = items[1].integer(side);
    if (static_cast<double>(nx) * static_cast<double>(ny) > kMaxCells) {
      resolution->fail("a resolution with " + huge, fmt::format("{} x {} cells", nx, ny));
    }
    g.nx = static_cast<int>(nx);
    g.ny = static_cast<int>(ny);
    g.cell_size_m = extent.x() / g.nx;
    const double hy = extent.y() / g.ny;
    if (std::abs(hy - g.cell_size_m) > 1e-9 * g.cell_size_m) {
      resolution->fail("square cells (extent_m[0] / nx == extent_m[1] / ny)",
                       fmt::format("[{}, {}], cells of {} x {} m", nx, ny, g.cell_size_m, hy));
    }
  }
  const Eigen::Vector2d origin = ground.get("origin_m") ? ground.vec2("origin_m", kCoordinate) : Eigen::Vector2d(-0.5 * extent);
  g.origin_x_m = origin.x();
  g.origin_y_m = origin.y();
  return g;
}

// The rows and columns a height file's header declares, read without decoding.
std::pair<std::uint64_t, std::uint64_t> declared_shape(const std::string& path, bool png) {
  if (png) {
    const PngSize size = read_png_size(path);
    return {size.height, size.width};
  }
  const NpyShape shape = read_npy_shape(path);
  return {shape.rows, shape.cols};
}

// Reads a height file now, so that a wrong shape or a bad value is reported
// against the scene key; make_initial_height reads it again. The shape is
// compared from the file's header first: a 0.5 MB PNG may declare 16384^2
// pixels (2.6 GB decoded).
void check_height_file(const YamlValue& path_value, const InitialHeight& init, const Grid& grid) {
  const bool png = fs::path(init.path).extension() == ".png";
  const std::pair<std::uint64_t, std::uint64_t> expected(grid.ny, grid.nx);
  std::pair<std::uint64_t, std::uint64_t> shape;
  ArrayXXdR a;
  try {
    shape = declared_shape(init.path, png);
    if (shape == expected) a = png ? read_png16(init.path, grid.ny, grid.nx) : read_npy_2d(init.path, grid.ny, grid.nx);
  } catch (const InputError& e) {
    path_value.fail(png ? "a readable 16-bit grey PNG" : "a readable .npy array", fmt::format("an error: {}", e.what()));
  }
  if (shape != expected) {
    path_value.fail(fmt::format("an array of {} rows x {} columns (the ground grid's ny x nx)", grid.ny, grid.nx),
                    fmt::format("{} x {} in {}", shape.first, shape.second, init.path));
  }
  if (!a.allFinite()) path_value.fail("finite heights", "a non-finite value in " + init.path);
  const double lowest = (png ? a * init.png_height_scale_m / 65535.0 : a).minCoeff() + init.height_m;
  if (lowest < 0.0) {
    path_value.fail("heights >= 0 (they are material amounts) after offset_m",
                    fmt::format("a lowest height of {} m in {}", lowest, init.path));
  }
}

InitialHeight read_initial_height(const Context& ctx, const YamlValue& value, const Grid& grid) {
  const std::vector<std::string> kinds = {"flat", "noise", "file"};
  const std::vector<std::vector<std::string>> keys = {
      {"kind", "height_m"},
      {"kind", "mean_m", "amplitude_m", "correlation_m"},
      {"kind", "path", "height_scale_m", "offset_m"}};
  // the allowed keys depend on the kind: read it first, then check the map against its kind
  const YamlMap any_kind = value.map({"kind", "height_m", "mean_m", "amplitude_m", "correlation_m", "path",
                                      "height_scale_m", "offset_m"});
  const std::size_t kind = any_kind.required("kind", "one of flat, noise, file").choice(kinds);
  const YamlMap map = value.map(keys[kind]);
  InitialHeight init;
  init.kind = static_cast<InitialHeight::Kind>(kind);
  if (init.kind == InitialHeight::Kind::kFlat) {
    init.height_m = map.number("height_m", kHeight);
  } else if (init.kind == InitialHeight::Kind::kNoise) {
    init.height_m = map.number("mean_m", kHeight);
    init.amplitude_m = map.number("amplitude_m", kHeight);
    if (init.amplitude_m > init.height_m) {
      map.get("amplitude_m")->fail(fmt::format("an amplitude <= mean_m ({}), so that heights stay >= 0", init.height_m));
    }
    init.correlation_m = map.number_or("correlation_m", kHeight, 0.0);
  } else {
    const YamlValue path = map.required("path", "a .npy or 16-bit .png file");
    init.path = existing_file(ctx, path, "a .npy or 16-bit .png height file");
    const std::string ext = fs::path(init.path).extension().string();
    if (ext != ".npy" && ext != ".png") path.fail("a .npy or .png file");
    init.height_m = map.number_or("offset_m", kCoordinate, 0.0);
    if (ext == ".png") {
      init.png_height_scale_m = map.number("height_scale_m", kLength);
    } else if (auto scale = map.get("height_scale_m")) {
      scale->fail("no height_scale_m for a .npy file (it holds metres)", scale->describe_got());
    }
    check_height_file(path, init, grid);
  }
  return init;
}

// [min, max] overlapping the ground's extent [lo, hi] along one axis.
Eigen::Vector2d read_range(const YamlMap& map, const std::string& key, double lo, double hi) {
  const Eigen::Vector2d r = map.vec2(key, kCoordinate);
  const std::string what = fmt::format("a range [min, max], min < max, overlapping the ground's [{}, {}]", lo, hi);
  if (!(r[0] < r[1]) || r[1] <= lo || r[0] >= hi) map.get(key)->fail(what, fmt::format("[{}, {}]", r[0], r[1]));
  return r;
}

std::vector<MaterialRegion> read_regions(const YamlValue& value, const Grid& g) {
  std::vector<MaterialRegion> regions;
  for (const YamlValue& item : value.list()) {
    const YamlMap map = item.map({"material", "x_range_m", "y_range_m"});
    MaterialRegion r;
    const YamlValue material = map.required("material", "a material name (a preset: sand, mud, snow, or one defined by a solver's section)");
    r.material = material.string();
    r.location = location_of(material);
    const Eigen::Vector2d x = read_range(map, "x_range_m", g.origin_x_m, g.origin_x_m + g.extent_x_m());
    const Eigen::Vector2d y = read_range(map, "y_range_m", g.origin_y_m, g.origin_y_m + g.extent_y_m());
    r.x_min_m = x[0];
    r.x_max_m = x[1];
    r.y_min_m = y[0];
    r.y_max_m = y[1];
    regions.push_back(r);
  }
  return regions;
}

GroundSpec read_ground(const Context& ctx, const YamlValue& value) {
  const YamlMap map =
      value.map({"extent_m", "cell_size_m", "resolution", "origin_m", "initial_height", "material", "regions"});
  GroundSpec g;
  g.grid = read_grid(map);
  g.initial = read_initial_height(ctx, map.required("initial_height", "a map with a kind"), g.grid);
  if (auto m = map.get("material")) {
    g.material = m->string();
    g.material_location = location_of(*m);
  }
  if (auto r = map.get("regions")) g.regions = read_regions(*r, g.grid);
  return g;
}

std::vector<Keyframe> read_motion(const YamlValue& value) {
  std::vector<Keyframe> keys;
  for (const YamlValue& item : value.list(1)) {
    const YamlMap map = item.map({"time_s", "position_m", "orientation_deg"});
    Keyframe k;
    k.time_s = map.number("time_s", Range::non_negative());
    if (!keys.empty() && !(k.time_s > keys.back().time_s)) {
      map.get("time_s")->fail(fmt::format("a time > {} s (the previous keyframe's: times must increase)", keys.back().time_s));
    }
    k.pose.position_m = map.vec3("position_m", kCoordinate);
    k.pose.orientation = orientation_from_rpy_deg(map.vec3_or("orientation_deg", Range::closed(-3600.0, 3600.0), Eigen::Vector3d::Zero()));
    keys.push_back(k);
  }
  return keys;
}

// A free body's dynamic: map (dynamic_body.h); its initial pose becomes the one keyframe.
DynamicBody read_dynamic(const YamlValue& value) {
  const YamlMap map = value.map(field_keys<DynamicBody>(kDynamicBodyFields));
  map.required("position_m", "the initial position [x, y, z] of the free body");
  DynamicBody d;
  read_fields_into(map, kDynamicBodyFields, d);
  validate_at(map, [&] { validate(d); });
  return d;
}

// Either motion (keyframes) or dynamic (a free body), never both.
void read_object_motion(const YamlMap& map, ObjectSpec& o) {
  const auto motion = map.get("motion");
  const auto dynamic = map.get("dynamic");
  if (motion && dynamic) dynamic->fail("either motion (keyframes) or dynamic (a free body), not both", "both");
  if (!dynamic) {
    o.keyframes = read_motion(map.required("motion", "a list of keyframes {time_s, position_m, orientation_deg} (or dynamic: for a free body)"));
    return;
  }
  o.dynamic = read_dynamic(*dynamic);
  o.keyframes = {Keyframe{0.0, Pose{o.dynamic->position_m, orientation_from_rpy_deg(o.dynamic->orientation_deg)}}};
  const double volume = o.volume_m3();
  if (!(volume > 0.0) || !std::isfinite(o.mass_kg())) {
    dynamic->fail("a body of positive volume and finite mass", fmt::format("volume {} m^3, mass {} kg", volume, o.mass_kg()));
  }
}

Eigen::Vector3d read_scale(const YamlValue& value) {
  const Range scale = Range::left_open(0.0, 1.0e6);
  if (value.is_scalar()) return Eigen::Vector3d::Constant(value.number(scale));
  if (value.is_list()) return value.vec3(scale);
  value.fail(scale.describe() + " or " + describe_list_of(3, scale));
}

TriangleMesh read_closed_mesh(const YamlValue& value, const std::string& path) {
  TriangleMesh mesh;
  try {
    mesh = read_mesh(path);
  } catch (const InputError& e) {
    value.fail("a readable OBJ or STL mesh", fmt::format("an error: {}", e.what()));
  }
  const std::string closed = "a closed, outward-oriented triangle mesh (every edge shared by two faces)";
  if (mesh.empty()) value.fail(closed, "an empty mesh (no faces) in " + path);
  if (!is_closed_manifold(mesh)) value.fail(closed, "an open or non-manifold mesh in " + path);
  if (signed_volume_m3(mesh) <= 0.0) value.fail(closed, "an inside-out mesh (negative volume) in " + path);
  return mesh;
}

ObjectSpec read_object(const Context& ctx, const YamlValue& value, std::size_t index) {
  using S = ObjectSpec::Shape;
  const std::vector<std::string> shapes = {"sphere", "box", "cylinder", "capsule", "mesh"};
  const std::vector<std::string> common = {"name", "shape", "scale", "simple", "motion", "dynamic"};
  const std::vector<std::vector<std::string>> shape_keys = {
      {"radius_m"}, {"half_extents_m", "size_m"}, {"radius_m", "half_height_m"}, {"radius_m", "half_height_m"}, {"mesh"}};
  std::vector<std::string> all = common;
  for (const char* k : {"radius_m", "half_height_m", "half_extents_m", "size_m", "mesh"}) all.emplace_back(k);
  const std::size_t shape = value.map(all).required("shape", "one of sphere, box, cylinder, capsule, mesh").choice(shapes);
  std::vector<std::string> allowed = common;
  allowed.insert(allowed.end(), shape_keys[shape].begin(), shape_keys[shape].end());
  const YamlMap map = value.map(allowed);

  ObjectSpec o;
  o.shape = static_cast<S>(shape);
  o.name = map.string_or("name", fmt::format("object_{}", index));
  switch (o.shape) {
    case S::kSphere:
      o.radius_m = map.number("radius_m", kLength);
      o.body = make_sphere(o.radius_m, kSegments);
      break;
    case S::kBox: {
      const auto half = map.get("half_extents_m");
      const auto size = map.get("size_m");
      if (half && size) size->fail("either half_extents_m or size_m, not both", "both");
      if (!half && !size) map.fail_missing("half_extents_m", "either half_extents_m or size_m");
      o.half_extents_m = half ? half->vec3(kLength) : Eigen::Vector3d(0.5 * size->vec3(kLength));
      o.body = make_box(o.half_extents_m);
      break;
    }
    case S::kCylinder:
      o.radius_m = map.number("radius_m", kLength);
      o.half_height_m = map.number("half_height_m", kLength);
      o.body = make_cylinder(o.radius_m, o.half_height_m, kSegments);
      break;
    case S::kCapsule:
      o.radius_m = map.number("radius_m", kLength);
      o.half_height_m = map.number("half_height_m", kHeight);
      o.body = make_capsule(o.radius_m, o.half_height_m, kSegments);
      break;
    case S::kMesh: {
      const YamlValue mesh = map.required("mesh", "a path to an OBJ or STL file");
      o.mesh_path = existing_file(ctx, mesh, "an OBJ or STL mesh file");
      o.body = read_closed_mesh(mesh, o.mesh_path);
      break;
    }
  }
  if (auto s = map.get("scale")) o.scale = read_scale(*s);
  o.body = scaled(o.body, o.scale);
  const double reach = o.body.V.size() > 0 ? o.body.V.cwiseAbs().maxCoeff() : 0.0;
  if (!(reach <= kMaxLength_m)) {
    (map.get("scale") ? *map.get("scale") : value)
        .fail(fmt::format("a body within {} m of its origin after scaling", kMaxLength_m),
              fmt::format("a body reaching {} m", reach));
  }
  o.simple = map.boolean_or("simple", false);
  read_object_motion(map, o);
  return o;
}

TimeSpec read_time(const YamlValue& value) {
  const YamlMap map = value.map(field_keys<TimeSpec>(kTimeFields));
  TimeSpec t;
  FieldReader reader(map);
  time_fields(reader, t);
  if (t.step_s > t.duration_s) map.get("step_s")->fail(fmt::format("a step <= duration_s ({} s)", t.duration_s));
  if (t.duration_s / t.step_s > kMaxSteps) {
    map.get("step_s")->fail(fmt::format("a step giving at most {:.0f} steps", kMaxSteps),
                            fmt::format("{} ({:.0f} steps)", t.step_s, t.duration_s / t.step_s));
  }
  return t;
}

CameraSpec read_camera(const YamlValue& value) {
  const YamlMap map = value.map(field_keys<CameraSpec>(kCameraFields));
  CameraSpec c;
  FieldReader reader(map);
  camera_fields(reader, c);
  const Eigen::Vector3d view = c.target_m - c.position_m;
  if (view.norm() == 0.0) value.fail("target_m different from position_m", "the same point");
  if (c.up.norm() == 0.0 || view.normalized().cross(c.up.normalized()).norm() < 1e-6) {
    value.fail("an up vector not parallel to the view direction", fmt::format("up [{}, {}, {}]", c.up[0], c.up[1], c.up[2]));
  }
  return c;
}

// What a run of the scene will hold, estimated before anything is allocated
// for it: the ground as about eight grids of doubles (heights, scratch
// copies, depth images, erosion memory), each body about three times (its
// mesh, the world copy, the swept copy), the camera's render at supersample 2.
void require_scene_memory(const Scene& s) {
  namespace est = memory_estimate;
  const Grid& g = s.ground.grid;
  std::uint64_t triangles = 0;
  for (const ObjectSpec& o : s.objects) triangles = est::sum(triangles, static_cast<std::uint64_t>(o.body.F.rows()));
  std::uint64_t bytes = est::sum(est::grid_bytes(static_cast<std::uint64_t>(g.nx), static_cast<std::uint64_t>(g.ny), 8),
                                 est::product(3, est::triangle_mesh_bytes(triangles)));
  if (s.camera) {
    bytes = est::sum(bytes, est::image_bytes(2 * static_cast<std::uint64_t>(s.camera->width_px),
                                             2 * static_cast<std::uint64_t>(s.camera->height_px), 16));
  }
  require_memory(bytes, fmt::format("{}: the scene ({} x {} cells, {} objects of {} triangles)", s.source_path, g.nx,
                                    g.ny, s.objects.size(), triangles));
}

const std::vector<std::string> kCommonKeys = {"name", "seed", "time", "ground", "objects", "camera"};

// Object names key per-object results: they must be unique.
void check_unique_names(const std::vector<ObjectSpec>& objects, const YamlValue& list) {
  const auto items = list.list();
  for (std::size_t k = 0; k < objects.size(); ++k) {
    for (std::size_t j = 0; j < k; ++j) {
      if (objects[j].name == objects[k].name) {
        items[k].fail(fmt::format("an object name used once (objects[{}] is also '{}')", j, objects[k].name),
                      "'" + objects[k].name + "'");
      }
    }
  }
}

// The sections: every key the scene has that a solver reads, and the
// sections read even when absent.
void read_sections(const YamlMap& map, const SectionTypes& sections, Scene& s) {
  for (const SectionType& type : sections) {
    const auto value = map.get(type.key);
    if (!value && !type.read_when_absent) continue;
    const YamlValue v = value ? *value : YamlValue(map.self().file(), YAML::Node(YAML::NodeType::Null), type.key);
    s.sections[type.key] = type.read(v, s);
  }
}

Scene read_scene(const Context& ctx, const YamlValue& root, const SectionTypes& sections) {
  std::vector<std::string> top = kCommonKeys;
  for (const SectionType& type : sections) top.push_back(type.key);
  if (!root.node().IsDefined() || root.node().IsNull()) root.fail("a map with the keys " + fmt::format("{}", fmt::join(top, ", ")), "an empty document");
  const YamlMap map = root.map(top);
  Scene s;
  s.source_path = (ctx.directory / fs::path(ctx.file).filename()).string();
  s.name = map.string_or("name", fs::path(ctx.file).stem().string());
  if (auto seed = map.get("seed")) s.seed = seed->unsigned_integer();
  s.time = read_time(map.required("time", "a map {step_s, duration_s}"));
  s.ground = read_ground(ctx, map.required("ground", "a map with extent_m, cell_size_m or resolution, initial_height"));
  if (auto objects = map.get("objects")) {
    const auto items = objects->list();
    for (std::size_t k = 0; k < items.size(); ++k) {
      s.objects.push_back(read_object(ctx, items[k], k));
      require_scene_memory(s);  // as the bodies are made, not after: 50,000 spheres would not fit
    }
    check_unique_names(s.objects, *objects);
  }
  if (auto c = map.get("camera")) s.camera = read_camera(*c);
  require_scene_memory(s);
  read_sections(map, sections, s);
  return s;
}

}  // namespace

Eigen::Quaterniond orientation_from_rpy_deg(const Eigen::Vector3d& rpy) {
  return (Eigen::AngleAxisd(rpy[2] * kDeg, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy[1] * kDeg, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy[0] * kDeg, Eigen::Vector3d::UnitX()))
      .normalized();
}

Eigen::Vector3d rpy_deg_from_orientation(const Eigen::Quaterniond& q) {
  const Eigen::Matrix3d R = q.normalized().toRotationMatrix();
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  double roll = 0.0, yaw = 0.0;
  if (std::abs(R(2, 0)) < 1.0 - 1e-12) {
    roll = std::atan2(R(2, 1), R(2, 2));
    yaw = std::atan2(R(1, 0), R(0, 0));
  } else {  // gimbal lock: put all of the remaining turn into yaw
    yaw = std::atan2(-R(0, 1), R(1, 1));
  }
  return Eigen::Vector3d(roll, pitch, yaw) / kDeg;
}

Scene load_scene_from_string(const std::string& yaml, const std::string& pretend_path, const SectionTypes& sections) {
  Context ctx{pretend_path, fs::absolute(fs::path(pretend_path)).parent_path().lexically_normal()};
  return read_scene(ctx, parse_yaml(yaml, pretend_path), sections);
}

Scene load_scene_from_node(const YAML::Node& root, const std::string& path, const SectionTypes& sections) {
  Context ctx{path, fs::absolute(fs::path(path)).parent_path().lexically_normal()};
  return read_scene(ctx, YamlValue(path, root, ""), sections);
}

Scene load_scene(const std::string& path, const SectionTypes& sections) {
  return load_scene_from_string(read_input_file(path, input_kind::kScene), path, sections);
}

}  // namespace repose
