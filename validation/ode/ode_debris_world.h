#pragma once
// A DebrisWorld (validation/rigid/debris_world.h) in ODE 0.16, double
// precision: the terrain a static dTriMesh, elements spheres, building parts
// dConvex prisms (convex against the terrain mesh through libccd, which
// Debian's ODE is built with; inertia of the hull's box), joints fixed
// joints (to the static environment for the ground) whose feedback force is
// read after every step; a joint whose force exceeded its break_force_n is
// destroyed. Parts joined by a live joint do not collide.
//
// ODE's CFM is an absolute compliance, and the ode: section's cfm was
// measured on 2 mm grains (ode_options.h); bodies of tonnes would sink
// into contacts that soft. Every contact and joint here is as stiff
// relative to its lighter body's mass as a grain's contact there:
// CFM = cfm x (kOdeCfmReferenceMassKg / lighter mass).

#include <memory>

#include "validation/ode/ode_options.h"
#include "validation/rigid/debris_world.h"

namespace repose {

// The mass (kg) of a 2 mm-radius grain of 2,500 kg/m^3, at which ode.cfm was measured.
inline constexpr double kOdeCfmReferenceMassKg = 8.4e-5;

// Throws InputError when the options break their rules.
std::unique_ptr<DebrisWorld> make_ode_debris_world(const DebrisWorldSpec& spec, const OdeOptions& options);

}  // namespace repose
