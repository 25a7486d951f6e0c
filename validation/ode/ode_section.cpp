#include "validation/ode/ode_section.h"

#include <fmt/format.h>

#include "models/core/config/fields.h"
#include "models/core/config/scene.h"

namespace repose {

namespace {

const auto kOdeFields = [](auto& v, OdeOptions& o) { ode_option_fields(v, o); };

std::shared_ptr<const SceneSection> read_ode_section(const YamlValue& value, const Scene&) {
  auto section = std::make_shared<OdeSection>();
  if (value.node().IsDefined() && !value.node().IsNull()) {
    const YamlMap map = value.map(field_keys<OdeOptions>(kOdeFields));
    read_fields_into(map, kOdeFields, section->options);
    validate_at(map, [&] { validate(section->options); });
  }
  return section;
}

}  // namespace

void OdeSection::write_yaml(YAML::Emitter& out) const { write_fields_map(out, options, kOdeFields); }

std::string OdeSection::summary() const {
  return fmt::format("ode: step {:.4g} s, {} solver iterations", options.rigid.time_step_s, options.rigid.solver_iterations);
}

SectionType ode_section_type() {
  return {OdeSection::kKey, "the ODE rigid-body reference's options (validation/ode/ode_options.h)", read_ode_section,
          false};
}

OdeOptions ode_options_of(const Scene& scene) {
  const OdeSection* section = scene.section<OdeSection>();
  return section ? section->options : OdeOptions{};
}

}  // namespace repose
