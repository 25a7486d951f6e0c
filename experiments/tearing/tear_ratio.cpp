#include "experiments/tearing/tear_ratio.h"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

namespace repose {

namespace {

const std::vector<std::map<std::string, double>>& direction(const SeedMeasures& tear, const char* d) {
  const auto it = tear.find(d);
  if (it == tear.end() || it->second.empty()) {
    throw std::invalid_argument(fmt::format("tear ratio: no {} tear measured", d));
  }
  return it->second;
}

double value(const std::map<std::string, double>& m, const std::string& measure) {
  const auto it = m.find(measure);
  if (it == m.end()) throw std::invalid_argument(fmt::format("tear ratio: no measure {}", measure));
  return it->second;
}

}  // namespace

TearRatio tear_ratio_cd_over_md(const SeedMeasures& tear, const std::string& measure) {
  const auto& md = direction(tear, "md");
  const auto& cd = direction(tear, "cd");
  if (md.size() != cd.size()) {
    throw std::invalid_argument(fmt::format("tear ratio: {} MD seeds against {} CD seeds", md.size(), cd.size()));
  }
  TearRatio r;
  double md_sum = 0.0, cd_sum = 0.0;
  for (std::size_t k = 0; k < md.size(); ++k) {
    const double m = value(md[k], measure), c = value(cd[k], measure);
    if (!(m > 0.0)) throw std::invalid_argument(fmt::format("tear ratio: MD {} is {} (no tear along the grain)", measure, m));
    r.per_seed.push_back(c / m);
    md_sum += m;
    cd_sum += c;
  }
  r.mean = cd_sum / md_sum;
  if (r.per_seed.size() > 1) {
    double mean = 0.0, ss = 0.0;
    for (const double v : r.per_seed) mean += v / static_cast<double>(r.per_seed.size());
    for (const double v : r.per_seed) ss += (v - mean) * (v - mean);
    r.seed_sd = std::sqrt(ss / static_cast<double>(r.per_seed.size() - 1));
  }
  return r;
}

double tear_ratio_residual(const TearRatio& ratio, double published_cd_over_md) {
  return ratio.mean / published_cd_over_md - 1.0;
}

}  // namespace repose
