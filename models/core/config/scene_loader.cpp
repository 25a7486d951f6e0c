#include "models/core/config/scene_loader.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/io/input_file.h"
#include "models/core/io/mesh_io.h"
#include "models/core/io/npy_io.h"
#include "models/core/io/png_io.h"
#include "models/core/config/yaml_reader.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

constexpr double kDeg = std::numbers::pi / 180.0;
// Limits that keep a typo from exhausting memory or time.
constexpr std::int64_t kMaxCellsPerSide = 16384;
constexpr double kMaxCells = 67108864.0;  // 2^26
constexpr double kMaxSteps = 1.0e7;
constexpr int kSegments = 32;  // tessellation of round primitives
// Lengths and coordinates stay within 1000 km, so that products of them stay
// finite in every model downstream.
constexpr double kMaxLength_m = 1.0e6;
const Range kLength = Range::left_open(0.0, kMaxLength_m);        // a size > 0
const Range kCoordinate = Range::closed(-kMaxLength_m, kMaxLength_m);
const Range kHeight = Range::closed(0.0, kMaxLength_m);           // an amount >= 0

enum class Need { kOptional, kRequired };

// ---- one field list per options struct, driving reading, writing and the allowed keys

// Collects the key names of a field list.
class FieldNames {
 public:
  std::vector<std::string> names;
  void number(const char* key, double&, const Range&, Need = Need::kOptional) { names.emplace_back(key); }
  void angle_deg(const char* key, double&, const Range&, Need = Need::kOptional) { names.emplace_back(key); }
  void integer(const char* key, int&, const IntRange&, Need = Need::kOptional) { names.emplace_back(key); }
  void boolean(const char* key, bool&) { names.emplace_back(key); }
  void vec3(const char* key, Eigen::Vector3d&, const Range&) { names.emplace_back(key); }
  template <class E>
  void choice(const char* key, E&, const std::vector<std::pair<std::string, E>>&) {
    names.emplace_back(key);
  }
};

// Reads the fields present in a map; absent optional fields keep their value.
class FieldReader {
 public:
  explicit FieldReader(const YamlMap& map) : map_(map) {}
  void number(const char* key, double& x, const Range& r, Need need = Need::kOptional) {
    if (auto v = value(key, r.describe(), need)) x = v->number(r);
  }
  void angle_deg(const char* key, double& rad, const Range& deg, Need need = Need::kOptional) {
    if (auto v = value(key, deg.describe(), need)) rad = v->number(deg) * kDeg;
  }
  void integer(const char* key, int& x, const IntRange& r, Need need = Need::kOptional) {
    if (auto v = value(key, r.describe(), need)) x = static_cast<int>(v->integer(r));
  }
  void boolean(const char* key, bool& b) {
    if (auto v = map_.get(key)) b = v->boolean();
  }
  void vec3(const char* key, Eigen::Vector3d& x, const Range& r) {
    if (auto v = map_.get(key)) x = v->vec3(r);
  }
  template <class E>
  void choice(const char* key, E& e, const std::vector<std::pair<std::string, E>>& table) {
    auto v = map_.get(key);
    if (!v) return;
    std::vector<std::string> words;
    for (const auto& [word, value] : table) words.push_back(word);
    e = table[v->choice(words)].second;
  }

 private:
  std::optional<YamlValue> value(const char* key, const std::string& expected, Need need) {
    return need == Need::kRequired ? std::optional<YamlValue>(map_.required(key, expected)) : map_.get(key);
  }
  const YamlMap& map_;
};

// Numbers as text for the emitter: the shortest form that reads back to the
// same double, and angles in degrees to 15 digits (so that 30 deg reads 30).
std::string num(double x) { return fmt::format("{}", x + 0.0); }  // + 0.0: no "-0"
std::string deg(double degrees) { return fmt::format("{:.15g}", degrees + 0.0); }

// Writes every field (angles in degrees).
class FieldWriter {
 public:
  explicit FieldWriter(YAML::Emitter& out) : out_(out) {}
  void number(const char* key, double& x, const Range&, Need = Need::kOptional) {
    out_ << YAML::Key << key << YAML::Value << num(x);
  }
  void angle_deg(const char* key, double& rad, const Range&, Need = Need::kOptional) {
    out_ << YAML::Key << key << YAML::Value << deg(rad / kDeg);
  }
  void integer(const char* key, int& x, const IntRange&, Need = Need::kOptional) { out_ << YAML::Key << key << YAML::Value << x; }
  void boolean(const char* key, bool& b) { out_ << YAML::Key << key << YAML::Value << b; }
  void vec3(const char* key, Eigen::Vector3d& x, const Range&) {
    out_ << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq << num(x[0]) << num(x[1]) << num(x[2]) << YAML::EndSeq;
  }
  template <class E>
  void choice(const char* key, E& e, const std::vector<std::pair<std::string, E>>& table) {
    for (const auto& [word, value] : table) {
      if (value == e) out_ << YAML::Key << key << YAML::Value << word;
    }
  }

 private:
  YAML::Emitter& out_;
};

template <class Visitor>
void time_fields(Visitor& v, TimeSpec& t) {
  v.number("step_s", t.step_s, Range::positive(), Need::kRequired);
  v.number("duration_s", t.duration_s, Range::positive(), Need::kRequired);
}

template <class Visitor>
void material_fields(Visitor& v, Material& m) {
  v.number("alpha", m.alpha, Range::closed(0.0, 1.0));
  v.angle_deg("repose_angle_deg", m.repose_angle_rad, Range::left_open(0.0, 90.0));
  v.number("sigma", m.sigma, Range::left_open(0.0, kSigmaMax));
  v.integer("erosion_iterations", m.erosion_iterations, IntRange{1, 1000});
}

template <class Visitor>
void camera_fields(Visitor& v, CameraSpec& c) {
  v.vec3("position_m", c.position_m, kCoordinate);
  v.vec3("target_m", c.target_m, kCoordinate);
  v.vec3("up", c.up, Range::closed(-1.0, 1.0));
  v.angle_deg("fov_y_deg", c.fov_y_rad, Range::open(0.0, 180.0));
  v.integer("width_px", c.width_px, IntRange{1, kMaxCellsPerSide});
  v.integer("height_px", c.height_px, IntRange{1, kMaxCellsPerSide});
}

template <class Visitor>
void ground_model_fields(Visitor& v, GroundModelSpec& g) {
  v.boolean("sweep", g.sweep);
  v.integer("substeps", g.substeps, IntRange{1, 10000});
  v.angle_deg("max_substep_angle_deg", g.max_substep_angle_rad, Range::left_open(0.0, 180.0));
  v.integer("erosion_memory_steps", g.erosion_memory_steps, IntRange{0, 1000000});
  v.integer("coarse_factor", g.coarse_factor, IntRange{1, 64});
  v.number("far_distance_m", g.far_distance_m, kHeight);
  using C = GroundModelSpec::Collision;
  v.choice("collision", g.collision, std::vector<std::pair<std::string, C>>{{"cpu", C::kCpu}, {"osmesa", C::kOsmesa}});
}

template <class Visitor>
void dem_fields(Visitor& v, DemSpec& d) {
  v.number("grain_radius_m", d.grain_radius_m, Range::positive());
  v.number("radius_spread", d.radius_spread, Range::right_open(0.0, 0.5));
  v.number("density_kg_m3", d.density_kg_m3, Range::positive());
  v.number("youngs_modulus_pa", d.youngs_modulus_pa, Range::positive());
  v.number("poisson_ratio", d.poisson_ratio, Range::right_open(0.0, 0.5));
  v.number("restitution", d.restitution, Range::left_open(0.0, 1.0));
  v.number("friction", d.friction, Range::non_negative());
  v.number("rolling_friction", d.rolling_friction, Range::non_negative());
  using R = DemSpec::RollingModel;
  v.choice("rolling_model", d.rolling_model, std::vector<std::pair<std::string, R>>{{"cdt", R::kCdt}, {"epsd2", R::kEpsd2}});
  v.number("cohesion_energy_density_j_m3", d.cohesion_energy_density_j_m3, Range::non_negative());
  v.number("time_step_s", d.time_step_s, Range::positive());
  v.number("bed_depth_m", d.bed_depth_m, Range::positive());
  v.number("settle_kinetic_energy_j", d.settle_kinetic_energy_j, Range::positive());
  v.number("gravity_m_s2", d.gravity_m_s2, Range::positive());
  v.number("dump_interval_s", d.dump_interval_s, Range::positive());
  using I = DemSpec::Initial;
  v.choice("initial", d.initial, std::vector<std::pair<std::string, I>>{{"bed", I::kBed}, {"column", I::kColumn}});
  using C = DemSpec::ColumnShape;
  v.choice("column_shape", d.column_shape,
           std::vector<std::pair<std::string, C>>{{"slot", C::kSlot}, {"cylinder", C::kCylinder}});
  v.number("column_width_m", d.column_width_m, Range::positive());
  v.number("column_height_m", d.column_height_m, Range::positive());
  using F = DemSpec::Floor;
  v.choice("floor", d.floor, std::vector<std::pair<std::string, F>>{{"smooth", F::kSmooth}, {"rough", F::kRough}});
  v.number("floor_rolling_friction", d.floor_rolling_friction, Range::non_negative());
}

// The field lists as values, so that one list can be handed to readers and writers.
const auto kTimeFields = [](auto& v, TimeSpec& x) { time_fields(v, x); };
const auto kMaterialFields = [](auto& v, Material& x) { material_fields(v, x); };
const auto kCameraFields = [](auto& v, CameraSpec& x) { camera_fields(v, x); };
const auto kGroundModelFields = [](auto& v, GroundModelSpec& x) { ground_model_fields(v, x); };
const auto kDemFields = [](auto& v, DemSpec& x) { dem_fields(v, x); };

// The keys of a field list, plus extra ones read by hand.
template <class Spec, class Fields>
std::vector<std::string> keys_of(Fields fields, std::vector<std::string> extra = {}) {
  FieldNames names;
  Spec spec;
  fields(names, spec);
  extra.insert(extra.end(), names.names.begin(), names.names.end());
  return extra;
}

// Reads a map that holds exactly one field list.
template <class Spec, class Fields>
Spec read_fields(const YamlValue& value, Fields fields, Spec spec = Spec{}) {
  const YamlMap map = value.map(keys_of<Spec>(fields));
  FieldReader reader(map);
  fields(reader, spec);
  return spec;
}

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

Material read_material(const YamlValue& value) {
  const std::string presets = "sand, mud, snow";
  Material m;
  if (value.is_scalar()) {
    if (!material_preset(value.string(), &m)) value.fail("a material preset (one of " + presets + ") or a map");
    return m;
  }
  const YamlMap map = value.map(keys_of<Material>(kMaterialFields, {"preset", "name"}));
  if (auto preset = map.get("preset")) {
    if (!material_preset(preset->string(), &m)) preset->fail("a material preset (one of " + presets + ")");
  } else {
    // fully explicit: every parameter of the paper must be given
    for (const char* key : {"alpha", "repose_angle_deg", "sigma"}) {
      if (!map.has(key)) map.fail_missing(key, "a value for every parameter when no preset is given");
    }
    m.name = "custom";
  }
  FieldReader reader(map);
  material_fields(reader, m);
  m.name = map.string_or("name", m.name);
  return m;
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

// Reads a height file now, so that a wrong shape or a bad value is reported
// against the scene key; make_initial_height reads it again.
void check_height_file(const YamlValue& path_value, const InitialHeight& init, const Grid& grid) {
  const bool png = fs::path(init.path).extension() == ".png";
  ArrayXXdR a;
  try {
    a = png ? read_png16(init.path) : read_npy_2d(init.path);
  } catch (const InputError& e) {
    path_value.fail(png ? "a readable 16-bit grey PNG" : "a readable .npy array", fmt::format("an error: {}", e.what()));
  }
  if (a.rows() != grid.ny || a.cols() != grid.nx) {
    path_value.fail(fmt::format("an array of {} rows x {} columns (the ground grid's ny x nx)", grid.ny, grid.nx),
                    fmt::format("{} x {} in {}", a.rows(), a.cols(), init.path));
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
    r.material = read_material(map.required("material", "a material preset or map"));
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
  if (auto m = map.get("material")) g.material = read_material(*m);
  else material_preset("sand", &g.material);
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
  const std::vector<std::string> common = {"name", "shape", "scale", "simple", "motion"};
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
  o.simple = map.boolean_or("simple", false);
  o.keyframes = read_motion(map.required("motion", "a list of keyframes {time_s, position_m, orientation_deg}"));
  return o;
}

TimeSpec read_time(const YamlValue& value) {
  const YamlMap map = value.map(keys_of<TimeSpec>(kTimeFields));
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
  const YamlMap map = value.map(keys_of<CameraSpec>(kCameraFields));
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

// Rayleigh time of the smallest grain: DEM practice keeps the step well below it.
double rayleigh_time_s(const DemSpec& d) {
  const double r_min = d.grain_radius_m * (1.0 - d.radius_spread);
  const double shear_modulus = d.youngs_modulus_pa / (2.0 * (1.0 + d.poisson_ratio));
  return std::numbers::pi * r_min * std::sqrt(d.density_kg_m3 / shear_modulus) / (0.1631 * d.poisson_ratio + 0.8766);
}

DemSpec read_dem(const YamlValue& value) {
  const YamlMap map = value.map(keys_of<DemSpec>(kDemFields));
  DemSpec d;
  FieldReader reader(map);
  dem_fields(reader, d);
  const double limit = 0.2 * rayleigh_time_s(d);
  if (d.time_step_s > limit) {
    const auto at = map.get("time_step_s");
    const std::string what = fmt::format("a time step <= 20 % of the Rayleigh time ({:.3g} s)", limit);
    if (at) at->fail(what);
    map.fail_missing("time_step_s", what);  // the default is too large for these grains
  }
  return d;
}

Scene read_scene(const Context& ctx, const YamlValue& root) {
  const std::vector<std::string> top = {"name", "seed", "time", "ground", "objects", "camera", "ground_model", "dem"};
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
    for (std::size_t k = 0; k < items.size(); ++k) s.objects.push_back(read_object(ctx, items[k], k));
  }
  if (auto c = map.get("camera")) s.camera = read_camera(*c);
  if (auto g = map.get("ground_model")) s.ground_model = read_fields<GroundModelSpec>(*g, kGroundModelFields);
  if (auto d = map.get("dem")) s.dem = read_dem(*d);
  return s;
}

// ---- writing

void write_vec(YAML::Emitter& out, const char* key, const Eigen::VectorXd& v, bool degrees = false) {
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (Eigen::Index k = 0; k < v.size(); ++k) out << (degrees ? deg(v[k]) : num(v[k]));
  out << YAML::EndSeq;
}

void write_material(YAML::Emitter& out, Material m) {
  out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << m.name;
  FieldWriter writer(out);
  material_fields(writer, m);
  out << YAML::EndMap;
}

void write_initial_height(YAML::Emitter& out, const InitialHeight& init) {
  out << YAML::BeginMap;
  switch (init.kind) {
    case InitialHeight::Kind::kFlat:
      out << YAML::Key << "kind" << YAML::Value << "flat" << YAML::Key << "height_m" << YAML::Value << num(init.height_m);
      break;
    case InitialHeight::Kind::kNoise:
      out << YAML::Key << "kind" << YAML::Value << "noise" << YAML::Key << "mean_m" << YAML::Value << num(init.height_m)
          << YAML::Key << "amplitude_m" << YAML::Value << num(init.amplitude_m) << YAML::Key << "correlation_m"
          << YAML::Value << num(init.correlation_m);
      break;
    case InitialHeight::Kind::kFile:
      out << YAML::Key << "kind" << YAML::Value << "file" << YAML::Key << "path" << YAML::Value << init.path
          << YAML::Key << "offset_m" << YAML::Value << num(init.height_m);
      if (fs::path(init.path).extension() == ".png") {
        out << YAML::Key << "height_scale_m" << YAML::Value << num(init.png_height_scale_m);
      }
      break;
  }
  out << YAML::EndMap;
}

void write_object(YAML::Emitter& out, const ObjectSpec& o) {
  static const char* names[] = {"sphere", "box", "cylinder", "capsule", "mesh"};
  out << YAML::BeginMap << YAML::Key << "name" << YAML::Value << o.name;
  out << YAML::Key << "shape" << YAML::Value << names[static_cast<int>(o.shape)];
  switch (o.shape) {
    case ObjectSpec::Shape::kSphere:
      out << YAML::Key << "radius_m" << YAML::Value << num(o.radius_m);
      break;
    case ObjectSpec::Shape::kBox:
      write_vec(out, "half_extents_m", o.half_extents_m);
      break;
    case ObjectSpec::Shape::kCylinder:
    case ObjectSpec::Shape::kCapsule:
      out << YAML::Key << "radius_m" << YAML::Value << num(o.radius_m) << YAML::Key << "half_height_m" << YAML::Value
          << num(o.half_height_m);
      break;
    case ObjectSpec::Shape::kMesh:
      out << YAML::Key << "mesh" << YAML::Value << o.mesh_path;
      break;
  }
  write_vec(out, "scale", o.scale);
  out << YAML::Key << "simple" << YAML::Value << o.simple;
  out << YAML::Key << "motion" << YAML::Value << YAML::BeginSeq;
  for (const Keyframe& k : o.keyframes) {
    out << YAML::Flow << YAML::BeginMap << YAML::Key << "time_s" << YAML::Value << num(k.time_s);
    write_vec(out, "position_m", k.pose.position_m);
    write_vec(out, "orientation_deg", rpy_deg_from_orientation(k.pose.orientation), true);
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
}

template <class Spec, class Fields>
void write_fields(YAML::Emitter& out, const char* key, Spec spec, Fields fields) {
  out << YAML::Key << key << YAML::Value << YAML::BeginMap;
  FieldWriter writer(out);
  fields(writer, spec);
  out << YAML::EndMap;
}

std::string shape_summary(const ObjectSpec& o) {
  switch (o.shape) {
    case ObjectSpec::Shape::kSphere: return fmt::format("sphere r {} m", o.radius_m);
    case ObjectSpec::Shape::kBox:
      return fmt::format("box {} x {} x {} m", 2 * o.half_extents_m.x(), 2 * o.half_extents_m.y(), 2 * o.half_extents_m.z());
    case ObjectSpec::Shape::kCylinder: return fmt::format("cylinder r {} m, h {} m", o.radius_m, 2 * o.half_height_m);
    case ObjectSpec::Shape::kCapsule: return fmt::format("capsule r {} m, straight part {} m", o.radius_m, 2 * o.half_height_m);
    case ObjectSpec::Shape::kMesh: return fmt::format("mesh {}", o.mesh_path);
  }
  return "";
}

std::string initial_summary(const InitialHeight& i) {
  switch (i.kind) {
    case InitialHeight::Kind::kFlat: return fmt::format("flat {} m", i.height_m);
    case InitialHeight::Kind::kNoise:
      return fmt::format("noise {} m +- {} m, correlation {} m", i.height_m, i.amplitude_m, i.correlation_m);
    case InitialHeight::Kind::kFile: return fmt::format("from {} (offset {} m)", i.path, i.height_m);
  }
  return "";
}

std::string material_summary(const Material& m) {
  return fmt::format("{} (alpha {}, repose angle {:.6g} deg, sigma {}, {} erosion iterations)", m.name, m.alpha,
                     m.repose_angle_rad / kDeg, m.sigma, m.erosion_iterations);
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

Scene load_scene_from_string(const std::string& yaml, const std::string& pretend_path) {
  Context ctx{pretend_path, fs::absolute(fs::path(pretend_path)).parent_path().lexically_normal()};
  return read_scene(ctx, parse_yaml(yaml, pretend_path));
}

Scene load_scene_from_node(const YAML::Node& root, const std::string& path) {
  Context ctx{path, fs::absolute(fs::path(path)).parent_path().lexically_normal()};
  return read_scene(ctx, YamlValue(path, root, ""));
}

Scene load_scene(const std::string& path) {
  require_regular_file(path, "scene");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  return load_scene_from_string(text.str(), path);
}

void write_scene_yaml(const Scene& s, YAML::Emitter& out) {
  out << YAML::BeginMap;
  out << YAML::Key << "name" << YAML::Value << s.name;
  out << YAML::Key << "seed" << YAML::Value << s.seed;
  write_fields(out, "time", s.time, kTimeFields);
  const Grid& g = s.ground.grid;
  out << YAML::Key << "ground" << YAML::Value << YAML::BeginMap;
  write_vec(out, "extent_m", Eigen::Vector2d(g.extent_x_m(), g.extent_y_m()));
  out << YAML::Key << "resolution" << YAML::Value << YAML::Flow << YAML::BeginSeq << g.nx << g.ny << YAML::EndSeq;
  write_vec(out, "origin_m", Eigen::Vector2d(g.origin_x_m, g.origin_y_m));
  out << YAML::Key << "initial_height" << YAML::Value;
  write_initial_height(out, s.ground.initial);
  out << YAML::Key << "material" << YAML::Value;
  write_material(out, s.ground.material);
  out << YAML::Key << "regions" << YAML::Value;
  if (s.ground.regions.empty()) out << YAML::Flow;
  out << YAML::BeginSeq;
  for (const MaterialRegion& r : s.ground.regions) {
    out << YAML::BeginMap << YAML::Key << "material" << YAML::Value;
    write_material(out, r.material);
    write_vec(out, "x_range_m", Eigen::Vector2d(r.x_min_m, r.x_max_m));
    write_vec(out, "y_range_m", Eigen::Vector2d(r.y_min_m, r.y_max_m));
    out << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  out << YAML::Key << "objects" << YAML::Value;
  if (s.objects.empty()) out << YAML::Flow;
  out << YAML::BeginSeq;
  for (const ObjectSpec& o : s.objects) write_object(out, o);
  out << YAML::EndSeq;
  if (s.camera) write_fields(out, "camera", *s.camera, kCameraFields);
  write_fields(out, "ground_model", s.ground_model, kGroundModelFields);
  if (s.dem) write_fields(out, "dem", *s.dem, kDemFields);
  out << YAML::EndMap;
}

std::string scene_to_yaml(const Scene& scene) {
  YAML::Emitter out;
  write_scene_yaml(scene, out);
  return std::string(out.c_str()) + "\n";
}

std::string describe_scene(const Scene& s) {
  const Grid& g = s.ground.grid;
  std::string out = fmt::format("scene '{}' ({})\n", s.name, s.source_path);
  out += fmt::format("ground: {} x {} cells of {} m over {} x {} m from ({}, {}) m; initial height {}\n", g.nx, g.ny,
                     g.cell_size_m, g.extent_x_m(), g.extent_y_m(), g.origin_x_m, g.origin_y_m,
                     initial_summary(s.ground.initial));
  out += fmt::format("material: {}; {} region(s)\n", material_summary(s.ground.material), s.ground.regions.size());
  for (const MaterialRegion& r : s.ground.regions) {
    out += fmt::format("  region x [{}, {}] y [{}, {}] m: {}\n", r.x_min_m, r.x_max_m, r.y_min_m, r.y_max_m,
                       material_summary(r.material));
  }
  out += fmt::format("objects: {}\n", s.objects.size());
  for (const ObjectSpec& o : s.objects) {
    const double first_s = o.keyframes.empty() ? 0.0 : o.keyframes.front().time_s;
    const double last_s = o.keyframes.empty() ? 0.0 : o.keyframes.back().time_s;
    out += fmt::format("  {}: {}, {} triangles, {} keyframe(s) over [{}, {}] s{}\n", o.name, shape_summary(o),
                       o.body.F.rows(), o.keyframes.size(), first_s, last_s, o.simple ? ", simple" : "");
  }
  out += fmt::format("time: {} steps of {} s ({} s); seed {}{}{}\n", s.time.step_count(), s.time.step_s,
                     s.time.duration_s, s.seed, s.camera ? "; camera" : "", s.dem ? "; DEM reference section" : "");
  return out;
}

}  // namespace repose
