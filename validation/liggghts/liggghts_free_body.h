#pragma once
// Free bodies (models/core/config/dynamic_body.h) in a LIGGGHTS run: a free
// sphere is one more granular atom among the grains, of its own diameter and
// density, created at its initial position and velocity after the bed is
// read (`create_atoms 1 single`, `set ... diameter density`), integrated
// with the grains' nve/sphere and meeting grains and walls by the grains'
// contact law (atom type 1: the grains' material). The grains are the static
// group `grains` made before it exists, which the dumps keep to.
//
// Only spheres move freely here: LIGGGHTS-PUBLIC 3.8 moves meshes only
// kinematically (fix move/mesh; the free 6-DOF mesh is a premium feature),
// so a free box, cylinder, capsule or mesh is refused. What would stand in
// for one is a clump of spheres (fix multisphere / particletemplate
// multisphere, documented in this build), not built here.
//
// Each body's state is printed every kFreeBodyPrintInterval_s to
// free_body_NAME.txt (step x y z vx vy vz fx fy fz wx wy wz); the contact
// force is the printed total force plus the body's weight (gravity along -z).

#include <string>
#include <vector>

#include "models/core/config/scene.h"
#include "validation/particles/dem_section.h"
#include "validation/particles/free_body_track.h"

namespace repose {

inline constexpr double kFreeBodyPrintInterval_s = 1.0e-4;

// Throws InputError naming the object when a free body is not a sphere
// (uniformly scaled): "LIGGGHTS: objects[K] 'NAME' is a free box: ...".
void check_liggghts_free_bodies(const Scene& scene);

// The highest point a free sphere reaches from its start (its centre plus
// radius, plus the rise its initial upward speed gives).
double free_sphere_top_m(const ObjectSpec& object, double gravity_m_s2);

// The dump group: "grains" when the scene has free bodies, else "all".
std::string liggghts_dump_group(const Scene& scene);

// The commands that make the grains' group and create, size, launch and
// print each free sphere; empty without free bodies. After the box is final.
// Checks the free bodies first (check_liggghts_free_bodies).
std::string free_sphere_commands(const Scene& scene, const DemSpec& dem);

// Each free body's printed states as a track (scene order of the free bodies).
// Throws InputError when a print file is missing or malformed.
std::vector<FreeBodyTrack> read_liggghts_free_bodies(const Scene& scene, const DemSpec& dem, const std::string& run_dir);

}  // namespace repose
