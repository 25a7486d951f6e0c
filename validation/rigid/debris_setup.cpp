#include "validation/rigid/debris_setup.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/terrain/terrain_surface.h"

namespace repose {

namespace {

Point2 area_centroid(const Polygon2& p) {
  double a = 0.0;
  Point2 c = Point2::Zero();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Point2& u = p[i];
    const Point2& v = p[(i + 1) % p.size()];
    const double cross = u.x() * v.y() - v.x() * u.y();
    a += cross;
    c += cross * (u + v);
  }
  return c / (3.0 * a);
}

// Downhill (unit, xy) at p: the negative gradient of the surface over +-step.
Eigen::Vector2d downhill(const TerrainSurface& surface, const Point2& p, double step_m) {
  const auto h = [&](double dx, double dy) { return surface.height_at(p + Point2(dx, dy)); };
  const auto xp = h(step_m, 0), xm = h(-step_m, 0), yp = h(0, step_m), ym = h(0, -step_m);
  if (!xp || !xm || !yp || !ym) return {1.0, 0.0};
  const Eigen::Vector2d g(*xp - *xm, *yp - *ym);
  return g.norm() > 0.0 ? Eigen::Vector2d(-g / g.norm()) : Eigen::Vector2d(1.0, 0.0);
}

double box_extent(const Polygon2& polygon) {
  Eigen::Vector2d lo = polygon.front(), hi = polygon.front();
  for (const Point2& p : polygon) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).maxCoeff();
}

}  // namespace

DebrisPart debris_part(const BuildingPart& part, double bulk_density_kg_m3) {
  const Polygon2& f = part.footprint_m;
  const Point2 c = area_centroid(f);
  const double mid = 0.5 * (part.bottom_m + part.top_m), half_h = 0.5 * (part.top_m - part.bottom_m);
  DebrisPart out;
  out.centre_m = Eigen::Vector3d(c.x(), c.y(), mid);
  out.hull_m.resize(static_cast<Eigen::Index>(2 * f.size()), 3);
  Eigen::Vector2d lo = f.front() - c, hi = f.front() - c;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Point2 d = f[i] - c;
    lo = lo.cwiseMin(d);
    hi = hi.cwiseMax(d);
    out.hull_m.row(static_cast<Eigen::Index>(2 * i)) << d.x(), d.y(), -half_h;
    out.hull_m.row(static_cast<Eigen::Index>(2 * i + 1)) << d.x(), d.y(), half_h;
  }
  out.half_extents_m = Eigen::Vector3d(0.5 * (hi.x() - lo.x()), 0.5 * (hi.y() - lo.y()), half_h);
  out.mass_kg = bulk_density_kg_m3 * std::abs(signed_area_m2(f)) * (part.top_m - part.bottom_m);
  out.building = part.building;
  return out;
}

std::vector<DebrisJoint> building_joints(const std::vector<BuildingPart>& parts, const std::vector<int>& part_index,
                                         double break_force_n) {
  REPOSE_DEMAND(parts.size() == part_index.size());
  std::vector<DebrisJoint> joints;
  const auto centre = [&](std::size_t i) {
    const Point2 c = area_centroid(parts[i].footprint_m);
    return Eigen::Vector3d(c.x(), c.y(), 0.5 * (parts[i].bottom_m + parts[i].top_m));
  };
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const BuildingPart& p = parts[i];
    if (p.storey == 0) {
      const Point2 c = area_centroid(p.footprint_m);
      joints.push_back({part_index[i], -1, Eigen::Vector3d(c.x(), c.y(), p.bottom_m), break_force_n});
    }
    for (std::size_t j = i + 1; j < parts.size(); ++j) {
      const BuildingPart& q = parts[j];
      const double touch_m = 1e-6 * std::max(1.0, box_extent(p.footprint_m));
      if (q.storey == p.storey && boundary_distance_m(p.footprint_m, q.footprint_m) <= touch_m) {
        joints.push_back({part_index[i], part_index[j], 0.5 * (centre(i) + centre(j)), break_force_n});
      }
      if (q.piece == p.piece && std::abs(q.storey - p.storey) == 1) {
        const BuildingPart& low = q.storey < p.storey ? q : p;
        const BuildingPart& high = q.storey < p.storey ? p : q;
        const Point2 c = area_centroid(low.footprint_m);
        joints.push_back({part_index[i], part_index[j],
                          Eigen::Vector3d(c.x(), c.y(), 0.5 * (low.top_m + high.bottom_m)), break_force_n});
      }
    }
  }
  return joints;
}

void append_building(const BuildingFootprint& footprint, std::vector<BuildingPart> parts, DebrisSetup& setup) {
  const int b = static_cast<int>(setup.building_names.size());
  setup.building_names.push_back(footprint.name);
  std::vector<int> index;
  for (BuildingPart& part : parts) {
    part.bottom_m += kPartClearanceM;
    part.top_m += kPartClearanceM;
    part.building = b;
    index.push_back(static_cast<int>(setup.spec.parts.size()));
    setup.spec.parts.push_back(debris_part(part, footprint.bulk_density_kg_m3));
  }
  for (const DebrisJoint& j : building_joints(parts, index, footprint.joint_break_force_n)) {
    setup.spec.joints.push_back(j);
    setup.joint_building.push_back(b);
  }
}

DebrisSetup debris_setup(const TerrainScene& scene, const DebrisMaterial& material, double rolling_friction_scale) {
  if (!scene.elements) throw InputError("terrain: elements: a debris run needs moving elements (terrain: elements)");
  DebrisSetup out;
  out.scenery = generate_scenery(scene);
  DebrisWorldSpec& spec = out.spec;
  spec.terrain = out.scenery.terrain.mesh;
  spec.plain_height_m = out.scenery.terrain.summary.max_height_m;
  for (int r : out.scenery.terrain.nesting.roots) {
    spec.plain_height_m = std::min(spec.plain_height_m, out.scenery.terrain.keys[static_cast<std::size_t>(r)].height_m);
  }
  spec.material = material;
  for (const PlacedElement& e : out.scenery.elements.elements) {
    const ElementLayer& l = scene.elements->layers[static_cast<std::size_t>(e.layer)];
    spec.elements.push_back({e.centre_m, Eigen::Vector3d::Zero(), e.radius_m, l.density_kg_m3, l.friction, l.restitution,
                             rolling_friction_scale * l.rolling_friction});
  }
  for (std::size_t b = 0; b < scene.buildings.size(); ++b) {
    std::vector<BuildingPart> parts;
    for (const BuildingPart& part : out.scenery.building_parts) {
      if (part.building == static_cast<int>(b)) parts.push_back(part);
    }
    append_building(scene.buildings[b], parts, out);
  }
  out.source_centre_m = area_centroid(counter_clockwise(scene.elements->region_m));
  const TerrainSurface surface(out.scenery.terrain.mesh);
  out.flow_direction = downhill(surface, out.source_centre_m, 0.25 * box_extent(scene.elements->region_m));
  return out;
}

double min_element_clearance_m(const std::vector<DebrisElement>& elements) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < elements.size(); ++i) {
    for (std::size_t j = i + 1; j < elements.size(); ++j) {
      const double gap = (elements[i].centre_m - elements[j].centre_m).norm() - elements[i].radius_m - elements[j].radius_m;
      best = std::min(best, gap);
    }
  }
  return best;
}

}  // namespace repose
