#pragma once
// A RigidWorld (validation/rigid/rigid_world.h) in ODE 0.16 (double
// precision): grains are sphere geoms on bodies, the ground box static box
// geoms, objects kinematic bodies (ODE primitives, or dTriMesh for meshes)
// given each step the velocity that carries them to their next pose, and
// snapped exactly onto it after the step (no drift from integrating the
// rotation). QuickStep solver, dHashSpace with levels from the grain size
// (2^min about one grain diameter, 2^(min+4) above; the default levels are
// 1.3-2.7x slower), auto-disable off.
// Free bodies (spec.bodies) are dynamic bodies with their geom (a mesh as
// dTriMesh, its origin taken as its centre of mass), ODE's exact mass for
// the primitives and a box's of the mesh's bounds; they meet grains, walls,
// objects and each other (rolling resistance only against grains).
//
// Contacts take the pair values rigid_world.h states: dContactApprox1 makes
// mu and the rolling rho coefficients of the normal force (without it they
// are absolute force limits), dContactAxisDep keeps rho for rolling only
// (rhoN = 0: no spin resistance, as cdt), rho = mu_r * r_eff (m).
//
// QuickStep reorders constraints with ODE's global random generator: each
// world keeps its own seed (set before and read back after each step), so
// runs repeat bit-identically even when several worlds exist in one process.

#include <memory>
#include <string>

#include "validation/ode/ode_options.h"
#include "validation/rigid/rigid_world.h"

namespace repose {

// "ODE 0.16.2 (double)".
std::string ode_version();

// Throws InputError when the options break their rules.
std::unique_ptr<RigidWorld> make_ode_world(const RigidWorldSpec& spec, const OdeOptions& options);

}  // namespace repose
