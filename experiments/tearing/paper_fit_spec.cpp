#include "experiments/tearing/paper_fit_spec.h"

#include <filesystem>

#include <fmt/format.h>

#include "models/core/config/yaml_reader.h"
#include "models/core/io/input_file.h"

namespace repose {

namespace {

std::string beside(const std::string& file, const std::string& relative) {
  return std::filesystem::weakly_canonical(std::filesystem::absolute(file).parent_path() / relative).string();
}

std::vector<int> seeds_of(const YamlValue& v) {
  std::vector<int> seeds;
  for (const YamlValue& item : v.list(1)) {
    seeds.push_back(static_cast<int>(item.number(Range::closed(0, 1e9))));
  }
  return seeds;
}

PaperFitParameter parameter_of(const YamlValue& v, const std::string& expected_name) {
  const YamlMap m = v.map({"name", "initial", "bounds", "step"});
  PaperFitParameter p;
  p.name = m.required("name", "the parameter's name").string();
  if (p.name != expected_name) m.required("name", "").fail(fmt::format("the parameter {}", expected_name));
  p.initial = m.number("initial", Range::any());
  const Eigen::Vector2d bounds = m.vec2("bounds", Range::any());
  p.lower = bounds[0];
  p.upper = bounds[1];
  if (!(p.lower <= p.initial && p.initial <= p.upper)) {
    m.required("bounds", "").fail(fmt::format("bounds holding the initial value {}", p.initial));
  }
  p.step = m.number("step", Range::positive());
  return p;
}

void read_published(const YamlMap& m, PaperFitSpec* s) {
  s->md_stiffness_n_per_m = m.number("md_stiffness_n_per_m", Range::positive());
  s->cd_stiffness_n_per_m = m.number("cd_stiffness_n_per_m", Range::positive());
  s->md_strength_n_per_m = m.number("md_strength_n_per_m", Range::positive());
  s->cd_strength_n_per_m = m.number("cd_strength_n_per_m", Range::positive());
  // the tear ratio, or the two tear resistances (mN) it is the ratio of
  const auto ratio = m.get("tear_cd_over_md");
  const auto md_tear = m.get("md_tear_mn"), cd_tear = m.get("cd_tear_mn");
  if (ratio && (md_tear || cd_tear)) ratio->fail("either tear_cd_over_md or md_tear_mn and cd_tear_mn", "both");
  if (ratio) {
    s->tear_cd_over_md = m.number("tear_cd_over_md", Range::positive());
    return;
  }
  s->md_tear_mn = m.number("md_tear_mn", Range::positive());
  s->cd_tear_mn = m.number("cd_tear_mn", Range::positive());
  s->tear_cd_over_md = s->cd_tear_mn / s->md_tear_mn;
}

}  // namespace

PaperFitSpec load_paper_fit_spec(const std::string& path) {
  const YamlValue root = read_yaml_file(path, input_kind::kExperiment);
  const YamlMap m = root.map({"name", "source", "tensile_scene", "tear_scene", "seeds", "tear_seeds", "published",
                              "parameters", "starts", "max_iterations", "fit_tear_seeds"});
  PaperFitSpec s;
  s.source_path = std::filesystem::absolute(path).string();
  s.name = m.required("name", "a name").string();
  s.source = m.required("source", "where the published values come from").string();
  s.tensile_scene = beside(path, m.required("tensile_scene", "a scene file").string());
  if (auto tear = m.get("tear_scene")) s.tear_scene = beside(path, tear->string());
  s.seeds = seeds_of(m.required("seeds", "a list of seeds"));
  if (auto tear_seeds = m.get("tear_seeds")) s.tear_seeds = seeds_of(*tear_seeds);
  if (!s.tear_scene.empty() && s.tear_seeds.empty()) m.fail_missing("tear_seeds", "the tear check's seeds");
  read_published(m.required("published", "the published values").map({"md_stiffness_n_per_m", "cd_stiffness_n_per_m",
                                                                        "md_strength_n_per_m", "cd_strength_n_per_m",
                                                                        "tear_cd_over_md", "md_tear_mn", "cd_tear_mn"}),
                 &s);
  const std::vector<YamlValue> parameters = m.required("parameters", "three or four parameters").list(3);
  const char* names[4] = {"stiffness_scale", "tear_strain", "fibre_anisotropy", "background_density"};
  if (parameters.size() != 3 && parameters.size() != 4) {
    m.required("parameters", "").fail("stiffness_scale, tear_strain, fibre_anisotropy[, background_density]");
  }
  for (std::size_t k = 0; k < parameters.size(); ++k) s.parameters.push_back(parameter_of(parameters[k], names[k]));
  if (s.parameters.size() == 4) {
    // the fourth is fitted to the tear ratio: it needs the tear scene, and a
    // fibre density in [0, 1)
    if (s.tear_scene.empty()) m.fail_missing("tear_scene", "the tear scene, to fit background_density to the tear ratio");
    if (!(s.parameters[3].lower >= 0.0 && s.parameters[3].upper < 1.0)) {
      parameters[3].map({"name", "initial", "bounds", "step"}).required("bounds", "").fail("bounds within [0, 1)");
    }
  }
  s.fit_tear_seeds = s.tear_seeds;
  if (auto fit_seeds = m.get("fit_tear_seeds")) s.fit_tear_seeds = seeds_of(*fit_seeds);
  s.starts = static_cast<int>(m.integer_or("starts", IntRange{1, 50}, 3));
  s.max_iterations = static_cast<int>(m.integer_or("max_iterations", IntRange{1, 500}, 20));
  return s;
}

}  // namespace repose
