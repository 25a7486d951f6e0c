#include "models/core/config/dynamic_body.h"

#include <cmath>

#include <fmt/format.h>

namespace repose {

void validate(const DynamicBody& d) {
  const std::string one = "either mass_kg or density_kg_m3 (exactly one, > 0)";
  if (!(d.mass_kg >= 0.0) || !std::isfinite(d.mass_kg)) throw FieldError("mass_kg", "a mass > 0", fmt::format("{}", d.mass_kg));
  if (!(d.density_kg_m3 >= 0.0) || !std::isfinite(d.density_kg_m3)) {
    throw FieldError("density_kg_m3", "a density > 0", fmt::format("{}", d.density_kg_m3));
  }
  if (d.mass_kg > 0.0 && d.density_kg_m3 > 0.0) throw FieldError("density_kg_m3", one, "both");
  if (d.mass_kg == 0.0 && d.density_kg_m3 == 0.0) throw FieldError("mass_kg", one, "neither");
  const std::pair<const char*, const Eigen::Vector3d*> vectors[] = {{"position_m", &d.position_m},
                                                                    {"orientation_deg", &d.orientation_deg},
                                                                    {"velocity_m_s", &d.velocity_m_s},
                                                                    {"angular_velocity_rad_s", &d.angular_velocity_rad_s},
                                                                    {"torque_n_m", &d.torque_n_m}};
  for (const auto& [key, v] : vectors) {
    if (!v->allFinite()) throw FieldError(key, "three finite numbers", fmt::format("[{}, {}, {}]", v->x(), v->y(), v->z()));
  }
}

}  // namespace repose
