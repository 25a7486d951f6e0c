#include "validation/ode/ode_solver.h"

#include "validation/ode/ode_engine.h"
#include "validation/ode/ode_section.h"
#include "models/terrain/terrain_section.h"
#include "validation/particles/dem_section.h"
#include "validation/rigid/rigid_solver.h"

namespace repose {

std::string OdeSolver::description() const {
  return "rigid bodies in ODE (options in ode:): a dem section's grains (settled bed, run, observables) or a terrain section's debris flow with breakable buildings";
}

std::vector<SectionType> OdeSolver::sections() const { return {dem_section_type(), ode_section_type(), terrain_section_type()}; }

bool OdeSolver::can_run(const Scene& scene, std::string* why) const {
  if (dem_of(scene) != nullptr || scene.section<TerrainSection>() != nullptr) return true;  // terrain: a debris flow
  if (why != nullptr) *why = "the scene has neither a 'dem' section (grains) nor a 'terrain' section (a debris flow)";
  return false;
}

std::unique_ptr<CompiledSolver> OdeSolver::compile(const Scene& scene) const {
  return compile_rigid(scene, ode_engine(ode_options_of(scene)));
}

}  // namespace repose
