#include "experiments/debris/debris_render.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <set>
#include <sstream>
#include <utility>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "models/core/base/error.h"
#include "models/core/geometry/triangle_mesh.h"
#include "models/core/io/mesh_io.h"
#include "models/core/io/npy_io.h"
#include "models/core/run/output_directory.h"
#include "validation/liggghts_debris/liggghts_debris_script.h"

namespace repose {

namespace fs = std::filesystem;

void DebrisRenderOptions::validate() const {
  auto fail = [](const std::string& what) { throw InputError("debris render: " + what); };
  if (frames < 1) fail("frames must be >= 1");
  if (width_px < 1 || height_px < 1) fail("width_px and height_px must be >= 1");
  if (!(elevation_deg > 0.0 && elevation_deg < 90.0)) fail("elevation_deg must lie in (0, 90)");
  if (!std::isfinite(azimuth_deg)) fail("azimuth_deg must be finite");
  if (!(margin_m >= 0.0 && std::isfinite(margin_m))) fail("margin_m must be >= 0");
  if (sphere_segments < 3 || sphere_segments > 16) fail("sphere_segments must lie in 3..16");
  if (!(moved_threshold_m > 0.0)) fail("moved_threshold_m must be > 0");
}

namespace {

std::vector<double> front_times(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: missing or unreadable (the frames' times)", path.string()));
  std::string line;
  std::getline(in, line);
  if (line.rfind("time_s,", 0) != 0) throw InputError(fmt::format("{}: expected a header starting time_s", path.string()));
  std::vector<double> times;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    try {
      times.push_back(std::stod(line.substr(0, line.find(','))));
    } catch (const std::exception&) {
      throw InputError(fmt::format("{}: line {}: expected a time in s", path.string(), times.size() + 2));
    }
  }
  return times;
}

std::vector<DebrisPart> read_parts(const fs::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: missing or unreadable", path.string()));
  std::vector<DebrisPart> parts;
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    for (const auto& p : j.at("parts")) {
      DebrisPart part;
      const auto& hull = p.at("hull_m");
      if (hull.size() < 6 || hull.size() % 2 != 0) throw InputError("a hull needs 2n >= 6 vertices");
      part.hull_m.resize(static_cast<Eigen::Index>(hull.size()), 3);
      for (std::size_t v = 0; v < hull.size(); ++v) {
        for (int c = 0; c < 3; ++c) part.hull_m(static_cast<Eigen::Index>(v), c) = hull.at(v).at(c).get<double>();
      }
      part.building = p.at("building").get<int>();
      parts.push_back(std::move(part));
    }
  } catch (const std::exception& e) {
    throw InputError(fmt::format("{}: not a debris run's parts ({})", path.string(), e.what()));
  }
  return parts;
}

DebrisRenderFrame read_frame(const fs::path& dir, int k, double time_s, std::size_t part_count) {
  DebrisRenderFrame f;
  f.time_s = time_s;
  const fs::path e = dir / fmt::format("frames/elements_{:03d}.npy", k), p = dir / fmt::format("frames/parts_{:03d}.npy", k);
  const ArrayXXdR elements = read_npy_2d(e.string());
  if (elements.size() > 0 && elements.cols() != 4) throw InputError(fmt::format("{}: expected 4 columns (x y z r)", e.string()));
  f.elements = elements.matrix();
  if (f.elements.rows() == 0) f.elements.resize(0, 4);
  const ArrayXXdR poses = part_count == 0 ? ArrayXXdR(0, 7) : read_npy_2d(p.string());
  if (static_cast<std::size_t>(poses.rows()) != part_count || (part_count > 0 && poses.cols() != 7)) {
    throw InputError(fmt::format("{}: expected {} rows of x y z qw qx qy qz (parts.json's parts)", p.string(), part_count));
  }
  for (Eigen::Index r = 0; r < poses.rows(); ++r) {
    Pose pose;
    pose.position_m = Eigen::Vector3d(poses(r, 0), poses(r, 1), poses(r, 2));
    pose.orientation = Eigen::Quaterniond(poses(r, 3), poses(r, 4), poses(r, 5), poses(r, 6)).normalized();
    f.parts.push_back(pose);
  }
  return f;
}

Eigen::Vector3d ramp(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi, double s) {
  return lo + std::clamp(s, 0.0, 1.0) * (hi - lo);
}

ColouredMesh terrain_mesh(const TriangleMesh& terrain, const DebrisRenderOptions& o) {
  ColouredMesh m{terrain, {}};
  const double lo = terrain.V.rows() > 0 ? terrain.V.col(2).minCoeff() : 0.0;
  const double hi = terrain.V.rows() > 0 ? terrain.V.col(2).maxCoeff() : 0.0;
  for (Eigen::Index v = 0; v < terrain.V.rows(); ++v) {
    m.vertex_rgb.push_back(ramp(o.terrain_low_rgb, o.terrain_high_rgb, hi > lo ? (terrain.V(v, 2) - lo) / (hi - lo) : 0.5));
  }
  return m;
}

ColouredMesh element_meshes(const DebrisRenderFrame& f, double r_lo, double r_hi, const DebrisRenderOptions& o) {
  const TriangleMesh unit = make_sphere(1.0, o.sphere_segments);
  const auto n = f.elements.rows();
  ColouredMesh m;
  m.mesh.V.resize(n * unit.V.rows(), 3);
  m.mesh.F.resize(n * unit.F.rows(), 3);
  for (Eigen::Index e = 0; e < n; ++e) {
    const Eigen::RowVector3d centre = f.elements.block<1, 3>(e, 0);
    const double r = f.elements(e, 3);
    m.mesh.V.middleRows(e * unit.V.rows(), unit.V.rows()) = (unit.V * r).rowwise() + centre;
    m.mesh.F.middleRows(e * unit.F.rows(), unit.F.rows()) = unit.F.array() + static_cast<int>(e * unit.V.rows());
    const Eigen::Vector3d rgb = ramp(o.element_small_rgb, o.element_large_rgb, r_hi > r_lo ? (r - r_lo) / (r_hi - r_lo) : 1.0);
    for (Eigen::Index v = 0; v < unit.V.rows(); ++v) m.vertex_rgb.push_back(rgb);
  }
  return m;
}

// Every part posed, flat (each triangle its own vertices), coloured by whether it moved since frame 0.
ColouredMesh part_meshes(const DebrisRunFrames& run, int k, const DebrisRenderOptions& o) {
  ColouredMesh m;
  std::vector<Eigen::RowVector3d> vertices;
  const DebrisRenderFrame& f = run.frames[static_cast<std::size_t>(k)];
  const DebrisRenderFrame& first = run.frames.front();
  for (std::size_t p = 0; p < run.parts.size(); ++p) {
    const TriangleMesh posed = transformed(part_mesh(run.parts[p]), f.parts[p]);
    const bool moved = (f.parts[p].position_m - first.parts[p].position_m).norm() > o.moved_threshold_m;
    for (Eigen::Index t = 0; t < posed.F.rows(); ++t) {
      for (int c = 0; c < 3; ++c) {
        vertices.push_back(posed.V.row(posed.F(t, c)));
        m.vertex_rgb.push_back(moved ? o.moved_part_rgb : o.part_rgb);
      }
    }
  }
  m.mesh.V.resize(static_cast<Eigen::Index>(vertices.size()), 3);
  m.mesh.F.resize(static_cast<Eigen::Index>(vertices.size() / 3), 3);
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    m.mesh.V.row(static_cast<Eigen::Index>(i)) = vertices[i];
    m.mesh.F(static_cast<Eigen::Index>(i / 3), static_cast<Eigen::Index>(i % 3)) = static_cast<int>(i);
  }
  return m;
}

// The camera moved towards its target as far as the box's eight corners
// stay inside the image (camera_around holds the box's bounding sphere,
// which leaves a flat box small in the picture).
CameraSpec closer_while_in_view(const CameraSpec& camera, const Aabb& box) {
  const auto in_view = [&](const CameraSpec& c) {
    for (int k = 0; k < 8; ++k) {
      const Eigen::Vector3d corner((k & 1) ? box.max.x() : box.min.x(), (k & 2) ? box.max.y() : box.min.y(),
                                   (k & 4) ? box.max.z() : box.min.z());
      const auto uv = project_to_image(c, corner);
      if (!uv || uv->x() < 0 || uv->y() < 0 || uv->x() > c.width_px || uv->y() > c.height_px) return false;
    }
    return true;
  };
  CameraSpec best = camera;
  for (double f = 0.95; f > 0.2; f -= 0.05) {
    CameraSpec c = camera;
    c.position_m = camera.target_m + f * (camera.position_m - camera.target_m);
    if (!in_view(c)) break;
    best = c;
  }
  return best;
}

}  // namespace

DebrisRunFrames read_debris_run_frames(const std::string& run_dir) {
  const fs::path dir(run_dir);
  if (!fs::is_directory(dir)) throw InputError(fmt::format("{}: not a folder (expected a debris run's)", run_dir));
  DebrisRunFrames run;
  run.terrain = read_mesh((dir / "terrain.obj").string());
  run.parts = read_parts(dir / "parts.json");
  const std::vector<double> times = front_times(dir / "front.csv");
  if (times.empty()) throw InputError(fmt::format("{}: no frames", (dir / "front.csv").string()));
  for (std::size_t k = 0; k < times.size(); ++k) {
    run.frames.push_back(read_frame(dir, static_cast<int>(k), times[k], run.parts.size()));
  }
  return run;
}

std::vector<int> picked_frames(int count, int wanted) {
  std::set<int> picks;
  if (count <= 0) return {};
  for (int i = 0; i < wanted; ++i) {
    picks.insert(wanted == 1 ? count - 1 : static_cast<int>(std::lround(static_cast<double>(i) * (count - 1) / (wanted - 1))));
  }
  return {picks.begin(), picks.end()};
}

CameraSpec debris_camera(const DebrisRunFrames& run, const std::vector<int>& picks, const DebrisRenderOptions& o) {
  o.validate();
  Aabb box;
  for (int k : picks) {
    const DebrisRenderFrame& f = run.frames.at(static_cast<std::size_t>(k));
    for (Eigen::Index e = 0; e < f.elements.rows(); ++e) {
      const Eigen::Vector3d c = f.elements.block<1, 3>(e, 0).transpose();
      box.extend(c - Eigen::Vector3d::Constant(f.elements(e, 3)));
      box.extend(c + Eigen::Vector3d::Constant(f.elements(e, 3)));
    }
    for (std::size_t p = 0; p < run.parts.size(); ++p) {
      const Aabb b = bounding_box(transformed(part_mesh(run.parts[p]), f.parts[p]));
      box.extend(b.min);
      box.extend(b.max);
    }
  }
  if (box.empty()) box = bounding_box(run.terrain);
  box.min -= Eigen::Vector3d::Constant(o.margin_m);
  box.max += Eigen::Vector3d::Constant(o.margin_m);
  const double az = o.azimuth_deg * std::numbers::pi / 180, el = o.elevation_deg * std::numbers::pi / 180;
  const Eigen::Vector3d from(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  return closer_while_in_view(camera_around(box, from, o.width_px, o.height_px), box);
}

RgbImage render_debris_frame(const DebrisRunFrames& run, int k, const CameraSpec& camera,
                             const DebrisRenderOptions& o) {
  o.validate();
  if (k < 0 || static_cast<std::size_t>(k) >= run.frames.size()) {
    throw InputError(fmt::format("debris render: frame {} of a run of {} frames", k, run.frames.size()));
  }
  double r_lo = 0.0, r_hi = 0.0;
  const auto& e0 = run.frames.front().elements;
  if (e0.rows() > 0) {
    r_lo = e0.col(3).minCoeff();
    r_hi = e0.col(3).maxCoeff();
  }
  const DebrisRenderFrame& f = run.frames[static_cast<std::size_t>(k)];
  std::vector<ColouredMesh> meshes = {terrain_mesh(run.terrain, o), element_meshes(f, r_lo, r_hi, o),
                                      part_meshes(run, k, o)};
  return render_coloured_meshes(meshes, camera, o.image);
}

std::vector<std::string> write_debris_renders(const std::string& run_dir, const std::string& png_prefix,
                                              const DebrisRenderOptions& o) {
  o.validate();
  const DebrisRunFrames run = read_debris_run_frames(run_dir);
  const std::vector<int> picks = picked_frames(static_cast<int>(run.frames.size()), o.frames);
  const CameraSpec camera = debris_camera(run, picks, o);
  std::vector<std::string> written;
  for (int k : picks) {
    const RgbImage image = render_debris_frame(run, k, camera, o);
    const std::string path = fmt::format("{}_{:03d}.png", png_prefix, k);
    write_file_atomically(path, [&](const std::string& temporary) { write_png_rgb(temporary, image); });
    written.push_back(path);
  }
  return written;
}

}  // namespace repose
