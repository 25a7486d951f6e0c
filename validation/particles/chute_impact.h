#pragma once
// The impact of a granular flow down a chute on a wall at its foot, measured
// alike for every particle reference (LIGGGHTS, Bullet, ODE) from grain sets
// with velocities and the wall's force over time. The chute is bed-aligned
// (dem_section.h: x down the slope, z normal to the floor, gravity tilted by
// the slope); the wall is the scene's first object.
//
// The incoming flow, per frame, over the grains whose centres lie in a
// window upstream of the wall (x in [window_x_min_m, window_x_max_m], the
// chute's whole width w):
//   mass per area  m_A = (sum of the grains' masses) / (window length * w)
//   depth          h   = the depth_quantile of the grains' tops (z + r)
//   speed          v   = the mass-weighted mean of the grains' x velocity
//   bulk density   rho = m_A / h
// The wall: F, the x component of the force on it (the flow pushes it down
// the slope), averaged over force_smoothing_s about the time the window's
// middle reaches the wall at speed v (frame time + distance / v).
//   pressure             p  = F / (w h)
//   Froude number        Fr = v / sqrt(g h cos slope)
//   pressure coefficient C  = p / (rho v^2) = F / (w m_A v^2)
// The hydrostatic + dynamic design form p = 1/2 k rho g h cos(slope) +
// alpha rho v^2 (k ~ 1, alpha ~ 1-2 in the design literature; see
// experiments/dem_chute.yaml for the sources) reads C = alpha + k / (2 Fr^2).
//
// The impact phase: the frames in which the window holds at least
// min_grains grains moving at flowing_speed_fraction of the window's largest
// speed or faster, once the wall has been reached (a force above zero
// later). Means are over those frames; the peak is the largest smoothed
// force while they arrive (from the first impact-phase frame to the last
// one's arrival at the wall), with the flow of the last impact-phase frame
// at or before it. The deposit that backs up behind the wall afterwards
// loads it statically: its force at the end of the run is final_force_n.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "models/core/config/scene.h"
#include "validation/particles/dem_section.h"
#include "validation/particles/grain_set.h"

namespace repose {

struct ChuteGeometry {
  double slope_rad = 0.0;
  double gravity_m_s2 = 9.81;
  double density_kg_m3 = 2500.0;  // of the grains
  double wall_face_x_m = 0.0;     // the wall's upstream face (its smallest x at t = 0)
  double width_m = 0.0;           // w: the chute's width the wall spans
  double window_x_min_m = 0.0;
  double window_x_max_m = 0.0;
};

// From the scene: dem.slope_deg, the impact window, the first object as the
// wall (its smallest x at pose_at(0)), the grid's y extent as w (narrowed to
// the wall's own y extent if it is narrower). InputError when the scene
// measures no impact, or the window leaves the grid.
ChuteGeometry chute_geometry(const Scene& scene);
ChuteGeometry chute_geometry(const DemSpec& dem, const Scene& scene);

// How high (normal to the floor) grains may splash up a wall at the foot of
// the chute: with no losses they rise at most as far as they fell, the
// settled height plus the grid's length times tan(slope); half as much again
// for grains thrown up by others. 0 on a level floor.
double chute_splash_top_m(const DemSpec& dem, const Grid& grid);

struct ChuteImpactOptions {
  double depth_quantile = 0.95;          // of the grains' tops: the flow depth (0, 1]
  double force_smoothing_s = 0.01;       // the force is averaged over this window
  double flowing_speed_fraction = 0.5;   // impact-phase frames move at least this fraction of the largest speed
  long min_grains = 3;                   // impact-phase frames hold at least this many grains in the window
};

struct ChuteFlow {
  long grains = 0;
  double mass_per_area_kg_m2 = 0.0;
  double depth_m = 0.0;    // 0 with no grains
  double speed_m_s = 0.0;  // 0 with no grains
};

// The flow in the window (InputError when the grains have no velocities).
ChuteFlow window_flow(const GrainSet& grains, const ChuteGeometry& geometry, const ChuteImpactOptions& options = {});

// Fr = v / sqrt(g h cos slope).
double froude_number(double speed_m_s, double depth_m, double gravity_m_s2, double slope_rad);
// C = p / (rho v^2).
double pressure_coefficient(double pressure_pa, double density_kg_m3, double speed_m_s);
// The design form's C = alpha + k / (2 Fr^2).
double design_pressure_coefficient(double froude, double k, double alpha);

struct ChuteFrame {
  double time_s = 0.0;
  ChuteFlow flow;
  double force_n = 0.0;   // smoothed, at the time the window's flow reaches the wall
  bool impact = false;    // in the impact phase
};

// Numbers of one state of the flow against the wall.
struct ChuteLoad {
  double time_s = 0.0;
  double force_n = 0.0;
  double depth_m = 0.0;
  double speed_m_s = 0.0;
  double mass_per_area_kg_m2 = 0.0;
  double bulk_density_kg_m3 = 0.0;  // m_A / h
  double pressure_pa = 0.0;         // F / (w h)
  double froude = 0.0;
  double coefficient = 0.0;         // p / (rho v^2)
};

struct ChuteImpact {
  ChuteGeometry geometry;
  std::vector<ChuteFrame> frames;
  long impact_frame_count = 0;
  ChuteLoad peak;  // the largest smoothed force and the flow before it
  ChuteLoad mean;  // means of F, h, v, m_A over the impact phase, and what they give
  double front_arrival_s = -1.0;  // the first frame with grains in the window (-1: never)
  double final_force_n = 0.0;     // smoothed, at the last force sample (the deposit at rest)
};

// The load of force F on the wall under a flow (m_A, h, v).
ChuteLoad chute_load(const ChuteGeometry& geometry, double time_s, double force_n, const ChuteFlow& flow);

// frames: grain sets with velocities at frame_time_s; the wall's force as
// samples (force_time_s ascending, force_x_n its x component). InputError for
// no frames, no force samples or a flow that never reaches the window.
ChuteImpact measure_chute_impact(const ChuteGeometry& geometry, const std::vector<GrainSet>& frames,
                                 const std::vector<double>& frame_time_s, const std::vector<double>& force_time_s,
                                 const std::vector<double>& force_x_n, const ChuteImpactOptions& options = {});

// CSV: time_s, grains, mass_per_area_kg_m2, depth_m, speed_m_s, force_n,
// pressure_pa, froude, coefficient, impact (0/1), one row per frame.
void write_chute_impact_csv(const std::string& path, const ChuteImpact& impact);

// JSON member "chute" (left out when absent): slope, window, peak and mean loads.
nlohmann::json chute_results_json(const std::optional<ChuteImpact>& impact);

}  // namespace repose
