#include "models/core/solver/solver_registry.h"

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

SolverRegistry& SolverRegistry::add(std::shared_ptr<const Solver> solver) {
  REPOSE_DEMAND(solver != nullptr);
  REPOSE_DEMAND(find(solver->name()) == nullptr && "solver names are unique");
  for (const SectionType& type : solver->sections()) {
    bool known = false;
    for (const SectionType& s : sections_) known = known || s.key == type.key;
    if (!known) sections_.push_back(type);
  }
  solvers_.push_back(std::move(solver));
  return *this;
}

std::vector<std::string> SolverRegistry::names() const {
  std::vector<std::string> names;
  for (const auto& s : solvers_) names.push_back(s->name());
  return names;
}

const Solver* SolverRegistry::find(const std::string& name) const {
  for (const auto& s : solvers_) {
    if (s->name() == name) return s.get();
  }
  return nullptr;
}

const Solver& SolverRegistry::get(const std::string& name) const {
  if (const Solver* s = find(name)) return *s;
  throw InputError(fmt::format("unknown solver '{}' (known: {})", name, fmt::join(names(), ", ")));
}

}  // namespace repose
