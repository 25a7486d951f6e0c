#include "models/core/solver/run.h"

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {

namespace {

template <class Map>
std::string names_of(const Map& map) {
  std::string names;
  for (const auto& [name, value] : map) names += (names.empty() ? "" : ", ") + name;
  return names.empty() ? "none" : names;
}

// Sets json[a][b][c] for the dotted name "a.b.c".
void set_dotted(nlohmann::json& json, const std::string& dotted, const nlohmann::json& value) {
  nlohmann::json* node = &json;
  std::size_t start = 0;
  for (std::size_t dot = dotted.find('.'); dot != std::string::npos; dot = dotted.find('.', start)) {
    node = &(*node)[dotted.substr(start, dot - start)];
    start = dot + 1;
  }
  (*node)[dotted.substr(start)] = value;
}

}  // namespace

const HeightField& Run::field(const std::string& name) const {
  const auto it = fields.find(name);
  if (it == fields.end()) {
    throw InputError(fmt::format("solver {}: no field '{}' (it produces: {})", solver, name, names_of(fields)));
  }
  return it->second;
}

const Measure& Run::measure(const std::string& name) const {
  const auto it = measures.find(name);
  if (it == measures.end()) {
    throw InputError(fmt::format("solver {}: no measure '{}' (it reports: {})", solver, name, names_of(measures)));
  }
  return it->second;
}

nlohmann::json results_json(const Run& run) {
  nlohmann::json json = run.details.is_object() ? run.details : nlohmann::json::object();
  for (const auto& [name, measure] : run.measures) set_dotted(json, name, measure.value);
  return json;
}

void to_json(nlohmann::json& json, const Run& run) {
  nlohmann::json measures = nlohmann::json::object();
  for (const auto& [name, m] : run.measures) measures[name] = {{"value", m.value}, {"unit", m.unit}};
  json = {{"solver", run.solver}, {"measures", measures}, {"details", run.details}, {"stages", run.stages},
          {"wall_s", run.wall_s},  {"cpu_s", run.cpu_s},       {"files", run.files}};
}

void from_json(const nlohmann::json& json, Run& run) {
  run.solver = json.at("solver").get<std::string>();
  run.measures.clear();
  for (const auto& [name, m] : json.at("measures").items()) {
    run.measures[name] = Measure{m.at("value").get<double>(), m.at("unit").get<std::string>()};
  }
  run.details = json.value("details", nlohmann::json::object());
  run.stages = json.value("stages", std::vector<std::string>{});
  run.wall_s = json.value("wall_s", 0.0);
  run.cpu_s = json.value("cpu_s", 0.0);
  run.files = json.value("files", std::vector<std::string>{});
}

}  // namespace repose
