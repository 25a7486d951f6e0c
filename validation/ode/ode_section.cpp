#include "validation/ode/ode_section.h"

#include <fmt/format.h>

#include "models/core/config/fields.h"
#include "models/core/config/scene.h"
#include "validation/particles/option_fields.h"

namespace repose {

namespace {

const auto kOdeFields = [](auto& v, OdeOptions& o) { ode_option_fields(v, o); };

}  // namespace

void OdeSection::write_yaml(YAML::Emitter& out) const { write_fields_map(out, options, kOdeFields); }

std::string OdeSection::summary() const {
  return fmt::format("ode: step {:.4g} s, {} solver iterations", options.rigid.time_step_s, options.rigid.solver_iterations);
}

SectionType ode_section_type() {
  auto read = [](const YamlValue& value, const Scene&) {
    return read_option_section<OdeSection>(value, kOdeFields);
  };
  return {OdeSection::kKey,
          "the ODE rigid-body reference's options (validation/ode/ode_options.h)", read, false};
}

OdeOptions ode_options_of(const Scene& scene) { return options_of<OdeSection>(scene); }

}  // namespace repose
