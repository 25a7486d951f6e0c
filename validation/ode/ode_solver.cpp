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

std::unique_ptr<CompiledSolver> OdeSolver::compile(const Scene& scene) const {
  return compile_rigid(scene, ode_engine(ode_options_of(scene)));
}

}  // namespace repose
