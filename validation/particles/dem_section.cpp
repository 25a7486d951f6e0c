#include "validation/particles/dem_section.h"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/config/fields.h"
#include "validation/particles/chute_impact.h"
#include "validation/particles/column_geometry.h"

namespace repose {

namespace {

const auto kDemFields = [](auto& v, DemSpec& x) { dem_fields(v, x); };

void require_positive(double v, const char* field) {
  if (!(std::isfinite(v) && v > 0.0)) throw FieldError(field, "a finite number > 0", yaml_number(v));
}

void require_non_negative(double v, const char* field) {
  if (!(std::isfinite(v) && v >= 0.0)) throw FieldError(field, "a finite number >= 0", yaml_number(v));
}

void require_in(double v, double lo, bool lo_open, double hi, bool hi_open, const char* field) {
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  if (!(std::isfinite(v) && above && below)) {
    throw FieldError(field, fmt::format("a number in {}{}, {}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]"),
                     yaml_number(v));
  }
}

}  // namespace

double rayleigh_time_s(const DemSpec& dem) {
  const double r = dem.grain_radius_m * (1.0 - dem.radius_spread);
  const double shear_modulus = dem.youngs_modulus_pa / (2.0 * (1.0 + dem.poisson_ratio));
  return std::numbers::pi * r * std::sqrt(dem.density_kg_m3 / shear_modulus) / (0.1631 * dem.poisson_ratio + 0.8766);
}

void validate(const DemSpec& d) {
  require_positive(d.grain_radius_m, "grain_radius_m");
  require_in(d.radius_spread, 0.0, false, 0.5, true, "radius_spread");
  require_positive(d.density_kg_m3, "density_kg_m3");
  require_positive(d.youngs_modulus_pa, "youngs_modulus_pa");
  require_in(d.poisson_ratio, 0.0, false, 0.5, true, "poisson_ratio");
  require_in(d.restitution, 0.0, true, 1.0, false, "restitution");
  require_non_negative(d.friction, "friction");
  require_non_negative(d.rolling_friction, "rolling_friction");
  require_non_negative(d.cohesion_energy_density_j_m3, "cohesion_energy_density_j_m3");
  require_positive(d.time_step_s, "time_step_s");
  require_positive(d.bed_depth_m, "bed_depth_m");
  require_positive(d.settle_kinetic_energy_j, "settle_kinetic_energy_j");
  require_positive(d.gravity_m_s2, "gravity_m_s2");
  require_positive(d.dump_interval_s, "dump_interval_s");
  require_positive(d.column_width_m, "column_width_m");
  require_positive(d.column_height_m, "column_height_m");
  require_non_negative(d.floor_rolling_friction, "floor_rolling_friction");
  require_non_negative(d.surface_probe_radius_m, "surface_probe_radius_m");
  require_in(d.slope_deg, 0.0, false, 80.0, true, "slope_deg");
  require_non_negative(d.impact_window_m, "impact_window_m");
  require_non_negative(d.impact_window_gap_m, "impact_window_gap_m");
  const double max_step = kMaxRayleighFraction * rayleigh_time_s(d);
  if (d.time_step_s > max_step) {
    throw FieldError("time_step_s",
                     fmt::format("a time step <= 20 % of the Rayleigh time {:.6g} s of the smallest grain, i.e. <= "
                                 "{:.6g} s (or a smaller Young's modulus / larger grains)",
                                 rayleigh_time_s(d), max_step),
                     fmt::format("{:.6g} s", d.time_step_s));
  }
}

void validate(const DemSpec& dem, const Scene& scene) {
  validate(dem);
  if (dem.initial == DemSpec::Initial::kColumn) column_geometry(dem, scene);
  if (measures_impact(dem) && (scene.objects.empty() || scene.objects.front().dynamic)) {
    throw InputError("dem: impact_window_m > 0 measures the impact on the scene's first object (the wall at the "
                     "chute's foot); add it as the first object, not a free body");
  }
  if (measures_impact(dem)) chute_geometry(dem, scene);  // the window must lie on the grid
}

Eigen::Vector3d gravity_direction(const DemSpec& dem) {
  const double a = dem.slope_deg * std::numbers::pi / 180.0;
  return dem.slope_deg == 0.0 ? Eigen::Vector3d(0, 0, -1) : Eigen::Vector3d(std::sin(a), 0.0, -std::cos(a));
}

void DemSection::write_yaml(YAML::Emitter& out) const { write_fields_map(out, spec, kDemFields); }

std::string DemSection::summary() const {
  return fmt::format("dem: grains of {} m (spread {}), {}, time step {} s ({:.2g} of the Rayleigh time)",
                     spec.grain_radius_m, spec.radius_spread,
                     spec.initial == DemSpec::Initial::kBed      ? fmt::format("a bed {} m deep", spec.bed_depth_m)
                     : spec.initial == DemSpec::Initial::kColumn ? std::string("a column")
                                                                 : std::string("snowfall"),
                     spec.time_step_s, spec.time_step_s / rayleigh_time_s(spec));
}

const DemSpec* dem_of(const Scene& scene) {
  const DemSection* section = scene.section<DemSection>();
  return section != nullptr ? &section->spec : nullptr;
}

const DemSpec& require_dem(const Scene& scene, const std::string& solver) {
  const DemSpec* dem = dem_of(scene);
  if (dem == nullptr) {
    throw InputError(fmt::format("{}: dem: the scene has no 'dem' section (its grains), so it cannot run under {}",
                                 scene.source_path.empty() ? scene.name : scene.source_path, solver));
  }
  validate(*dem);
  return *dem;
}

Scene with_dem(Scene scene, const DemSpec& dem) {
  auto section = std::make_shared<DemSection>();
  section->spec = dem;
  scene.sections[DemSection::kKey] = section;
  return scene;
}

SectionType dem_section_type() {
  auto read = [](const YamlValue& value, const Scene& common) -> std::shared_ptr<const SceneSection> {
    const YamlMap map = value.map(field_keys<DemSpec>(kDemFields));
    auto section = std::make_shared<DemSection>();
    read_fields_into(map, kDemFields, section->spec);
    validate_at(map, [&] { validate(section->spec); });
    try {
      validate(section->spec, common);
    } catch (const InputError& e) {
      value.fail("a column that fits the ground grid and a wall for an impact window", e.what());
    }
    return section;
  };
  return {DemSection::kKey, "the grains of the particle references (validation/particles/dem_section.h)", read, false};
}

}  // namespace repose
