#include "models/ground/ground_step.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "models/core/base/error.h"
#include "models/core/geometry/faces_turned.h"
#include "models/ground/coarse_contact.h"
#include "models/ground/displacement.h"
#include "models/ground/ground_model.h"
#include "models/ground/ground_params.h"
#include "models/ground/ground_state.h"
#include "models/ground/substep_count.h"
#include "models/ground/swept_mesh.h"

namespace repose {

namespace {

// The highest point of an object at a pose: the crest of the heaps it
// pushes up (excess_routing.h). A swept mesh reaches higher (the start of a
// press from above), but the object is where the step ends.
double top_at(const ObjectSpec& object, const Pose& pose) {
  const Eigen::Vector3d up = pose.orientation.conjugate() * Eigen::Vector3d::UnitZ();
  return (object.body.V * up).maxCoeff() + pose.position_m.z();
}

// Translation below this (per substep) is not swept: the body alone is the same.
bool moved(const Pose& a, const Pose& b, double cell_size_m) {
  return (b.position_m - a.position_m).norm() > 1e-6 * cell_size_m;
}

// Objects whose footprints touch or overlap share one contact region (as
// they share one Z-buffer in the paper), so one object's displaced material
// is never pushed under another: clusters of touching footprints.
std::vector<std::vector<std::size_t>> touching_clusters(const std::vector<Underside>& undersides) {
  const std::size_t n = undersides.size();
  std::vector<std::size_t> parent(n);
  for (std::size_t k = 0; k < n; ++k) parent[k] = k;
  auto root = [&](std::size_t k) {
    while (parent[k] != k) k = parent[k] = parent[parent[k]];
    return k;
  };
  auto touch = [](const Footprint& a, const Footprint& b) {
    return a.i0 <= b.i0 + b.ni && b.i0 <= a.i0 + a.ni && a.j0 <= b.j0 + b.nj && b.j0 <= a.j0 + a.nj;
  };
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      if (!undersides[a].empty() && !undersides[b].empty() && touch(undersides[a].footprint, undersides[b].footprint)) {
        parent[root(b)] = root(a);
      }
    }
  }
  std::vector<std::vector<std::size_t>> clusters(n);
  for (std::size_t k = 0; k < n; ++k) clusters[root(k)].push_back(k);
  std::erase_if(clusters, [](const auto& c) { return c.empty(); });
  return clusters;
}

// The lowest underside of several objects over the box around their footprints.
Underside merged_underside(const std::vector<Underside>& undersides, const std::vector<std::size_t>& members) {
  Footprint box = undersides[members[0]].footprint;
  for (const std::size_t m : members) box = bounding_box(box, undersides[m].footprint);
  Underside u;
  u.footprint = box;
  for (const std::size_t m : members) u.top_m = std::max(u.top_m, undersides[m].top_m);
  u.z_m.resize(box.nj, box.ni);
  for (int j = 0; j < box.nj; ++j) {
    for (int i = 0; i < box.ni; ++i) {
      double z = std::numeric_limits<double>::infinity();
      for (const std::size_t m : members) z = std::min(z, undersides[m].at(box.i0 + i, box.j0 + j));
      u.z_m(j, i) = z;
    }
  }
  return u;
}

// A fine object that touches nothing still bounds the ground under it:
// erosion raises a cell at most to the highest ground within max(En) cells
// (one ring per pass, sigma <= 1/4), and displacement may have deposited
// material under it. So, after displacement, an object whose lowest point is
// below the ground within that reach joins the ceiling in place of its empty
// contact (e.g. one lifted out of its own imprint), and material deposited
// above its underside is displaced as by any contact.
int add_hovering_undersides(const GroundModel& model, const GroundParams& params,
                            const std::vector<FacesDown>& faces_down, const std::vector<double>& tops,
                            const std::vector<char>& coarse,
                            const std::vector<Eigen::Vector3d>& motion, UndersideRenderer& renderer,
                            GroundState* state, Ceiling* ceiling) {
  int reach_cells = 0;  // beyond the grid's size it reaches nothing more (and cannot overflow)
  for (const Material& m : params.materials) reach_cells = std::max(reach_cells, m.erosion_passes(model.grid.cell_size_m));
  reach_cells = std::min(reach_cells, std::max(model.grid.nx, model.grid.ny));
  int contact_cells = 0;
  std::size_t fine = 0;  // ceiling->undersides holds the fine objects in order
  for (std::size_t o = 0; o < faces_down.size(); ++o) {
    if (coarse[o]) continue;
    const std::size_t k = fine++;
    if (!ceiling->undersides[k].empty()) continue;
    ceiling->undersides[k] = find_underside_of_faces_down(faces_down[o], state->height, renderer, reach_cells);
    if (ceiling->undersides[k].empty()) continue;
    ceiling->undersides[k].top_m = tops[o];
    const Underside u = ceiling->undersides[k];  // displace reads the ceiling too
    contact_cells += displace(model, params, u, *ceiling, motion[o], state).contact_cells;
  }
  return contact_cells;
}

// One substep: every object from `from` to `to`: collision, displacement
// (coarse objects on their patch, touching fine objects as one region),
// then erosion.
void substep(const GroundModel& model, const GroundParams& params, const std::vector<Pose>& from,
             const std::vector<Pose>& to, UndersideRenderer& renderer, GroundState* state, StepReport* report) {
  const std::size_t n_objects = model.objects.size();
  Ceiling ceiling;
  std::vector<FacesDown> faces_down(n_objects);
  std::vector<Eigen::Vector3d> motion(n_objects), fine_motion;
  std::vector<char> coarse(n_objects);
  std::vector<double> tops(n_objects);
  for (std::size_t o = 0; o < n_objects; ++o) {
    const ObjectSpec& object = model.objects[o];
    motion[o] = to[o].position_m - from[o].position_m;
    // the faces_down are only ever seen from below: their faces turned down,
    // made once; a vertical press or lift needs no silhouette (swept_mesh.h)
    if (model.options.sweep && moved(from[o], to[o], model.grid.cell_size_m)) {
      REPOSE_DEMAND(model.swept_bodies.size() == n_objects);
      const SweptBody& swept = model.swept_bodies[o];
      state->sweep_caches.resize(n_objects);
      faces_down[o] = is_vertical(motion[o]) ? vertical_sweep_faces_down(object.body, swept, from[o], to[o],
                                                                         &state->sweep_caches[o])
                                             : faces_down_of(swept_mesh(object.body, swept, from[o], to[o]));
      ++report->swept_objects;
    } else {
      faces_down[o] = faces_down_of(transformed(object.body, to[o]));
    }
    coarse[o] = uses_coarse_grid(model, static_cast<int>(o), to[o]);
    tops[o] = top_at(object, to[o]);
    if (!coarse[o]) {
      ceiling.undersides.push_back(find_underside_of_faces_down(faces_down[o], state->height, renderer));
      ceiling.undersides.back().top_m = tops[o];
      fine_motion.push_back(motion[o]);
    }
  }
  for (std::size_t o = 0; o < n_objects; ++o) {
    if (!coarse[o]) continue;
    report->contact_cells += deform_coarse(model, params, faces_down[o], motion[o], renderer, state).contact_cells;
    ++report->coarse_objects;
  }
  // a cluster of touching objects is displaced as one region, moving with their mean motion
  for (const std::vector<std::size_t>& cluster : touching_clusters(ceiling.undersides)) {
    Eigen::Vector3d mean_motion = Eigen::Vector3d::Zero();
    for (const std::size_t m : cluster) mean_motion += fine_motion[m] / static_cast<double>(cluster.size());
    const Underside merged = cluster.size() == 1 ? Underside{} : merged_underside(ceiling.undersides, cluster);
    const Underside& u = cluster.size() == 1 ? ceiling.undersides[cluster[0]] : merged;
    report->contact_cells += displace(model, params, u, ceiling, mean_motion, state).contact_cells;
  }
  report->contact_cells +=
      add_hovering_undersides(model, params, faces_down, tops, coarse, motion, renderer, state, &ceiling);
  const ErosionResult e = erode(model, params, ceiling, state);
  report->erosion.passes += e.passes;
  report->erosion.pair_visits += e.pair_visits;
  report->erosion.moves += e.moves;
}

}  // namespace

bool uses_coarse_grid(const GroundModel& model, int object, const Pose& pose) {
  if (model.options.coarse_factor <= 1) return false;
  if (model.objects[static_cast<std::size_t>(object)].simple) return true;
  return model.options.far_distance_m > 0.0 && model.camera &&
         (pose.position_m - model.camera->position_m).norm() > model.options.far_distance_m;
}

StepReport step(const GroundModel& model, const GroundParams& params, UndersideRenderer& renderer,
                GroundState* state) {
  StepReport report;
  const double dt = model.time.step_s;
  const double t0 = state->step_index * dt;  // not accumulated: no drift over many steps
  const std::size_t n_objects = model.objects.size();
  std::vector<Pose> end_poses(n_objects);
  for (std::size_t o = 0; o < n_objects; ++o) end_poses[o] = model.objects[o].pose_at(t0 + dt);
  const int substeps = substep_count(model, state->previous_poses, end_poses, state->step_index);
  report.substeps = substeps;

  std::vector<Pose> poses = state->previous_poses;
  for (int s = 1; s <= substeps; ++s) {
    std::vector<Pose> to(n_objects);
    for (std::size_t o = 0; o < n_objects; ++o) {
      to[o] = s == substeps ? end_poses[o] : model.objects[o].pose_at(t0 + dt * s / substeps);
    }
    substep(model, params, poses, to, renderer, state, &report);
    poses = to;
  }
  // a remembered cell is forgotten once its time is up and its slopes have settled (erosion_memory.h)
  const std::vector<double> max_dh = max_height_differences(model, params);
  state->erosion.end_step([&](std::int64_t c) { return is_settled(model, max_dh, state->height, c); });
  state->previous_poses = end_poses;
  ++state->step_index;
  state->time_s = state->step_index * dt;
  return report;
}

}  // namespace repose
