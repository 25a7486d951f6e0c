#include "models/core/run/build_info.h"

#include <GL/gl.h>
#include <png.h>

#include <Eigen/Core>
#include <CLI/Version.hpp>
#include <bullet/LinearMath/btScalar.h>
#include <ceres/version.h>

#include <array>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "models/core/gl/osmesa_context.h"

namespace repose {
namespace {

const char* const kUnknown = "unknown";

// The source tree: this file is models/core/run/build_info.cpp in it (the
// compiler sees its absolute path, as CMake passes it).
std::filesystem::path source_dir() {
#ifdef REPOSE_SOURCE_DIR
  return REPOSE_SOURCE_DIR;
#else
  const std::filesystem::path self(__FILE__);
  if (!self.is_absolute()) return {};
  return self.parent_path().parent_path().parent_path();
#endif
}

// Runs a shell command (stderr discarded) and keeps its standard output
// without the trailing newline; false when it cannot run or exits non-zero.
bool run_and_read(const std::string& command, std::string* output) {
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen((command + " 2>/dev/null").c_str(), "r"), ::pclose);
  if (!pipe) return false;
  std::array<char, 256> chunk;
  output->clear();
  std::size_t n = 0;
  while ((n = std::fread(chunk.data(), 1, chunk.size(), pipe.get())) > 0) output->append(chunk.data(), n);
  const int status = ::pclose(pipe.release());
  while (!output->empty() && (output->back() == '\n' || output->back() == '\r')) output->pop_back();
  return status == 0;
}

std::string shell_quoted(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

void fill_git(BuildInfo* info) {
#ifdef REPOSE_GIT_COMMIT
  info->git_commit = REPOSE_GIT_COMMIT;
#ifdef REPOSE_GIT_DIRTY
  info->git_dirty = REPOSE_GIT_DIRTY;
#endif
#else
  info->git_commit = kUnknown;
  const std::filesystem::path dir = source_dir();
  std::error_code ec;
  if (dir.empty() || !std::filesystem::exists(dir / ".git", ec)) return;
  const std::string git = "git -C " + shell_quoted(dir.string());
  std::string commit;
  if (!run_and_read(git + " rev-parse HEAD", &commit) || commit.size() != 40) return;
  info->git_commit = commit;
  // dirty: the code differs from the commit. Changes under data/ (what the
  // canonical-data script writes while it runs) are results, not code: a
  // run made while they are being copied in is not from changed code.
  std::string changes;
  if (run_and_read(git + " status --porcelain --untracked-files=no -- . ':(exclude)data'", &changes)) {
    info->git_dirty = !changes.empty();
  }
#endif
}

std::string compiler() {
#if defined(__clang__)
  return fmt::format("Clang {}.{}.{}", __clang_major__, __clang_minor__, __clang_patchlevel__);
#elif defined(__GNUC__)
  return fmt::format("GCC {}.{}.{}", __GNUC__, __GNUC_MINOR__, __GNUC_PATCHLEVEL__);
#else
  return kUnknown;
#endif
}

std::string build_type() {
  std::string type;
#ifdef REPOSE_BUILD_TYPE
  type = REPOSE_BUILD_TYPE;
#else
#if defined(__OPTIMIZE__)
  type = "optimised";
#else
  type = "not optimised";
#endif
#if defined(NDEBUG)
  type += ", NDEBUG";
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
  type += ", AddressSanitizer";
#endif
  return type;
}

std::string opengl_version() {
  try {
    OsmesaContext context(1, 1);
    const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    return version != nullptr ? version : kUnknown;
  } catch (const std::exception& e) {
    return fmt::format("unavailable ({})", e.what());
  }
}

#ifdef REPOSE_YAML_CPP_VERSION
const char* const kYamlCppVersion = REPOSE_YAML_CPP_VERSION;
#else
const char* const kYamlCppVersion = kUnknown;
#endif
#ifdef REPOSE_ODE_VERSION
const char* const kOdeVersion = REPOSE_ODE_VERSION;
#else
const char* const kOdeVersion = kUnknown;
#endif

}  // namespace

BuildInfo build_info(const BuildInfoOptions& options) {
  BuildInfo info;
  fill_git(&info);
  info.compiler = compiler();
  info.build_type = build_type();
  info.libraries = {
      {"Eigen", fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
      {"yaml-cpp", kYamlCppVersion},
      {"fmt", fmt::format("{}.{}.{}", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100)},
      {"CLI11", CLI11_VERSION},
      {"libpng", png_get_libpng_ver(nullptr)},  // the library loaded at run time
      {"Ceres", CERES_VERSION_STRING},
      {"Bullet", fmt::format("{}.{}", BT_BULLET_VERSION / 100, BT_BULLET_VERSION % 100)},
      {"ODE", kOdeVersion},
  };
  if (options.query_opengl) info.libraries.push_back({"OpenGL (OSMesa)", opengl_version()});
  return info;
}

std::string describe_build(const BuildInfo& info) {
  std::string text = fmt::format("git commit {}{}\n", info.git_commit, info.git_dirty ? " (dirty)" : "");
  text += fmt::format("compiler {}, build {}\n", info.compiler, info.build_type);
  for (const auto& library : info.libraries) text += fmt::format("{} {}\n", library.name, library.version);
  return text;
}

}  // namespace repose
