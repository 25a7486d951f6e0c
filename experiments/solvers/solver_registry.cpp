#include "experiments/solvers/solver_registry.h"

#include "models/core/solver/initial_solver.h"
#include "models/ground/ground_solver.h"
#include "models/heightspan/heightspan_solver.h"
#include "models/tearing/tearing_solver.h"
#include "models/snow/snow_solver.h"
#include "models/terrain/terrain_solver.h"
#include "validation/bullet/bullet_solver.h"
#include "validation/liggghts_debris/liggghts_debris_solver.h"
#include "validation/ode/ode_solver.h"

namespace repose {

namespace {

SolverRegistry make_registry() {
  SolverRegistry registry;
  registry.add(std::make_shared<GroundSolver>());
  registry.add(std::make_shared<HeightSpanSolver>());
  registry.add(std::make_shared<LiggghtsDebrisSolver>());  // LiggghtsSolver, and terrain debris
  registry.add(std::make_shared<BulletSolver>());
  registry.add(std::make_shared<OdeSolver>());
  registry.add(std::make_shared<TearingSolver>());
  registry.add(std::make_shared<SnowSolver>());
  registry.add(std::make_shared<TerrainSolver>());
  registry.add(std::make_shared<InitialSolver>());
  return registry;
}

}  // namespace

const SolverRegistry& solver_registry() {
  static const SolverRegistry registry = make_registry();
  return registry;
}

}  // namespace repose
