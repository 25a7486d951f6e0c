#include "models/ground/ground_section.h"

#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"

namespace repose {

namespace {

const auto kGroundModelFields = [](auto& v, GroundModelSpec& x) { ground_model_fields(v, x); };
const auto kMaterialFields = [](auto& v, Material& x) { material_fields(v, x); };

// free_bodies: and bearing: (each optional; absent: the defaults).
void read_free_bodies(const YamlMap& map, FreeBodySpec& spec) {
  if (auto value = map.get("free_bodies"); value && !value->node().IsNull()) {
    const YamlMap sub = value->map(field_keys<FreeBodySpec>(kFreeBodyFields));
    read_fields_into(sub, kFreeBodyFields, spec);
    validate_at(sub, [&] { validate(spec); });
  }
  if (auto value = map.get("bearing"); value && !value->node().IsNull()) {
    const YamlMap sub = value->map(field_keys<BekkerBearing>(kBekkerBearingFields));
    read_fields_into(sub, kBekkerBearingFields, spec.bearing);
    validate_at(sub, [&] { validate(spec.bearing); });
  }
}
const char* const kPresets = "sand, mud, snow";

Material read_material(const std::string& name, const YamlValue& value) {
  const YamlMap map = value.map(field_keys<Material>(kMaterialFields, {"preset"}));
  Material m;
  std::string preset = name;
  if (auto p = map.get("preset")) preset = p->string();
  if (!material_preset(preset, &m)) {
    if (auto p = map.get("preset")) p->fail(std::string("a material preset (one of ") + kPresets + ")");
    // a new name without a preset: every parameter of the paper must be given
    for (const char* key : {"alpha", "repose_angle_deg", "sigma"}) {
      if (!map.has(key)) map.fail_missing(key, "a value for every parameter of a material that is not a preset");
    }
  }
  read_fields_into(map, kMaterialFields, m);
  m.name = name;
  validate_at(map, [&] { validate(m); });
  return m;
}

// Every material the common scene names must be defined or a preset.
void check_named(const GroundModelSection& section, const std::string& name, const std::string& location,
                 const std::string& key, const Scene& common) {
  Material m;
  if (section.materials.count(name) != 0 || material_preset(name, &m)) return;
  const std::string where = location.empty() ? common.source_path : location;
  throw InputError(fmt::format("{}: {}: expected a material preset (one of {}) or a name defined in "
                               "ground_model.materials, got '{}'",
                               where, key, kPresets, name));
}

}  // namespace

void validate(const GroundModelSpec& o) {
  if (o.substeps < 1 || o.substeps > 10000) {
    throw FieldError("substeps", "an integer in [1, 10000]", std::to_string(o.substeps));
  }
  // the substep count of a rotation is ceil(angle / max): a floor keeps it bounded
  if (!(o.max_substep_angle_rad >= 0.01 * kRadPerDeg && o.max_substep_angle_rad <= std::numbers::pi)) {
    throw FieldError("max_substep_angle_deg", "an angle in [0.01, 180] deg",
                     yaml_degrees(o.max_substep_angle_rad / kRadPerDeg));
  }
  if (o.erosion_memory_steps < 0 || o.erosion_memory_steps > 65000) {
    throw FieldError("erosion_memory_steps", "an integer in [0, 65000] (the memory counter is 16-bit)",
                     std::to_string(o.erosion_memory_steps));
  }
  if (!(o.bed_slope_rad >= 0.0 && o.bed_slope_rad < 80.0 * kRadPerDeg)) {
    throw FieldError("bed_slope_deg", "an angle in [0, 80) deg", yaml_degrees(o.bed_slope_rad / kRadPerDeg));
  }
  if (o.coarse_factor < 1 || o.coarse_factor > 64) {
    throw FieldError("coarse_factor", "an integer in [1, 64]", std::to_string(o.coarse_factor));
  }
  if (o.heap_laying != GroundModelSpec::HeapLaying::kPortions && o.heap_laying != GroundModelSpec::HeapLaying::kOnePass) {
    throw FieldError("heap_laying", "portions or one_pass", std::to_string(static_cast<int>(o.heap_laying)));
  }
  if (!(o.far_distance_m >= 0.0 && o.far_distance_m <= 1.0e6)) {
    throw FieldError("far_distance_m", "a distance in [0, 1e6] m", yaml_number(o.far_distance_m));
  }
}

Material GroundModelSection::material(const std::string& name) const {
  const auto it = materials.find(name);
  if (it != materials.end()) return it->second;
  Material m;
  if (!material_preset(name, &m)) {
    throw InputError(fmt::format("ground_model: material '{}' is neither defined in ground_model.materials nor a "
                                 "preset ({})",
                                 name, kPresets));
  }
  return m;
}

void GroundModelSection::write_yaml(YAML::Emitter& out) const {
  out << YAML::BeginMap;
  FieldWriter writer(out);
  GroundModelSpec o = options;
  ground_model_fields(writer, o);
  out << YAML::Key << "materials" << YAML::Value;
  if (materials.empty()) out << YAML::Flow;
  out << YAML::BeginMap;
  for (const auto& [name, material] : materials) {
    out << YAML::Key << name << YAML::Value;
    write_fields_map(out, material, kMaterialFields);
  }
  out << YAML::EndMap;
  out << YAML::Key << "free_bodies" << YAML::Value;
  write_fields_map(out, free_bodies, kFreeBodyFields);
  out << YAML::Key << "bearing" << YAML::Value;
  write_fields_map(out, free_bodies.bearing, kBekkerBearingFields);
  out << YAML::EndMap;
}

std::string GroundModelSection::summary() const {
  std::string text = fmt::format("ground_model: {}, {} substep(s), erosion memory {} steps, coarse factor {}, "
                                 "collision {}",
                                 options.sweep ? "sweep" : "no sweep", options.substeps, options.erosion_memory_steps,
                                 options.coarse_factor,
                                 options.collision == GroundModelSpec::Collision::kCpu ? "cpu" : "osmesa");
  if (options.bed_slope_rad > 0.0) text += fmt::format(", bed inclined {:.6g} deg", options.bed_slope_rad / kRadPerDeg);
  if (options.heap_laying == GroundModelSpec::HeapLaying::kOnePass) text += ", heaps laid in one pass";
  const BekkerBearing& b = free_bodies.bearing;
  text += b.law == BekkerBearing::Law::kOff
              ? std::string("; free bodies: ODE, no bearing sinkage")
              : fmt::format("; free bodies: ODE, Bekker bearing n {}, k_c {} N/m^(n+1), k_phi {} N/m^(n+2)",
                            b.exponent_n, b.k_c_n_per_m_n_plus_1, b.k_phi_n_per_m_n_plus_2);
  for (const auto& [name, m] : materials) {
    text += fmt::format("; {}: alpha {}, repose angle {:.6g} deg, sigma {}, {} erosion iterations", name, m.alpha,
                        m.repose_angle_rad / kRadPerDeg, m.sigma, m.erosion_iterations);
    if (m.erosion_iterations_cell_m > 0.0) {
      text += fmt::format(" at {} m cells (scaled with the cells' area)", m.erosion_iterations_cell_m);
    }
    if (m.drag_compaction_ratio != 1.0) text += fmt::format(", drag compaction ratio {}", m.drag_compaction_ratio);
  }
  return text;
}

const GroundModelSection& ground_model_section(const Scene& scene) {
  static const GroundModelSection defaults;
  const GroundModelSection* section = scene.section<GroundModelSection>();
  return section != nullptr ? *section : defaults;
}

Scene with_ground_options(Scene scene, const GroundModelSpec& options) {
  validate(options);
  auto section = std::make_shared<GroundModelSection>(ground_model_section(scene));
  section->options = options;
  scene.sections[GroundModelSection::kKey] = section;
  return scene;
}

Scene with_material(Scene scene, const Material& material) {
  validate(material);
  auto section = std::make_shared<GroundModelSection>(ground_model_section(scene));
  section->materials[material.name] = material;
  scene.sections[GroundModelSection::kKey] = section;
  return scene;
}

std::shared_ptr<const SceneSection> read_ground_model_section(const YamlValue& value, const Scene& common) {
  auto section = std::make_shared<GroundModelSection>();
  if (value.node().IsDefined() && !value.node().IsNull()) {
    const YamlMap map =
        value.map(field_keys<GroundModelSpec>(kGroundModelFields, {"materials", "free_bodies", "bearing"}));
    read_fields_into(map, kGroundModelFields, section->options);
    validate_at(map, [&] { validate(section->options); });
    read_free_bodies(map, section->free_bodies);
    if (auto materials = map.get("materials")) {
      if (!materials->is_map()) materials->fail("a map from material names to {preset, alpha, repose_angle_deg, ...}");
      for (const auto& entry : materials->node()) {
        const std::string name = entry.first.as<std::string>();
        const YamlValue item(value.file(), entry.second, materials->path() + "." + name);
        section->materials[name] = read_material(name, item);
      }
    }
  }
  if (common.ground.regions.size() > 254) {
    throw InputError(fmt::format("{}: ground.regions: {} regions, the ground model supports at most 254",
                                 common.source_path, common.ground.regions.size()));
  }
  check_named(*section, common.ground.material, common.ground.material_location, "ground.material", common);
  for (std::size_t r = 0; r < common.ground.regions.size(); ++r) {
    const MaterialRegion& region = common.ground.regions[r];
    check_named(*section, region.material, region.location, fmt::format("ground.regions[{}].material", r), common);
  }
  return section;
}

SectionType ground_model_section_type() {
  return {GroundModelSection::kKey, "the ground model's options and materials (models/ground/ground_section.h)",
          read_ground_model_section, true};
}

}  // namespace repose
