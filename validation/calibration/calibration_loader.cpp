#include "validation/calibration/calibration_loader.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/io/input_file.h"
#include "models/core/config/fields.h"
#include "models/core/config/yaml_reader.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

const Range kCoordinate = Range::closed(-1.0e6, 1.0e6);

struct Context {
  fs::path directory;  // absolute folder of the calibration file
};

std::string resolve(const Context& ctx, const std::string& path) {
  const fs::path p(path);
  return (p.is_absolute() ? p : ctx.directory / p).lexically_normal().string();
}

std::string existing(const Context& ctx, const YamlValue& value, bool directory, const std::string& what) {
  const std::string path = resolve(ctx, value.string());
  std::error_code ec;
  if (!fs::exists(path, ec)) value.fail(what, fmt::format("'{}', which does not exist ({})", value.string(), path));
  if (fs::is_directory(path, ec) != directory) {
    value.fail(what, fmt::format("'{}', which is {}a directory ({})", value.string(), directory ? "not " : "", path));
  }
  return path;
}

// ---- field lists (models/core/config/fields.h)

template <class Visitor>
void solver_fields(Visitor& v, CalibrationSolverSpec& s) {
  using L = CalibrationSolverSpec::Loss;
  v.choice("loss", s.loss, std::vector<std::pair<std::string, L>>{{"none", L::kNone}, {"huber", L::kHuber}, {"cauchy", L::kCauchy}});
  v.number("loss_scale", s.loss_scale, Range::positive());
  v.integer("starts", s.starts, IntRange{1, 256});
  v.integer("max_iterations", s.max_iterations, IntRange{1, 10000});
  v.seed("seed", s.seed);
  v.integer("threads", s.threads, IntRange{1, 64});
  v.boolean("cross_validation", s.cross_validation);
  v.number("min_reciprocal_condition", s.min_reciprocal_condition, Range::open(0.0, 1.0));
}

template <class Visitor>
void ladder_fields(Visitor& v, LadderSpec& l) {
  v.boolean("multires", l.multires);
  v.integer("multires_coarse_factor", l.multires_coarse_factor, IntRange{2, 16});
  v.integer("timing_repeats", l.timing_repeats, IntRange{1, 100});
}

// ---- pieces

CalibrationRegion read_region(const YamlValue& value) {
  const YamlMap map = value.map({"x", "y"});
  const Eigen::Vector2d x = map.vec2("x", kCoordinate), y = map.vec2("y", kCoordinate);
  for (const auto& [key, r] : {std::pair{"x", x}, std::pair{"y", y}}) {
    if (!(r[0] < r[1])) map.get(key)->fail("a range [min, max] with min < max", fmt::format("[{}, {}]", r[0], r[1]));
  }
  return {x[0], x[1], y[0], y[1]};
}

// A series observable's name and its increasing times (s).
void read_series_observable(const YamlMap& map, ObservableSpec* o) {
  o->series = map.string("name");
  const YamlValue times = map.required("times_s", "a list of times (s) at which to compare the series");
  for (const YamlValue& t : times.list(1)) {
    o->times_s.push_back(t.number(Range::closed(0.0, 1.0e6)));
    if (o->times_s.size() > 1 && !(o->times_s.back() > o->times_s[o->times_s.size() - 2])) {
      t.fail("a time later than the one before it");
    }
  }
}

ObservableSpec read_observable(const YamlValue& value) {
  using K = ObservableSpec::Kind;
  const std::vector<std::string> kinds = {"height_field", "transect",    "crater_depth", "rim_height",
                                          "pile_angle",   "furrow_area", "series",     "measure",
                                          "heap_flank"};
  const std::vector<std::vector<std::string>> keys = {
      {"kind", "weight", "region_m"},
      {"kind", "weight", "from_m", "to_m", "samples"},
      {"kind", "weight", "region_m"},
      {"kind", "weight", "region_m"},
      {"kind", "weight", "centre_m"},
      {"kind", "weight", "from_m", "to_m", "samples"},
      {"kind", "weight", "name", "times_s"},
      {"kind", "weight", "name"},
      {"kind", "weight", "region_m", "base_height_m", "reach_m"}};
  // the allowed keys depend on the kind: read it first, then check the map against its kind
  if (!value.is_map()) value.fail("a map with a kind");
  const YAML::Node kind_node = value.node()["kind"];
  if (!kind_node) {
    value.map({"kind", "weight", "region_m", "from_m", "to_m", "samples", "centre_m", "name", "times_s", "base_height_m", "reach_m"})
        .fail_missing("kind", "one of height_field, transect, crater_depth, rim_height, pile_angle, furrow_area, series, measure, heap_flank");
  }
  const std::size_t kind = YamlValue(value.file(), kind_node, value.path() + ".kind").choice(kinds);
  const YamlMap map = value.map(keys[kind]);
  ObservableSpec o;
  o.kind = static_cast<K>(kind);
  o.weight = map.number_or("weight", Range::positive(), 1.0);
  if (auto r = map.get("region_m")) o.region = read_region(*r);
  if (o.kind == K::kTransect || o.kind == K::kFurrowArea) {
    o.from_m = map.vec2("from_m", kCoordinate);
    o.to_m = map.vec2("to_m", kCoordinate);
    if (o.from_m == o.to_m) map.get("to_m")->fail("a point other than from_m");
    o.samples = static_cast<int>(map.integer_or("samples", IntRange{2, 100000}, o.samples));
  }
  if (o.kind == K::kPileAngle) o.centre_m = map.vec2("centre_m", kCoordinate);
  if (o.kind == K::kSeries) read_series_observable(map, &o);
  if (o.kind == K::kMeasure) o.measure = map.string("name");
  if (o.kind == K::kHeapFlank) {
    if (map.has("base_height_m")) o.base_height_m = map.number("base_height_m", kCoordinate);
    o.reach_m = map.number_or("reach_m", Range::positive(), o.reach_m);
  }
  return o;
}

std::string location_of(const YamlValue& value) {
  return fmt::format("{}:{}:{}", value.file(), value.node().Mark().line + 1, value.node().Mark().column + 1);
}

// "ground.sand.alpha" -> ("ground", "sand.alpha")
std::pair<std::string, std::string> split_parameter_name(const YamlValue& value) {
  const std::string full = value.string();
  const std::size_t dot = full.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == full.size()) {
    value.fail("a parameter named solver.parameter (e.g. ground.sand.alpha)");
  }
  return {full.substr(0, dot), full.substr(dot + 1)};
}

ReferenceSpec read_reference(const Context& ctx, const YamlValue& value, const std::string& field) {
  const YamlMap map = value.map({"data", "liggghts", "heuristic"});
  int count = 0;
  for (const char* key : {"data", "liggghts", "heuristic"}) count += map.has(key) ? 1 : 0;
  if (count != 1) value.fail("exactly one of data, liggghts, heuristic", count == 0 ? "none" : "several");
  ReferenceSpec r;
  r.location = location_of(value);
  if (auto data = map.get("data")) {
    r.kind = ReferenceSpec::Kind::kData;
    // one folder, or a list of folders: the same scene on several random beds
    const std::vector<YamlValue> folders = data->is_list() ? data->list(1) : std::vector<YamlValue>{*data};
    for (const YamlValue& folder : folders) {
      const std::string dir = existing(ctx, folder, true, "a folder of a reference run (height_initial.npy, height_final.npy)");
      for (const std::string& file : {std::string("height_initial.npy"), field + ".npy"}) {
        if (!fs::exists(fs::path(dir) / file)) folder.fail(fmt::format("a folder holding {}", file), dir);
      }
      r.directories.push_back(dir);
    }
  } else if (auto run = map.get("liggghts")) {
    r.kind = ReferenceSpec::Kind::kLiggghts;
    r.directories = {resolve(ctx, run->string())};
  } else {
    r.kind = ReferenceSpec::Kind::kHeuristic;
    const YamlValue h = *map.get("heuristic");
    if (!h.is_map()) h.fail("a map from parameter names (solver.parameter) to values");
    for (const auto& entry : h.node()) {
      const YamlValue key(h.file(), entry.first, h.path());
      const YamlValue item(h.file(), entry.second, h.path() + "." + entry.first.Scalar());
      split_parameter_name(key);
      r.values.emplace_back(key.string(), item.number(Range::any()));
    }
  }
  return r;
}

CalibrationScene read_scene_entry(const Context& ctx, const YamlValue& value) {
  const YamlMap map =
      value.map({"scene", "name", "role", "reference", "observables", "rmse_region_m", "field", "seed", "beds", "cell_size_m"});
  CalibrationScene s;
  s.scene_path = existing(ctx, map.required("scene", "a scene file"), false, "a scene file");
  s.name = map.string_or("name", "");
  s.field = map.string_or("field", s.field);
  if (s.field.empty() || s.field.find('/') != std::string::npos) map.get("field")->fail("a field name (e.g. height_final)");
  if (auto role = map.get("role")) s.role = role->choice({"fit", "held_out"}) == 0 ? CalibrationScene::Role::kFit
                                                                                  : CalibrationScene::Role::kHeldOut;
  s.reference = read_reference(ctx, map.required("reference", "a map with one of data, liggghts, heuristic"), s.field);
  for (const YamlValue& o : map.required("observables", "a list of observables").list(1)) {
    s.observables.push_back(read_observable(o));
  }
  if (auto r = map.get("rmse_region_m")) s.rmse_region = read_region(*r);
  if (auto h = map.get("cell_size_m")) {
    s.cell_size_m = h->number(Range::positive());
    s.cell_size_location = location_of(*h);
  }
  if (map.has("seed")) s.seed = static_cast<std::uint64_t>(map.integer_or("seed", IntRange{0, std::int64_t{1} << 62}, 0));
  if (auto beds = map.get("beds")) {
    if (beds->choice({"mean", "each"}) == 1) {
      if (s.reference.kind != ReferenceSpec::Kind::kData || s.reference.directories.size() < 2) {
        beds->fail("mean, or each with a data reference of two or more seeds' folders", "each");
      }
      s.beds = CalibrationScene::Beds::kEach;
    }
  }
  return s;
}

ParameterSpec read_parameter(const YamlValue& value) {
  const YamlMap map = value.map({"name", "initial", "bounds", "step", "fixed"});
  ParameterSpec p;
  std::tie(p.solver, p.name) = split_parameter_name(map.required("name", "a parameter named solver.parameter"));
  p.location = location_of(value);
  p.fixed = map.boolean_or("fixed", false);
  if (auto b = map.get("bounds")) {
    const Eigen::Vector2d v = b->vec2(Range::any());
    if (!(v[0] < v[1])) b->fail("bounds [lower, upper] with lower < upper", fmt::format("[{}, {}]", v[0], v[1]));
    p.file_lower = v[0];
    p.file_upper = v[1];
  }
  const Range within = p.file_lower ? Range::closed(*p.file_lower, *p.file_upper) : Range::any();
  p.file_initial = map.number("initial", within);
  if (map.has("step")) {
    p.file_step = map.number("step", p.file_lower ? Range::left_open(0.0, 0.5 * (*p.file_upper - *p.file_lower))
                                                  : Range::positive());
  }
  return p;
}

LadderSpec read_ladder(const Context& ctx, const YamlValue& value) {
  const auto fields = [](auto& v, LadderSpec& l) { ladder_fields(v, l); };
  const YamlMap map = value.map(field_keys<LadderSpec>(fields, {"scene", "heuristic_cell_sizes_m", "references"}));
  LadderSpec l;
  FieldReader reader(map);
  ladder_fields(reader, l);
  l.scene = map.string_or("scene", "");
  for (const YamlValue& c : map.required("heuristic_cell_sizes_m", "a list of cell sizes (m)").list(1)) {
    l.heuristic_cell_sizes_m.push_back(c.number(Range::left_open(0.0, 1.0e3)));
  }
  if (auto list = map.get("references")) {
    for (const YamlValue& item : list->list()) {
      const YamlMap m = item.map({"scene", "data"});
      LadderReference r;
      r.scene_path = existing(ctx, m.required("scene", "a scene file"), false, "a scene file");
      r.directory = existing(ctx, m.required("data", "a reference run folder"), true, "a reference run folder");
      const fs::path dir(r.directory);
      if (!fs::exists(dir / "height_final.npy")) m.get("data")->fail("a folder holding height_final.npy", r.directory);
      if (!fs::exists(dir / "liggghts_manifest.json") && !fs::exists(dir / "manifest.json")) {
        m.get("data")->fail("a run folder holding its manifest (manifest.json or liggghts_manifest.json)", r.directory);
      }
      l.references.push_back(r);
    }
  }
  return l;
}

CalibrationSpec read_calibration(const Context& ctx, const YamlValue& root, const std::string& path) {
  if (!root.is_map()) root.fail("a calibration (a map with scenes and parameters)");
  const YamlMap map = root.map({"name", "scenes", "parameters", "solver", "ladder"});
  CalibrationSpec spec;
  spec.source_path = fs::absolute(path).lexically_normal().string();
  spec.name = map.string_or("name", fs::path(path).stem().string());
  const YamlValue scenes = map.required("scenes", "a list of scenes");
  for (const YamlValue& s : scenes.list(1)) spec.scenes.push_back(read_scene_entry(ctx, s));
  if (std::none_of(spec.scenes.begin(), spec.scenes.end(),
                   [](const CalibrationScene& s) { return s.role == CalibrationScene::Role::kFit; })) {
    scenes.fail("at least one scene with role fit", "only held_out scenes");
  }
  const YamlValue parameters = map.required("parameters", "a list of parameters");
  for (const YamlValue& p : parameters.list(1)) {
    ParameterSpec param = read_parameter(p);
    for (const ParameterSpec& other : spec.parameters) {
      if (other.label() == param.label()) p.fail("a parameter not listed before", param.label() + " again");
    }
    spec.parameters.push_back(param);
  }
  spec.fitted_solver = spec.parameters.front().solver;
  for (std::size_t k = 0; k < spec.parameters.size(); ++k) {
    if (spec.parameters[k].solver != spec.fitted_solver) {
      parameters.list()[k].fail(fmt::format("a parameter of solver {} (a calibration fits one solver, named by the "
                                            "first parameter)",
                                            spec.fitted_solver),
                                spec.parameters[k].label());
    }
  }
  if (std::all_of(spec.parameters.begin(), spec.parameters.end(), [](const ParameterSpec& p) { return p.fixed; })) {
    parameters.fail("at least one parameter that is not fixed", "all fixed");
  }
  if (auto s = map.get("solver")) {
    const auto fields = [](auto& v, CalibrationSolverSpec& x) { solver_fields(v, x); };
    const YamlMap solver = s->map(field_keys<CalibrationSolverSpec>(fields, {}));
    FieldReader reader(solver);
    solver_fields(reader, spec.solver);
  }
  if (auto l = map.get("ladder")) {
    spec.ladder = read_ladder(ctx, *l);
    // the ladder's scene name is checked once the scenes are loaded (calibration_problem.cpp)
  }
  return spec;
}

}  // namespace

CalibrationSpec load_calibration_from_string(const std::string& yaml, const std::string& pretend_path) {
  const Context ctx{fs::absolute(fs::path(pretend_path)).parent_path().lexically_normal()};
  return read_calibration(ctx, parse_yaml(yaml, pretend_path), pretend_path);
}

CalibrationSpec load_calibration(const std::string& path) {
  // a regular file within the bound: a FIFO waited forever, /dev/zero ran out of memory
  return load_calibration_from_string(read_input_file(path, input_kind::kCalibration), path);
}

}  // namespace repose
