#include "experiments/tearing/paper_fit_report.h"

#include <cmath>
#include <fstream>

#include <fmt/format.h>

namespace repose {

namespace {

struct Row {
  std::string quantity;
  double model = 0.0, published = 0.0;
};

std::vector<Row> rows_of(const PaperFitSpec& spec, const DirectionMeasures& tensile, const DirectionMeasures& tear) {
  auto at = [](const DirectionMeasures& m, const char* d, const char* k) { return m.at(d).at(k); };
  std::vector<Row> rows{
      {"MD tensile stiffness (N/m)", at(tensile, "md", "tensile.stiffness_n_per_m"), spec.md_stiffness_n_per_m},
      {"CD tensile stiffness (N/m)", at(tensile, "cd", "tensile.stiffness_n_per_m"), spec.cd_stiffness_n_per_m},
      {"MD tensile strength (N/m)", at(tensile, "md", "tensile.strength_n_per_m"), spec.md_strength_n_per_m},
      {"CD tensile strength (N/m)", at(tensile, "cd", "tensile.strength_n_per_m"), spec.cd_strength_n_per_m},
      {"MD strain at peak (model only)", at(tensile, "md", "tensile.strain_at_peak"), NAN},
      {"CD strain at peak (model only)", at(tensile, "cd", "tensile.strain_at_peak"), NAN}};
  if (!tear.empty()) {
    // The check compares the energy the tear itself took per unit length (the
    // torn cells' energy, tear_run.h), not the grips' work, most of which is
    // the flaps' motion and drag: the seed's twist pulls the halves apart out
    // of plane, as the Elmendorf test does, and its tear resistance is that
    // work of tearing per unit length.
    const double md = at(tear, "md", "tear.fracture_energy_per_length_j_per_m"),
                 cd = at(tear, "cd", "tear.fracture_energy_per_length_j_per_m");
    const double md_grips = at(tear, "md", "tear.work_per_length_j_per_m"),
                 cd_grips = at(tear, "cd", "tear.work_per_length_j_per_m");
    rows.push_back({"MD grips' work per tear length (J/m, model only)", md_grips, NAN});
    rows.push_back({"CD grips' work per tear length (J/m, model only)", cd_grips, NAN});
    rows.push_back({"grips' work CD / MD (model only: mostly flap motion and drag)", cd_grips / md_grips, NAN});
    rows.push_back({"MD fracture energy per tear length (J/m, model only)", md, NAN});
    rows.push_back({"CD fracture energy per tear length (J/m, model only)", cd, NAN});
    rows.push_back({"tear resistance CD / MD: fracture energy (check, not fitted)", cd / md, spec.tear_cd_over_md});
  }
  return rows;
}

}  // namespace

void write_paper_fit_report(const PaperFitSpec& spec, const std::vector<double>& fitted,
                            const CalibrationUncertainty& uncertainty, double final_cost,
                            const DirectionMeasures& tensile, const DirectionMeasures& tear, double cpu_s,
                            const std::string& out_dir) {
  std::ofstream md(out_dir + "/report.md"), csv(out_dir + "/fit.csv");
  md << fmt::format("# {}\n\nPublished values: {}\n\nFitted (value +- standard error; s^2 = 2 cost / (n - p)):\n\n",
                    spec.name, spec.source);
  md << "| parameter | initial | fitted | standard error |\n|---|---|---|---|\n";
  csv << "kind,name,value,standard_error_or_published\n";
  for (std::size_t k = 0; k < fitted.size(); ++k) {
    const double se = uncertainty.standard_error[k];
    md << fmt::format("| {} | {:.4g} | {:.4g} | {} |\n", spec.parameters[k].name, spec.parameters[k].initial, fitted[k],
                      uncertainty.determined[k] ? fmt::format("{:.3g}", se) : "undetermined");
    csv << fmt::format("parameter,{},{},{}\n", spec.parameters[k].name, fitted[k], se);
  }
  md << fmt::format("\nFinal cost {:.4g} (residuals relative to the published values); {}\n\n", final_cost,
                    uncertainty.note.empty() ? "every parameter determined" : uncertainty.note);
  md << "| quantity | model | published | model / published |\n|---|---|---|---|\n";
  for (const Row& r : rows_of(spec, tensile, tear)) {
    md << fmt::format("| {} | {:.4g} | {} | {} |\n", r.quantity, r.model,
                      std::isnan(r.published) ? "" : fmt::format("{:.4g}", r.published),
                      std::isnan(r.published) ? "" : fmt::format("{:.3f}", r.model / r.published));
    csv << fmt::format("measure,\"{}\",{},{}\n", r.quantity, r.model, r.published);
  }
  md << fmt::format("\nCPU time {:.1f} s (the process, every thread)\n", cpu_s);
}

}  // namespace repose
