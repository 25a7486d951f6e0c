#pragma once
// A part of a scene file that one solver (or a family of solvers) owns:
// `ground_model:`, `dem:`, `snow:`, `tearing:`, `bullet:` ... The common
// scene (scene.h) holds what every solver reads; each section is defined in
// its solver's folder with one field list (fields.h) and a validate() that
// names the field and the rule, called by the loader and by the model alike.
//
// A section is immutable once read. The loader finds a section's reader by
// its key in the SectionType list it is given (the solver registry's).

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace repose {

struct Scene;
class YamlValue;

class SceneSection {
 public:
  virtual ~SceneSection() = default;
  // The resolved section (every default filled) as one YAML map, read back
  // by the same reader to an equal section.
  virtual void write_yaml(YAML::Emitter& out) const = 0;
  // One line for `repose check`.
  virtual std::string summary() const = 0;
};

// How a section is read. `common` is the scene read so far (everything but
// the sections), for rules that involve both (a column that must fit the
// grid, a camera the renderer can draw). Errors throw InputError with the
// file, line:column and key (yaml_reader.h).
struct SectionType {
  std::string key;          // the top-level key, e.g. "ground_model"
  std::string description;  // for `repose check --help` and messages
  std::function<std::shared_ptr<const SceneSection>(const YamlValue& value, const Scene& common)> read;
  // Read (with a null value: the defaults) when the scene has no such key,
  // so that its rules about the common scene are checked for every scene.
  bool read_when_absent = false;
};

using SectionTypes = std::vector<SectionType>;

}  // namespace repose
