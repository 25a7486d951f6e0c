#include "models/tearing/spring_links.h"

#include <algorithm>
#include <cmath>
#include <unordered_map>

#include "models/core/base/error.h"
#include "models/tearing/sheet_forces.h"

namespace repose {

std::vector<SpringLink> spring_links(const SheetModel& model, const std::vector<double>& spring_constant) {
  REPOSE_DEMAND(spring_constant.size() == 6 * static_cast<std::size_t>(model.cell_count()));
  std::vector<SpringLink> links;
  std::unordered_map<long long, int> link_of_pair;
  for (int c = 0; c < model.cell_count(); ++c) {
    const std::array<CellSpring, 6> springs = cell_springs(model, c);
    for (int k = 0; k < 6; ++k) {
      const CellSpring& s = springs[static_cast<std::size_t>(k)];
      const double constant = spring_constant[static_cast<std::size_t>(6 * c + k)];
      const long long key = static_cast<long long>(std::min(s.a, s.b)) * model.vertex_count() + std::max(s.a, s.b);
      const auto [at, added] = link_of_pair.emplace(key, static_cast<int>(links.size()));
      if (added) {
        SpringLink link;
        link.a = s.a;
        link.b = s.b;
        link.rest_length_m = s.rest_length_m;
        link.first = 4 * (6 * c + k);
        link.cell[0] = c;
        link.constant[0] = constant;
        links.push_back(link);
        continue;
      }
      SpringLink& link = links[static_cast<std::size_t>(at->second)];
      REPOSE_DEMAND(link.cell[1] < 0);
      REPOSE_DEMAND(std::abs(link.rest_length_m - s.rest_length_m) <= 1e-12 * link.rest_length_m);
      link.cell[1] = c;
      link.constant[1] = constant;
    }
  }
  return links;
}

}  // namespace repose
