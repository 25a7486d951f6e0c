#include "validation/ode/ode_solver.h"

#include "validation/ode/ode_engine.h"
#include "validation/ode/ode_section.h"
#include "validation/particles/dem_section.h"
#include "validation/rigid/rigid_solver.h"

namespace repose {

std::string OdeSolver::description() const {
  return "rigid spheres in ODE (needs the scene's dem section; options in ode:): settled bed, run, observables";
}

std::vector<SectionType> OdeSolver::sections() const { return {dem_section_type(), ode_section_type()}; }

bool OdeSolver::can_run(const Scene& scene, std::string* why) const {
  if (dem_of(scene) != nullptr) return true;
  if (why != nullptr) *why = "the scene has no 'dem' section (the grains of the particle references)";
  return false;
}

std::unique_ptr<CompiledSolver> OdeSolver::compile(const Scene& scene) const {
  return compile_rigid(scene, ode_engine(ode_options_of(scene)));
}

}  // namespace repose
