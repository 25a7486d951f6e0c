#include "validation/liggghts/liggghts_dump.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include "models/core/base/error.h"
#include "models/core/base/memory_budget.h"
#include "models/core/io/input_file.h"

namespace repose {

namespace {

// Line-by-line reader that knows where it is, for messages.
class DumpReader {
 public:
  // InputStream checks the file (a regular file within the dump bound) and
  // never reads past it.
  explicit DumpReader(const std::string& path) : path_(path), in_(path, input_kind::kLiggghtsDump) {}

  const std::string& path() const { return path_; }
  // The file's size, an upper bound for counts the file declares.
  std::uint64_t file_bytes() const { return in_.file().size(); }

  bool next(std::string* line) {
    if (!std::getline(in_, *line)) return false;
    ++line_number_;
    if (!line->empty() && line->back() == '\r') line->pop_back();
    return true;
  }

  // The next line, which must exist (else: truncated, expecting `what`).
  std::string require(const char* what) {
    std::string line;
    if (!next(&line)) fail(fmt::format("truncated: expected {} after the end of the file", what));
    return line;
  }

  [[noreturn]] void fail(const std::string& reason) const { fail_at(line_number_, reason); }
  [[noreturn]] void fail_at(long line, const std::string& reason) const {
    throw InputError(line > 0 ? fmt::format("{}:{}: {}", path_, line, reason) : fmt::format("{}: {}", path_, reason));
  }

  double number(const std::string& token, const char* what) const {
    double v = 0.0;
    const auto r = std::from_chars(token.data(), token.data() + token.size(), v);
    if (r.ec != std::errc() || r.ptr != token.data() + token.size()) {
      // from_chars rejects "nan"/"inf" spellings of some writers the same way: both are errors here
      fail(fmt::format("{}: expected a number, got '{}'", what, token));
    }
    if (!std::isfinite(v)) fail(fmt::format("{}: non-finite value '{}'", what, token));
    return v;
  }

  long integer(const std::string& token, const char* what) const {
    long v = 0;
    const auto r = std::from_chars(token.data(), token.data() + token.size(), v);
    if (r.ec != std::errc() || r.ptr != token.data() + token.size()) {
      fail(fmt::format("{}: expected an integer, got '{}'", what, token));
    }
    return v;
  }

 private:
  std::string path_;
  InputStream in_;
  long line_number_ = 0;
};

std::vector<std::string> split(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// The first word of a line that must hold a number; an empty line is an error.
std::string first_word(DumpReader& r, const std::string& line, const char* item) {
  const auto words = split(line);
  if (words.empty()) r.fail(fmt::format("{}: expected an integer, got an empty line", item));
  return words.front();
}

void expect_item(DumpReader& r, const std::string& line, const std::string& item) {
  if (line.rfind("ITEM: " + item, 0) != 0) r.fail(fmt::format("expected 'ITEM: {}', got '{}'", item, line));
}

// A count the file cannot hold, or whose arrays exceed the memory budget,
// is refused before allocating for it: a row holds at least one character
// and one separator per column.
void check_atom_count(const DumpReader& r, long count, std::size_t columns) {
  const std::uint64_t max_rows = r.file_bytes() / (2 * columns);
  if (static_cast<std::uint64_t>(count) > max_rows) {
    r.fail(fmt::format("NUMBER OF ATOMS {} is more rows than the file can hold ({} bytes, at most {} rows of {} columns)",
                       count, r.file_bytes(), max_rows, columns));
  }
  // id, type, position and radius per atom
  constexpr std::uint64_t kBytesPerAtom = sizeof(long) + sizeof(int) + 4 * sizeof(double);
  require_memory(memory_estimate::items_bytes(static_cast<std::uint64_t>(count), kBytesPerAtom),
                 fmt::format("{}: a dump frame of {} atoms", r.path(), count));
}

DumpFrame read_frame(DumpReader& r, const std::string& timestep_line) {
  DumpFrame f;
  expect_item(r, timestep_line, "TIMESTEP");
  f.timestep = r.integer(first_word(r, r.require("the time step"), "TIMESTEP"), "TIMESTEP");
  expect_item(r, r.require("ITEM: NUMBER OF ATOMS"), "NUMBER OF ATOMS");
  const long count = r.integer(first_word(r, r.require("the number of atoms"), "NUMBER OF ATOMS"), "NUMBER OF ATOMS");
  if (count < 0) r.fail(fmt::format("NUMBER OF ATOMS: expected a non-negative count, got {}", count));
  expect_item(r, r.require("ITEM: BOX BOUNDS"), "BOX BOUNDS");
  for (int a = 0; a < 3; ++a) {
    const auto w = split(r.require("box bounds"));
    if (w.size() < 2) r.fail("BOX BOUNDS: expected 'lo hi'");
    f.box_lo_m[a] = r.number(w[0], "BOX BOUNDS");
    f.box_hi_m[a] = r.number(w[1], "BOX BOUNDS");
  }
  const std::string atoms = r.require("ITEM: ATOMS");
  expect_item(r, atoms, "ATOMS");
  const auto columns = split(atoms.substr(std::string("ITEM: ATOMS").size()));
  std::map<std::string, int> index;
  for (std::size_t c = 0; c < columns.size(); ++c) index.emplace(columns[c], static_cast<int>(c));
  for (const char* needed : {"id", "x", "y", "z", "radius"}) {
    if (!index.contains(needed)) r.fail(fmt::format("ITEM: ATOMS: missing column '{}' (have: {})", needed, atoms));
  }
  const int ci = index["id"], cx = index["x"], cy = index["y"], cz = index["z"], cr = index["radius"];
  const int ct = index.contains("type") ? index["type"] : -1;
  const bool velocity = index.contains("vx") && index.contains("vy") && index.contains("vz");
  const int cvx = velocity ? index["vx"] : -1, cvy = velocity ? index["vy"] : -1, cvz = velocity ? index["vz"] : -1;
  check_atom_count(r, count, columns.size());

  f.id.resize(count);
  f.type.assign(count, 1);
  f.grains.position_m.resize(count, 3);
  f.grains.radius_m.resize(count);
  if (velocity) f.grains.velocity_m_s.resize(count, 3);
  for (long k = 0; k < count; ++k) {
    const auto w = split(r.require(fmt::format("{} atom rows (got {})", count, k).c_str()));
    if (w.size() != columns.size()) {
      r.fail(fmt::format("expected {} columns, got {} (fewer rows than NUMBER OF ATOMS {}?)", columns.size(), w.size(),
                         count));
    }
    f.id[k] = r.integer(w[ci], "id");
    if (ct >= 0) f.type[k] = static_cast<int>(r.integer(w[ct], "type"));
    f.grains.position_m.row(k) << r.number(w[cx], "x"), r.number(w[cy], "y"), r.number(w[cz], "z");
    f.grains.radius_m[k] = r.number(w[cr], "radius");
    if (f.grains.radius_m[k] <= 0.0) r.fail(fmt::format("radius: expected a positive value, got {}", w[cr]));
    if (velocity) f.grains.velocity_m_s.row(k) << r.number(w[cvx], "vx"), r.number(w[cvy], "vy"), r.number(w[cvz], "vz");
  }
  return f;
}

}  // namespace

std::vector<DumpFrame> read_dump_file(const std::string& path) {
  DumpReader r(path);
  std::vector<DumpFrame> frames;
  for (std::string line; r.next(&line);) {
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (line.rfind("ITEM:", 0) != 0) {
      r.fail(fmt::format("expected 'ITEM: TIMESTEP' (more rows than NUMBER OF ATOMS?), got '{}'", line));
    }
    frames.push_back(read_frame(r, line));
  }
  return frames;
}

DumpFrame read_last_dump_frame(const std::string& path) {
  auto frames = read_dump_file(path);
  if (frames.empty()) throw InputError(fmt::format("{}: empty dump file (no frame)", path));
  return std::move(frames.back());
}

std::vector<std::string> list_dump_files(const std::string& directory) {
  std::vector<std::pair<long, std::string>> found;
  std::error_code ec;
  if (!std::filesystem::is_directory(directory, ec)) {
    throw InputError(fmt::format("{}: not a directory of dumps", directory));
  }
  for (const auto& entry : std::filesystem::directory_iterator(directory)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind("dump.", 0) != 0 || name.size() < 10 || name.substr(name.size() - 4) != ".txt") continue;
    const std::string digits = name.substr(5, name.size() - 9);
    long step = 0;
    const auto r = std::from_chars(digits.data(), digits.data() + digits.size(), step);
    if (r.ec != std::errc() || r.ptr != digits.data() + digits.size()) continue;
    found.emplace_back(step, entry.path().string());
  }
  std::sort(found.begin(), found.end());
  std::vector<std::string> out;
  for (auto& f : found) out.push_back(std::move(f.second));
  return out;
}

}  // namespace repose
