#pragma once
// An example solver, as small as a solver can be: what a new model writes to
// join repose. It owns a scene section (`settle: {depth_m: 0.005}`), declares
// one fittable parameter (depth_m) and runs a trivial model: the ground
// settles uniformly by depth_m, never below its base. Registered by one line
// (example_solver_test.cpp), it runs through `repose run`, `repose
// experiment` and `repose calibrate` with nothing else changed.

#include <algorithm>
#include <memory>

#include "models/core/base/cpu_time.h"
#include "models/core/config/fields.h"
#include "models/core/config/initial_height.h"
#include "models/core/config/scene.h"
#include "models/core/solver/solver.h"

namespace repose::example {

// The options (SI units) with one field list and one validate().
struct SettleSpec {
  double depth_m = 0.005;  // how far the surface settles, [0, 0.1] m
};

inline void validate(const SettleSpec& s) {
  if (!(s.depth_m >= 0.0 && s.depth_m <= 0.1)) throw FieldError("depth_m", "a depth in [0, 0.1] m", yaml_number(s.depth_m));
}

template <class Visitor>
void settle_fields(Visitor& v, SettleSpec& s) {
  v.number("depth_m", s.depth_m, Range::any());
}

class SettleSection final : public SceneSection {
 public:
  static constexpr const char* kKey = "settle";
  SettleSpec spec;
  void write_yaml(YAML::Emitter& out) const override {
    write_fields_map(out, spec, [](auto& v, SettleSpec& x) { settle_fields(v, x); });
  }
  std::string summary() const override { return "settle: " + yaml_number(spec.depth_m) + " m"; }
};

inline SectionType settle_section_type() {
  const auto fields = [](auto& v, SettleSpec& x) { settle_fields(v, x); };
  auto read = [fields](const YamlValue& value, const Scene&) -> std::shared_ptr<const SceneSection> {
    const YamlMap map = value.map(field_keys<SettleSpec>(fields));
    auto section = std::make_shared<SettleSection>();
    read_fields_into(map, fields, section->spec);
    validate_at(map, [&] { validate(section->spec); });
    return section;
  };
  return {SettleSection::kKey, "the example solver's settlement (tests/experiments/example_solver.h)", read, false};
}

class CompiledSettle final : public CompiledSolver {
 public:
  explicit CompiledSettle(const Scene& scene) : initial_(make_initial_height(scene)) {
    const SettleSpec& spec = scene.section<SettleSection>()->spec;
    parameters_ = {{"depth_m", "m", 1.0, 0.0, 0.1, spec.depth_m, "how far the surface settles"}};
  }
  const std::vector<ParameterInfo>& parameters() const override { return parameters_; }
  Run run(const std::vector<double>& values_si, const RunOptions&) const override {
    check_values(parameters_, values_si, "example");
    const Stopwatch clock;
    Run run;
    run.solver = "example";
    HeightField settled = initial_;
    settled.heights() = (initial_.heights() - values_si[0]).max(0.0);
    run.set("mean_drop_m", (initial_.heights() - settled.heights()).mean(), "m");
    run.fields["height_initial"] = initial_;
    run.fields["height_final"] = std::move(settled);
    run.stages = {"settle"};
    run.wall_s = clock.wall_s();
    run.cpu_s = clock.cpu_s();
    return run;
  }

 private:
  HeightField initial_;
  std::vector<ParameterInfo> parameters_;
};

class ExampleSolver final : public Solver {
 public:
  std::string name() const override { return "example"; }
  std::string description() const override { return "a uniform settlement (tests/experiments/example_solver.h)"; }
  std::vector<SectionType> sections() const override { return {settle_section_type()}; }
  std::unique_ptr<CompiledSolver> compile(const Scene& scene) const override {
    return std::make_unique<CompiledSettle>(scene);
  }
};

}  // namespace repose::example
