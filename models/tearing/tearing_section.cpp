#include "models/tearing/tearing_section.h"

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"

namespace repose {

namespace {

template <class V>
void sheet_fields(V& v, SheetSpec& s) {
  v.number("width_m", s.width_m, Range::positive());
  v.number("height_m", s.height_m, Range::positive());
  v.number("grammage_kg_per_m2", s.grammage_kg_per_m2, Range::positive());
  v.integer("cells_x", s.cells_x, IntRange{1, 2000});
  v.number("bending_stiffness_n_m", s.bending_stiffness_n_m, Range::non_negative());
  v.boolean("twist_stiffness", s.twist_stiffness);
  v.number("stiffness_density_exponent", s.stiffness_density_exponent, Range::closed(0, 8));
  v.number("tear_strain_density_exponent", s.tear_strain_density_exponent, Range::closed(0, 8));
  v.choice("tear_rule", s.tear_rule, ChoiceTable<TearRule>{{"strain", TearRule::kStrain}, {"energy", TearRule::kEnergy}, {"cohesive", TearRule::kCohesive}});
  v.boolean("isotropic_tear_energy", s.isotropic_tear_energy);
  v.number("damping_per_s", s.damping_per_s, Range::non_negative());
  v.number("stiffness_damping_s", s.stiffness_damping_s, Range::non_negative());
  v.number("release_time_s", s.release_time_s, Range::non_negative());
  v.vec3("gravity_m_per_s2", s.gravity_m_per_s2, Range::any());
  v.number("notch_length_m", s.notch_length_m, Range::non_negative());
  v.number("notch_x_m", s.notch_x_m, Range::non_negative());
}

template <class V>
void params_fields(V& v, SheetParams& p) {
  v.number("stiffness_n_per_m", p.stiffness_n_per_m, Range::positive());
  v.number("tear_strain", p.tear_strain, Range::left_open(0, 10));
  v.number("tear_energy_j_per_m", p.tear_energy_j_per_m, Range::positive());
  v.number("fibre_anisotropy", p.fibre_anisotropy, Range::right_open(0, 1));
}

template <class V>
void settings_fields(V& v, TearRunOptions& t) {
  using I = TearRunOptions::Integrator;
  v.choice("integrator", t.integrator, ChoiceTable<I>{{"explicit", I::kExplicit}, {"implicit", I::kImplicit}});
  v.number("time_step_fraction", t.time_step_fraction, Range::positive());
  v.number("stop_at_depth_m", t.stop_at_depth_m, Range::non_negative());
}

template <class V>
void fibre_fields(V& v, FibreOptions& f) {
  v.integer("layers", f.layers, IntRange{1, 8});
  v.number("pixel_size_m", f.pixel_size_m, Range::positive());
  v.number("clumps_per_m2", f.clumps_per_m2, Range::non_negative());
  v.number("clump_width_min_m", f.clump_width_min_m, Range::positive());
  v.number("clump_width_max_m", f.clump_width_max_m, Range::positive());
  v.number("clump_length_min_m", f.clump_length_min_m, Range::positive());
  v.number("clump_length_max_m", f.clump_length_max_m, Range::positive());
  v.angle_deg("grain_direction_deg", f.grain_direction_rad, Range::closed(-360, 360));
  v.angle_deg("grain_spread_deg", f.grain_spread_rad, Range::closed(0, 90));
  v.number("background_density", f.background_density, Range::right_open(0, 1));
}

struct Twist {
  double grip_depth_m = 0.01, gap_m = 0.01, speed_m_per_s = 4.0;
};

template <class V>
void twist_fields(V& v, Twist& t) {
  v.number("grip_depth_m", t.grip_depth_m, Range::positive());
  v.number("gap_m", t.gap_m, Range::non_negative());
  v.number("speed_m_per_s", t.speed_m_per_s, Range::any());
}

template <class V>
void grip_fields(V& v, GripSpec& g) {
  v.number("x_min_m", g.x_min_m, Range::any(), Need::kRequired);
  v.number("x_max_m", g.x_max_m, Range::any(), Need::kRequired);
  v.number("y_min_m", g.y_min_m, Range::any(), Need::kRequired);
  v.number("y_max_m", g.y_max_m, Range::any(), Need::kRequired);
  v.vec3("velocity_m_per_s", g.velocity_m_per_s, Range::any());
  v.boolean("hold_x", g.held_axes[0]);
  v.boolean("hold_y", g.held_axes[1]);
  v.boolean("hold_z", g.held_axes[2]);
}

template <class V>
void tensile_fields(V& v, TensileOptions& t) {
  v.number("speed_m_per_s", t.speed_m_per_s, Range::positive());
  v.number("max_strain", t.max_strain, Range::positive());
  v.number("stiffness_strain_fraction", t.stiffness_strain_fraction, Range::left_open(0, 1));
}

const auto kSheet = [](auto& v, SheetSpec& x) { sheet_fields(v, x); };
const auto kParams = [](auto& v, SheetParams& x) { params_fields(v, x); };
const auto kSettings = [](auto& v, TearRunOptions& x) { settings_fields(v, x); };
const auto kFibres = [](auto& v, FibreOptions& x) { fibre_fields(v, x); };
const auto kTwist = [](auto& v, Twist& x) { twist_fields(v, x); };
const auto kGrip = [](auto& v, GripSpec& x) { grip_fields(v, x); };
const auto kTensile = [](auto& v, TensileOptions& x) { tensile_fields(v, x); };

std::vector<std::string> section_keys() {
  std::vector<std::string> keys = field_keys<SheetSpec>(kSheet, {"fibres", "twist", "grips", "tensile"});
  for (const auto& k : field_keys<SheetParams>(kParams)) keys.push_back(k);
  for (const auto& k : field_keys<TearRunOptions>(kSettings)) keys.push_back(k);
  return keys;
}

void read_grips(const YamlMap& map, TearingSection* s) {
  const auto twist = map.get("twist");
  const auto grips = map.get("grips");
  const auto tensile = map.get("tensile");
  if ((twist ? 1 : 0) + (grips ? 1 : 0) + (tensile ? 1 : 0) > 1) {
    (tensile ? tensile : grips)->fail("one of twist, grips and tensile");
  }
  if (tensile) {
    TensileOptions t;
    read_fields_into(tensile->map(field_keys<TensileOptions>(kTensile)), kTensile, t);
    s->sheet.grips = tensile_grips(s->sheet.width_m, s->sheet.height_m, s->sheet.cell_size_m(), t.speed_m_per_s);
    s->tensile = t;
  }
  if (twist) {
    Twist t;
    read_fields_into(twist->map(field_keys<Twist>(kTwist)), kTwist, t);
    s->sheet.grips = seed_twist_grips(s->sheet.width_m, s->sheet.height_m, t.grip_depth_m, t.gap_m, t.speed_m_per_s);
  }
  if (grips) {
    for (const YamlValue& item : grips->list(1)) {
      GripSpec g;
      read_fields_into(item.map(field_keys<GripSpec>(kGrip)), kGrip, g);
      s->sheet.grips.push_back(g);
    }
  }
}

}  // namespace

void TearingSection::write_yaml(YAML::Emitter& out) const {
  out << YAML::BeginMap;
  FieldWriter writer(out);
  SheetSpec sheet_copy = sheet;
  SheetParams params_copy = params;
  TearRunOptions settings_copy = run;
  FibreOptions fibres_copy = sheet.fibres;
  sheet_fields(writer, sheet_copy);
  params_fields(writer, params_copy);
  settings_fields(writer, settings_copy);
  out << YAML::Key << "fibres" << YAML::Value;
  write_fields_map(out, fibres_copy, kFibres);
  if (tensile) {  // its grips follow from it
    TensileOptions tensile_copy = *tensile;
    out << YAML::Key << "tensile" << YAML::Value;
    write_fields_map(out, tensile_copy, kTensile);
    out << YAML::EndMap;
    return;
  }
  out << YAML::Key << "grips" << YAML::Value << YAML::BeginSeq;
  for (const GripSpec& g : sheet.grips) write_fields_map(out, g, kGrip);
  out << YAML::EndSeq << YAML::EndMap;
}

std::string TearingSection::summary() const {
  return fmt::format("tearing: {} x {} m sheet, {} x {} cells, {} fibre layers, grain {:.4g} deg, {} grip(s), {} "
                     "integrator, E t {} N/m, {}",
                     sheet.width_m, sheet.height_m, sheet.cells_x, sheet.cells_y(), sheet.fibres.layers,
                     sheet.fibres.grain_direction_rad / kRadPerDeg, sheet.grips.size(),
                     run.integrator == TearRunOptions::Integrator::kExplicit ? "explicit" : "implicit",
                     params.stiffness_n_per_m,
                     sheet.tear_rule == TearRule::kStrain   ? fmt::format("tear strain {}", params.tear_strain)
                     : sheet.tear_rule == TearRule::kEnergy ? fmt::format("tear energy {} J/m", params.tear_energy_j_per_m)
                                                            : fmt::format("cohesive, peak strain {}, tear energy {} J/m",
                                                                          params.tear_strain, params.tear_energy_j_per_m));
}

std::shared_ptr<const SceneSection> read_tearing_section(const YamlValue& value, const Scene& common) {
  auto s = std::make_shared<TearingSection>();
  const YamlMap map = value.map(section_keys());
  read_fields_into(map, kSheet, s->sheet);
  read_fields_into(map, kParams, s->params);
  read_fields_into(map, kSettings, s->run);
  s->run.duration_s = common.time.duration_s;  // the solver takes it from the scene again
  if (auto fibres = map.get("fibres")) {
    const YamlMap f = fibres->map(field_keys<FibreOptions>(kFibres));
    read_fields_into(f, kFibres, s->sheet.fibres);
    validate_at(f, [&] { s->sheet.fibres.validate(); });
  }
  read_grips(map, s.get());
  validate_at(map, [&] { s->sheet.validate(); });
  validate_at(map, [&] { s->params.validate(); });
  validate_at(map, [&] { s->run.validate(); });
  if (s->tensile) validate_at(map, [&] { s->tensile->time_step_fraction = s->run.time_step_fraction; s->tensile->validate(); });
  return s;
}

SectionType tearing_section_type() {
  return {TearingSection::kKey, "the paper-tearing sheet, its fibres, grips and integrator (models/tearing/tearing_section.h)",
          read_tearing_section, false};
}

}  // namespace repose
