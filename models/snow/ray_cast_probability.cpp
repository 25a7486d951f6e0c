#include "models/snow/ray_cast_probability.h"

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/snow/shadow_map.h"

namespace repose {

namespace {

// The Embree device and scene of the occluders, released on scope exit.
class EmbreeScene {
 public:
  explicit EmbreeScene(const std::vector<TriangleMesh>& meshes) {
    device_ = rtcNewDevice("threads=1");
    if (device_ == nullptr) throw std::runtime_error(fmt::format("embree: rtcNewDevice failed ({})", 0));
    scene_ = rtcNewScene(device_);
    for (const TriangleMesh& m : meshes) {
      if (m.empty()) continue;
      RTCGeometry geom = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
      auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                            3 * sizeof(float), static_cast<size_t>(m.V.rows())));
      for (Eigen::Index k = 0; k < m.V.rows(); ++k) {
        for (int c = 0; c < 3; ++c) v[3 * k + c] = static_cast<float>(m.V(k, c));
      }
      auto* f = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                               3 * sizeof(unsigned), static_cast<size_t>(m.F.rows())));
      for (Eigen::Index k = 0; k < m.F.rows(); ++k) {
        for (int c = 0; c < 3; ++c) f[3 * k + c] = static_cast<unsigned>(m.F(k, c));
      }
      rtcCommitGeometry(geom);
      rtcAttachGeometry(scene_, geom);
      rtcReleaseGeometry(geom);
    }
    rtcCommitScene(scene_);
  }
  ~EmbreeScene() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // True when the ray from p along dir meets a triangle at t in (t_near, inf).
  bool occluded(const Eigen::Vector3d& p, const Eigen::Vector3d& dir, double t_near) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = static_cast<float>(p.x());
    ray.org_y = static_cast<float>(p.y());
    ray.org_z = static_cast<float>(p.z());
    ray.dir_x = static_cast<float>(dir.x());
    ray.dir_y = static_cast<float>(dir.y());
    ray.dir_z = static_cast<float>(dir.z());
    ray.tnear = static_cast<float>(t_near);
    ray.tfar = std::numeric_limits<float>::infinity();
    ray.mask = 0xFFFFFFFFu;
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
  }

 private:
  RTCDevice device_ = nullptr;
  RTCScene scene_ = nullptr;
};

}  // namespace

SnowProbability snow_probability_ray_cast(const SnowModel& model, const std::vector<Eigen::Vector3d>& directions) {
  const EmbreeScene scene(model.occluders);
  const Grid& g = model.grid;
  SnowProbability p;
  p.direction_count = static_cast<int>(directions.size());
  p.per_map.assign(model.maps.size(), ArrayXXdR::Zero(g.ny, g.nx));
  std::vector<double> bias(directions.size());
  for (std::size_t d = 0; d < directions.size(); ++d) {
    bias[d] = shadow_bias_m(directions[d], shadow_pixel_m(model), model.options.shadow_bias_cells);
  }
  const double n = std::max<std::size_t>(1, directions.size());
  for (std::size_t m = 0; m < model.maps.size(); ++m) {
    const SnowMap& map = model.maps[m];
    for (int j = 0; j < g.ny; ++j) {
      for (int i = 0; i < g.nx; ++i) {
        if (!map.covered(i, j)) continue;
        const Eigen::Vector3d point(g.centre_x(i), g.centre_y(j), map.base_z(i, j));
        int lit = 0;
        for (std::size_t d = 0; d < directions.size(); ++d) {
          if (!scene.occluded(point, -directions[d].normalized(), bias[d])) ++lit;
        }
        p.per_map[m](j, i) = lit / n;
      }
    }
  }
  return p;
}

}  // namespace repose
