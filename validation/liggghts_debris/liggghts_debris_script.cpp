#include "validation/liggghts_debris/liggghts_debris_script.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/io/mesh_io.h"
#include "validation/liggghts/liggghts_motion.h"
#include "validation/liggghts/liggghts_script.h"

namespace repose {

namespace {

std::string n(double v) { return liggghts_number(v); }

// An element material: one atom type.
struct Material {
  double friction = 0, restitution = 0, rolling = 0;
  auto key() const { return std::tie(friction, restitution, rolling); }
};

std::vector<Material> element_materials(const DebrisWorldSpec& spec, std::vector<int>* type_of) {
  std::vector<Material> out;
  for (const DebrisElement& e : spec.elements) {
    const Material m{e.friction, e.restitution, e.rolling_friction};
    if (!(m.restitution > 0.05)) {
      throw InputError(fmt::format("terrain: elements: layers: restitution = {} must be > 0.05 for LIGGGHTS", m.restitution));
    }
    auto it = std::find_if(out.begin(), out.end(), [&](const Material& o) { return o.key() == m.key(); });
    if (it == out.end()) it = out.insert(out.end(), m);
    type_of->push_back(2 + static_cast<int>(it - out.begin()));
  }
  return out;
}

// The pair table (types 1 = walls, 2.. = materials) of one value.
std::string pair_table(const std::vector<Material>& m, double wall_value, double Material::*field) {
  const std::size_t types = m.size() + 1;
  std::string s = std::to_string(types);
  for (std::size_t i = 0; i < types; ++i) {
    for (std::size_t j = 0; j < types; ++j) {
      const double v = i == 0 && j == 0 ? wall_value
                       : i == 0         ? m[j - 1].*field
                       : j == 0         ? m[i - 1].*field
                                        : 0.5 * (m[i - 1].*field + m[j - 1].*field);
      s.append(" ").append(n(v));
    }
  }
  return s;
}

struct Box {
  Eigen::Vector3d lo, hi;
};

Box debris_box(const DebrisSetup& setup, const std::vector<DebrisMeshFile>& meshes, const LiggghtsDebrisOptions& o) {
  Box b{Eigen::Vector3d::Constant(1e300), Eigen::Vector3d::Constant(-1e300)};
  for (const DebrisMeshFile& m : meshes) {
    b.lo = b.lo.cwiseMin(m.mesh.V.colwise().minCoeff().transpose());
    b.hi = b.hi.cwiseMax(m.mesh.V.colwise().maxCoeff().transpose());
  }
  for (const DebrisElement& e : setup.spec.elements) {
    b.lo = b.lo.cwiseMin(e.centre_m - Eigen::Vector3d::Constant(e.radius_m));
    b.hi = b.hi.cwiseMax(e.centre_m + Eigen::Vector3d::Constant(e.radius_m));
  }
  b.lo.head<2>().array() -= o.box_margin_m;
  b.hi.head<2>().array() += o.box_margin_m;
  b.lo.z() = std::min(b.lo.z(), setup.spec.plain_height_m) - 1.0;
  b.hi.z() += o.box_top_margin_m;
  return b;
}

std::string data_text(const DebrisSetup& setup, const std::vector<int>& type_of, int types, const Box& box) {
  std::ostringstream s;
  s << "LIGGGHTS data file: debris elements (repose; generated)\n\n"
    << setup.spec.elements.size() << " atoms\n" << types << " atom types\n\n"
    << n(box.lo.x()) << " " << n(box.hi.x()) << " xlo xhi\n" << n(box.lo.y()) << " " << n(box.hi.y()) << " ylo yhi\n"
    << n(box.lo.z()) << " " << n(box.hi.z()) << " zlo zhi\n\nAtoms\n\n";
  for (std::size_t i = 0; i < setup.spec.elements.size(); ++i) {
    const DebrisElement& e = setup.spec.elements[i];
    s << i + 1 << " " << type_of[i] << " " << n(2.0 * e.radius_m) << " " << n(e.density_kg_m3) << " " << n(e.centre_m.x())
      << " " << n(e.centre_m.y()) << " " << n(e.centre_m.z()) << "\n";
  }
  s << "\nVelocities\n\n";
  for (std::size_t i = 0; i < setup.spec.elements.size(); ++i) {
    const Eigen::Vector3d& v = setup.spec.elements[i].velocity_m_s;
    s << i + 1 << " " << n(v.x()) << " " << n(v.y()) << " " << n(v.z()) << " 0 0 0\n";
  }
  return s.str();
}

void write_materials(std::ostringstream& s, const DebrisSetup& setup, const std::vector<Material>& m,
                     const LiggghtsDebrisOptions& o) {
  const std::size_t types = m.size() + 1;
  std::string e, nu;
  for (std::size_t t = 0; t < types; ++t) {
    e.append(" ").append(n(o.youngs_modulus_pa));
    nu.append(" ").append(n(o.poisson_ratio));
  }
  const DebrisMaterial& b = setup.spec.material;
  s << "# type 1: terrain, plain and buildings; types 2..: the element materials\n"
    << "fix m1 all property/global youngsModulus peratomtype" << e << "\n"
    << "fix m2 all property/global poissonsRatio peratomtype" << nu << "\n"
    << "fix m3 all property/global coefficientRestitution peratomtypepair "
    << pair_table(m, std::max(b.building_restitution, 0.1), &Material::restitution) << "\n"
    << "fix m4 all property/global coefficientFriction peratomtypepair "
    << pair_table(m, b.building_friction, &Material::friction) << "\n"
    << "fix m5 all property/global coefficientRollingFriction peratomtypepair " << pair_table(m, 0.0, &Material::rolling)
    << "\n\n";
}

constexpr const char* kModel = "model hertz tangential history rolling_friction cdt";

}  // namespace

TriangleMesh part_mesh(const DebrisPart& p) {
  const auto k = static_cast<int>(p.hull_m.rows() / 2);
  TriangleMesh m;
  m.V.resize(p.hull_m.rows(), 3);
  for (Eigen::Index r = 0; r < p.hull_m.rows(); ++r) m.V.row(r) = p.centre_m.transpose() + p.hull_m.row(r);
  std::vector<Eigen::Vector3i> f;
  for (int i = 1; i + 1 < k; ++i) {
    f.emplace_back(1, 2 * i + 1, 2 * i + 3);  // top, counter-clockwise seen from above
    f.emplace_back(0, 2 * i + 2, 2 * i);      // bottom, clockwise seen from above
  }
  for (int i = 0; i < k; ++i) {
    const int j = (i + 1) % k;
    f.emplace_back(2 * i, 2 * j, 2 * j + 1);
    f.emplace_back(2 * i, 2 * j + 1, 2 * i + 1);
  }
  m.F.resize(static_cast<Eigen::Index>(f.size()), 3);
  for (std::size_t i = 0; i < f.size(); ++i) m.F.row(static_cast<Eigen::Index>(i)) = f[i].transpose();
  return m;
}

LiggghtsDebrisScript liggghts_debris_script(const DebrisSetup& setup, double duration_s,
                                            const LiggghtsDebrisOptions& o) {
  o.validate();
  if (setup.spec.elements.empty()) throw InputError("liggghts debris: the setup has no elements (terrain: elements)");
  LiggghtsDebrisScript out;
  std::vector<int> type_of;
  const std::vector<Material> materials = element_materials(setup.spec, &type_of);
  out.atom_types = static_cast<int>(materials.size()) + 1;
  out.meshes.push_back({"terrain.stl", setup.spec.terrain});
  for (std::size_t p = 0; p < setup.spec.parts.size(); ++p) {
    out.meshes.push_back({fmt::format("part_{}.stl", p), part_mesh(setup.spec.parts[p])});
  }
  const Box box = debris_box(setup, out.meshes, o);
  out.data = data_text(setup, type_of, out.atom_types, box);
  out.total_steps = liggghts_steps(duration_s, o.time_step_s);
  out.dump_every_steps = std::max(1L, liggghts_steps(o.frame_interval_s > 0 ? o.frame_interval_s : duration_s / 20.0, o.time_step_s));
  out.force_every_steps = std::max(1L, liggghts_steps(o.force_interval_s, o.time_step_s));
  double r_max = 0.0;
  for (const DebrisElement& e : setup.spec.elements) r_max = std::max(r_max, e.radius_m);

  std::ostringstream s;
  s << "# repose: a debris flow on generated terrain (generated; do not edit)\n"
    << "atom_style granular\natom_modify map array\nboundary f f f\nnewton off\ncommunicate single vel yes\nunits si\n"
    << "read_data " << kDebrisDataFile << "\n"
    << "neighbor " << n(o.neighbor_skin_radii * r_max) << " bin\nneigh_modify delay 0\n\n";
  write_materials(s, setup, materials, o);
  s << "pair_style gran " << kModel << "\npair_coeff * *\ntimestep " << n(o.time_step_s) << "\n"
    << "fix gravity all gravity " << n(setup.spec.gravity_m_s2) << " vector 0 0 -1\n\n"
    << "# the terrain and the building parts (force on part p in f_part<p>[1..3]) as mesh walls, the plain a plane\n"
    << "fix terrain all mesh/surface file terrain.stl type 1\n";
  std::string ids = " terrain", forces;
  for (std::size_t p = 0; p < setup.spec.parts.size(); ++p) {
    s << fmt::format("fix part{0} all mesh/surface/stress file part_{0}.stl type 1 stress on\n", p);
    ids += fmt::format(" part{}", p);
    forces += fmt::format(" f_part{0}[1] f_part{0}[2] f_part{0}[3]", p);
  }
  s << "fix walls all wall/gran " << kModel << " mesh n_meshes " << out.meshes.size() << " meshes" << ids << "\n"
    << "fix plain all wall/gran " << kModel << " primitive type 1 zplane " << n(setup.spec.plain_height_m) << "\n"
    << "fix integrate all nve/sphere\n";
  if (!forces.empty()) {
    s << fmt::format("fix bforce all ave/time 1 {0} {0}{1} file {2}\n", out.force_every_steps, forces, kDebrisForceFile);
  }
  s << "\nthermo_style custom step atoms ke\nthermo " << out.dump_every_steps << "\nthermo_modify lost error norm no\n"
    << "dump grains all custom " << out.dump_every_steps << " " << kDebrisDumpDirectory
    << "/dump.*.txt id type x y z radius vx vy vz\ndump_modify grains sort id\n\n"
    << "run " << out.total_steps << "\n"
    << "print \"" << kCompleteMarker << "\"\n";
  out.script = s.str();
  return out;
}

void write_liggghts_debris_inputs(const LiggghtsDebrisScript& script, const std::string& run_dir) {
  namespace fs = std::filesystem;
  std::ofstream(fs::path(run_dir) / kDebrisScriptFile) << script.script;
  std::ofstream(fs::path(run_dir) / kDebrisDataFile) << script.data;
  for (const DebrisMeshFile& m : script.meshes) write_stl((fs::path(run_dir) / m.file_name).string(), m.mesh);
  fs::create_directories(fs::path(run_dir) / kDebrisDumpDirectory);
}

}  // namespace repose
