#include "validation/particles/held_mass_series.h"

#include <charconv>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "validation/particles/particle_observables.h"

namespace repose {

namespace {

constexpr const char* kMassSuffix = "_mass_kg";

std::string object_label(const ObjectSpec& o, std::size_t k) {
  return o.name.empty() ? fmt::format("object_{}", k) : o.name;
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string cell; std::getline(s, cell, ',');) out.push_back(cell);
  if (!line.empty() && line.back() == ',') out.emplace_back();
  return out;
}

double parse_number(const std::string& text, const std::string& path, int line) {
  double v = 0.0;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
  if (r.ec != std::errc() || r.ptr != text.data() + text.size()) {
    throw InputError(fmt::format("{}:{}: '{}' is not a number", path, line, text));
  }
  return v;
}

}  // namespace

HeldMassSeries held_mass_series(const std::vector<ObjectSpec>& objects, const std::vector<GrainFrame>& frames,
                                double density_kg_m3) {
  HeldMassSeries out;
  for (const GrainFrame& f : frames) out.time_s.push_back(f.time_s);
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const ObjectSpec& o = objects[k];
    if (o.dynamic) continue;
    out.objects.push_back(object_label(o, k));
    std::vector<double>& mass = out.mass_kg.emplace_back();
    for (const GrainFrame& f : frames) {
      mass.push_back(mass_held_by_object_kg(f.grains, transformed(o.body, o.pose_at(f.time_s)), density_kg_m3));
    }
  }
  return out;
}

void write_held_mass_csv(const std::string& path, const HeldMassSeries& series) {
  std::ofstream out(path);
  if (!out) throw InputError(fmt::format("{}: cannot write", path));
  out << "time_s";
  for (const std::string& name : series.objects) out << ',' << name << kMassSuffix;
  out << '\n';
  for (std::size_t f = 0; f < series.time_s.size(); ++f) {
    out << fmt::format("{}", series.time_s[f]);
    for (const auto& mass : series.mass_kg) out << fmt::format(",{}", mass[f]);
    out << '\n';
  }
  if (!out) throw InputError(fmt::format("{}: write failed", path));
}

std::map<std::string, HeldMassTrack> read_held_mass_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("{}: cannot read the held mass", path));
  std::string line;
  if (!std::getline(in, line)) throw InputError(fmt::format("{}:1: empty; expected a header time_s,...", path));
  const std::vector<std::string> header = split_csv(line);
  if (header.empty() || header.front() != "time_s") {
    throw InputError(fmt::format("{}:1: the first column must be time_s", path));
  }
  const std::string suffix = kMassSuffix;
  std::map<std::string, HeldMassTrack> tracks;
  std::vector<std::pair<std::size_t, HeldMassTrack*>> columns;
  for (std::size_t c = 1; c < header.size(); ++c) {
    const std::string& h = header[c];
    if (h.size() > suffix.size() && h.ends_with(suffix)) {
      columns.emplace_back(c, &tracks[h.substr(0, h.size() - suffix.size())]);
    }
  }
  for (int number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> cells = split_csv(line);
    if (cells.size() != header.size()) {
      throw InputError(fmt::format("{}:{}: {} values, the header has {}", path, number, cells.size(), header.size()));
    }
    const double t = parse_number(cells[0], path, number);
    for (auto& [c, track] : columns) {
      track->time_s.push_back(t);
      track->mass_kg.push_back(parse_number(cells[c], path, number));
    }
  }
  return tracks;
}

}  // namespace repose
