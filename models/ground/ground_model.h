#pragma once
// The ground model's fixed description, built once from a Scene (as MuJoCo
// compiles mjModel): the grid, which material lies on each cell, the objects
// and how they move, and the model options. Nothing here changes while the
// model runs; the changing part is GroundState, the fitted part GroundParams.

#include <cstdint>
#include <string>
#include <vector>

#include "models/core/geometry/grid.h"
#include "models/ground/ground_section.h"
#include "models/ground/material.h"
#include "models/core/config/scene.h"
#include "models/ground/swept_mesh.h"

namespace repose {

struct GroundModel {
  Grid grid;
  // materials[0] is the ground's material, materials[r + 1] region r's.
  std::vector<Material> materials;
  // ny * nx, row-major: index into materials for each cell (later regions win).
  std::vector<std::uint8_t> material_index;
  std::vector<ObjectSpec> objects;
  // Per object: its body's edge adjacency and face normals, so that a swept
  // mesh costs a copy per step, not a hash map (swept_mesh.h).
  std::vector<SweptBody> swept_bodies;
  GroundModelSpec options;
  FreeBodySpec free_bodies;  // how ODE drives objects with dynamic: (free_body_drive.h)
  TimeSpec time;
  std::optional<CameraSpec> camera;

  std::int64_t cell(int i, int j) const { return static_cast<std::int64_t>(j) * grid.nx + i; }
  int material_at(std::int64_t cell_index) const { return material_index[static_cast<std::size_t>(cell_index)]; }
};

// The scene's ground-model section gives the options and the materials
// (ground_section.h; its reader has checked them). Throws FieldError for
// options changed in code that break validate(GroundModelSpec) or
// validate(FreeBodySpec). Free bodies (dynamic:) are kept: ODE drives them
// (free_body_drive.h); InputError naming one ODE cannot drive here.
GroundModel build_ground_model(const Scene& scene);

// False, with why (the object and what to do), when the scene has a free
// body: for the models built on the ground model that cannot move one.
bool keyframed_objects_only(const Scene& scene, std::string* why);

// A model of a grid alone (no objects), all cells of one material: for
// tests and the coarse patches of the multi-resolution stage.
GroundModel make_plain_ground_model(const Grid& grid, const Material& material, const GroundModelSpec& options = {});

}  // namespace repose
