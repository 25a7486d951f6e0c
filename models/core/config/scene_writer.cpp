#include "models/core/config/scene_loader.h"

#include <filesystem>

#include <fmt/format.h>

#include "models/core/config/dynamic_body.h"
#include "models/core/config/fields.h"
#include "models/core/config/scene_fields.h"

namespace repose {

namespace {

namespace fs = std::filesystem;

std::string num(double x) { return yaml_number(x); }
std::string deg(double degrees) { return yaml_degrees(degrees); }

// ---- writing

void write_vec(YAML::Emitter& out, const char* key, const Eigen::VectorXd& v, bool degrees = false) {
  out << YAML::Key << key << YAML::Value << YAML::Flow << YAML::BeginSeq;
  for (Eigen::Index k = 0; k < v.size(); ++k) out << (degrees ? deg(v[k]) : num(v[k]));
  out << YAML::EndSeq;
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
    case InitialHeight::Kind::kGiven:
      out << YAML::Key << "kind" << YAML::Value << "given" << YAML::Key << "note" << YAML::Value
          << "a field given in code (e.g. a reference's settled surface); not loadable";
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
  if (o.dynamic) {
    out << YAML::Key << "dynamic" << YAML::Value;
    write_fields_map(out, *o.dynamic, kDynamicBodyFields);
    out << YAML::EndMap;
    return;
  }
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
    case InitialHeight::Kind::kGiven: return "given in code";
  }
  return "";
}

}  // namespace

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
  out << YAML::Key << "material" << YAML::Value << s.ground.material;
  out << YAML::Key << "regions" << YAML::Value;
  if (s.ground.regions.empty()) out << YAML::Flow;
  out << YAML::BeginSeq;
  for (const MaterialRegion& r : s.ground.regions) {
    out << YAML::BeginMap << YAML::Key << "material" << YAML::Value << r.material;
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
  for (const auto& [key, section] : s.sections) {
    out << YAML::Key << key << YAML::Value;
    section->write_yaml(out);
  }
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
  out += fmt::format("material: {}; {} region(s)\n", s.ground.material, s.ground.regions.size());
  for (const MaterialRegion& r : s.ground.regions) {
    out += fmt::format("  region x [{}, {}] y [{}, {}] m: {}\n", r.x_min_m, r.x_max_m, r.y_min_m, r.y_max_m,
                       r.material);
  }
  out += fmt::format("objects: {}\n", s.objects.size());
  for (const ObjectSpec& o : s.objects) {
    const double first_s = o.keyframes.empty() ? 0.0 : o.keyframes.front().time_s;
    const double last_s = o.keyframes.empty() ? 0.0 : o.keyframes.back().time_s;
    const std::string motion = o.dynamic ? fmt::format("free body of {} kg", o.mass_kg())
                                         : fmt::format("{} keyframe(s) over [{}, {}] s", o.keyframes.size(), first_s, last_s);
    out += fmt::format("  {}: {}, {} triangles, {}{}\n", o.name, shape_summary(o), o.body.F.rows(), motion,
                       o.simple ? ", simple" : "");
  }
  out += fmt::format("time: {} steps of {} s ({} s); seed {}{}{}\n", s.time.step_count(), s.time.step_s,
                     s.time.duration_s, s.seed, s.camera ? "; camera" : "", "");
  for (const auto& [key, section] : s.sections) out += section->summary() + "\n";
  return out;
}

}  // namespace repose
