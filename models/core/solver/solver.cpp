#include "models/core/solver/solver.h"

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/scene.h"

namespace repose {

std::vector<double> CompiledSolver::default_values() const {
  std::vector<double> values;
  for (const ParameterInfo& p : parameters()) values.push_back(p.value_si);
  return values;
}

std::size_t CompiledSolver::parameter_index(const std::string& name) const {
  const auto& list = parameters();
  std::string names;
  for (std::size_t k = 0; k < list.size(); ++k) {
    if (list[k].name == name) return k;
    names += (names.empty() ? "" : ", ") + list[k].name;
  }
  throw InputError(fmt::format("no parameter '{}' (this scene's are: {})", name, names.empty() ? "none" : names));
}

bool Solver::can_run(const Scene& scene, std::string* why) const {
  for (const SectionType& type : sections()) {
    if (type.read_when_absent || scene.has_section(type.key)) continue;
    if (why != nullptr) *why = fmt::format("the scene has no '{}' section ({})", type.key, type.description);
    return false;
  }
  return true;
}

void check_values(const std::vector<ParameterInfo>& parameters, const std::vector<double>& values_si,
                  const std::string& solver) {
  if (values_si.size() != parameters.size()) {
    throw InputError(fmt::format("solver {}: {} parameter values given, it has {}", solver, values_si.size(),
                                 parameters.size()));
  }
  for (std::size_t k = 0; k < values_si.size(); ++k) {
    const ParameterInfo& p = parameters[k];
    const double v = values_si[k];
    if (!(v >= p.lower_si && v <= p.upper_si)) {
      throw InputError(fmt::format("solver {}: parameter {} = {} {} is outside [{}, {}] {}", solver, p.name,
                                   v / p.si_per_unit, p.unit, p.lower_si / p.si_per_unit,
                                   p.upper_si / p.si_per_unit, p.unit));
    }
  }
}

}  // namespace repose
