#include "experiments/tearing/paper_fit_report.h"

#include <cmath>
#include <fstream>

#include <fmt/format.h>

namespace repose {

namespace {

struct Row {
  std::string quantity;
  double model = 0.0, seed_sd = NAN, published = NAN, unfitted = NAN;
};

double mean_of(const std::vector<std::map<std::string, double>>& runs, const std::string& m) {
  double sum = 0.0;
  for (const auto& r : runs) sum += r.at(m);
  return sum / static_cast<double>(runs.size());
}

double sd_of(const std::vector<std::map<std::string, double>>& runs, const std::string& m) {
  if (runs.size() < 2) return 0.0;
  const double mean = mean_of(runs, m);
  double ss = 0.0;
  for (const auto& r : runs) ss += (r.at(m) - mean) * (r.at(m) - mean);
  return std::sqrt(ss / static_cast<double>(runs.size() - 1));
}

std::vector<Row> tensile_rows(const PaperFitSpec& spec, const PaperFitResults& r) {
  const std::string stiffness = "tensile.stiffness_n_per_m", strength = "tensile.strength_n_per_m",
                    strain = "tensile.strain_at_peak";
  auto row = [&](const char* quantity, const char* d, const std::string& m, double published) {
    const auto& runs = r.tensile.at(d);
    const auto unfitted = r.unfitted.find(d);
    return Row{quantity, mean_of(runs, m), sd_of(runs, m), published,
               unfitted == r.unfitted.end() ? NAN : unfitted->second.at(m)};
  };
  return {row("MD tensile stiffness (N/m)", "md", stiffness, spec.md_stiffness_n_per_m),
          row("CD tensile stiffness (N/m)", "cd", stiffness, spec.cd_stiffness_n_per_m),
          row("MD tensile strength (N/m)", "md", strength, spec.md_strength_n_per_m),
          row("CD tensile strength (N/m)", "cd", strength, spec.cd_strength_n_per_m),
          row("MD strain at peak (model only)", "md", strain, NAN),
          row("CD strain at peak (model only)", "cd", strain, NAN)};
}

// The check compares the energy the tear itself took per unit length (the
// torn cells' energy, tear_run.h), not the grips' work, most of which is
// the flaps' motion and drag: the seed's twist pulls the halves apart out
// of plane, as the Elmendorf test does, and its tear resistance is that
// work of tearing per unit length.
std::vector<Row> tear_rows(const PaperFitSpec& spec, const SeedMeasures& tear) {
  std::vector<Row> rows;
  for (const char* d : {"md", "cd"}) {
    const std::string dir = d == std::string("md") ? "MD (along)" : "CD (across)";
    const auto& runs = tear.at(d);
    for (const auto& [m, label] : std::vector<std::pair<std::string, std::string>>{
             {"tear.work_per_length_j_per_m", "grips' work per tear depth (J/m)"},
             {"tear.fracture_energy_per_length_j_per_m", "fracture energy per tear depth (J/m)"},
             {"tear.fracture_energy_per_path_length_j_per_m", "fracture energy per path length (J/m)"},
             {"tear.tortuosity", "tortuosity"}}) {
      rows.push_back({dir + " " + label + " (model only)", mean_of(runs, m), sd_of(runs, m)});
    }
  }
  const TearRatio depth = tear_ratio_cd_over_md(tear, "tear.fracture_energy_per_length_j_per_m");
  const TearRatio path = tear_ratio_cd_over_md(tear, "tear.fracture_energy_per_path_length_j_per_m");
  rows.push_back({"tear resistance CD / MD per depth (shown, not the check)", depth.mean, depth.seed_sd});
  rows.push_back({"tear resistance CD / MD per path length (the check)", path.mean, path.seed_sd, spec.tear_cd_over_md});
  return rows;
}

std::string cell(double v, const char* format) { return std::isnan(v) ? "" : fmt::format(fmt::runtime(format), v); }

}  // namespace

void write_paper_fit_report(const PaperFitSpec& spec, const PaperFitResults& r, const std::string& out_dir) {
  std::ofstream md(out_dir + "/report.md"), csv(out_dir + "/fit.csv");
  md << fmt::format("# {}\n\nPublished values: {}\n\nFitted (value +- standard error; s^2 = 2 cost / (n - p)):\n\n",
                    spec.name, spec.source);
  md << "| parameter | initial | fitted | standard error |\n|---|---|---|---|\n";
  csv << "kind,name,value,seed_sd_or_standard_error,published,unfitted\n";
  for (std::size_t k = 0; k < r.fitted.size(); ++k) {
    const double se = r.uncertainty.standard_error[k];
    md << fmt::format("| {} | {:.4g} | {:.4g} | {} |\n", spec.parameters[k].name, spec.parameters[k].initial,
                      r.fitted[k], r.uncertainty.determined[k] ? fmt::format("{:.3g}", se) : "undetermined");
    csv << fmt::format("parameter,{},{},{},,{}\n", spec.parameters[k].name, r.fitted[k], se, spec.parameters[k].initial);
  }
  md << fmt::format("\nFinal cost {:.4g} (residuals relative to the published values); {}\n\n", r.final_cost,
                    r.uncertainty.note.empty() ? "every parameter determined" : r.uncertainty.note);
  md << "Model: mean over the seeds, with the seeds' standard deviation; unfitted: the sheet at the file's initial "
        "values.\n\n";
  md << "| quantity | model | seed sd | published | model / published | unfitted / published |\n"
        "|---|---|---|---|---|---|\n";
  std::vector<Row> rows = tensile_rows(spec, r);
  if (!r.tear.empty()) {
    const std::vector<Row> tear = tear_rows(spec, r.tear);
    rows.insert(rows.end(), tear.begin(), tear.end());
  }
  for (const Row& row : rows) {
    md << fmt::format("| {} | {:.4g} | {} | {} | {} | {} |\n", row.quantity, row.model, cell(row.seed_sd, "{:.3g}"),
                      cell(row.published, "{:.4g}"), cell(row.model / row.published, "{:.3f}"),
                      cell(row.unfitted / row.published, "{:.3f}"));
    csv << fmt::format("measure,\"{}\",{},{},{},{}\n", row.quantity, row.model, row.seed_sd, row.published, row.unfitted);
  }
  if (!r.tear.empty()) {
    const TearRatio path = tear_ratio_cd_over_md(r.tear, "tear.fracture_energy_per_path_length_j_per_m");
    md << "\nTear ratio CD / MD per path length, per seed:";
    for (std::size_t k = 0; k < path.per_seed.size(); ++k) {
      md << fmt::format(" {} (seed {})", cell(path.per_seed[k], "{:.3f}"), spec.tear_seeds[k]);
    }
    md << "\n";
  }
  md << fmt::format("\nCPU time {:.1f} s (the process, every thread)\n", r.cpu_s);
}

}  // namespace repose
