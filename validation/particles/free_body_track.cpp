#include "validation/particles/free_body_track.h"

#include <algorithm>
#include <fstream>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

std::vector<FreeBodyTrack> start_free_body_tracks(const std::vector<ObjectSpec>& bodies) {
  std::vector<FreeBodyTrack> tracks;
  for (const ObjectSpec& o : bodies) {
    REPOSE_DEMAND(o.dynamic.has_value());
    tracks.push_back({o.name, o.mass_kg(), {}});
  }
  return tracks;
}

void record_free_bodies(std::vector<FreeBodyTrack>& tracks, double time_s, const std::vector<FreeBodyState>& states,
                        double gravity_m_s2) {
  REPOSE_DEMAND(tracks.size() == states.size());
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    FreeBodySample s{time_s, states[k], Eigen::Vector3d::Zero()};
    if (!tracks[k].samples.empty()) {
      const FreeBodySample& before = tracks[k].samples.back();
      const double dt = time_s - before.time_s;
      REPOSE_DEMAND(dt > 0.0);
      s.contact_force_n = tracks[k].mass_kg * ((s.state.velocity_m_s - before.state.velocity_m_s) / dt +
                                               Eigen::Vector3d(0, 0, gravity_m_s2));
    }
    tracks[k].samples.push_back(s);
  }
}

FreeBodyRest free_body_rest(const ObjectSpec& body, const FreeBodyTrack& track, const HeightField& surface_initial,
                            double gravity_m_s2, double window_s) {
  REPOSE_DEMAND(!track.samples.empty());
  const FreeBodySample& last = track.samples.back();
  FreeBodyRest r;
  r.position_m = last.state.pose.position_m;
  const TriangleMesh placed = transformed(body.body, last.state.pose);
  r.bottom_z_m = placed.V.col(2).minCoeff();
  r.surface_z_m = surface_initial.sample(r.position_m.x(), r.position_m.y());
  r.resting_depth_m = r.surface_z_m - r.bottom_z_m;
  r.final_speed_m_s = last.state.velocity_m_s.norm();
  r.weight_n = track.mass_kg * gravity_m_s2;
  int n = 0;
  for (std::size_t k = 1; k < track.samples.size(); ++k) {
    const FreeBodySample& s = track.samples[k];
    r.max_force_n = std::max(r.max_force_n, s.contact_force_n.norm());
    if (s.time_s > last.time_s - window_s) {
      r.resting_force_n += s.contact_force_n;
      ++n;
    }
  }
  if (n > 0) r.resting_force_n /= n;
  return r;
}

void write_free_body_csv(const std::string& path, const FreeBodyTrack& track) {
  std::ofstream out(path);
  out << "time_s,x_m,y_m,z_m,qw,qx,qy,qz,vx_m_s,vy_m_s,vz_m_s,wx_rad_s,wy_rad_s,wz_rad_s,fx_n,fy_n,fz_n\n";
  for (const FreeBodySample& s : track.samples) {
    const Eigen::Vector3d& p = s.state.pose.position_m;
    const Eigen::Quaterniond& q = s.state.pose.orientation;
    const Eigen::Vector3d& v = s.state.velocity_m_s;
    const Eigen::Vector3d& w = s.state.angular_velocity_rad_s;
    const Eigen::Vector3d& f = s.contact_force_n;
    out << fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", s.time_s, p.x(), p.y(), p.z(), q.w(),
                       q.x(), q.y(), q.z(), v.x(), v.y(), v.z(), w.x(), w.y(), w.z(), f.x(), f.y(), f.z());
  }
  if (!out) throw std::runtime_error(fmt::format("{}: write failed", path));
}

nlohmann::json free_bodies_json(const std::vector<FreeBodyTrack>& tracks, const std::vector<FreeBodyRest>& rests) {
  REPOSE_DEMAND(tracks.size() == rests.size());
  auto vec = [](const Eigen::Vector3d& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
  nlohmann::json json = nlohmann::json::object();
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    const FreeBodyRest& r = rests[k];
    json[tracks[k].name] = {{"mass_kg", tracks[k].mass_kg},
                            {"resting_depth_m", r.resting_depth_m},
                            {"bottom_z_m", r.bottom_z_m},
                            {"surface_z_m", r.surface_z_m},
                            {"final_position_m", vec(r.position_m)},
                            {"final_speed_m_s", r.final_speed_m_s},
                            {"resting_force_n", vec(r.resting_force_n)},
                            {"weight_n", r.weight_n},
                            {"max_force_n", r.max_force_n},
                            {"trajectory", fmt::format("free_body_{}.csv", tracks[k].name)}};
  }
  return json;
}

}  // namespace repose
