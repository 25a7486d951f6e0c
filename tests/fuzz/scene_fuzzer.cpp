// libFuzzer target: the scene loader on arbitrary YAML text. The scene
// "lives" in /dev/shm/repose-fuzz-scene-PID/, where a few valid files are
// written first (a mesh, a .npy and a PNG height map, the names the seed
// corpus uses), so that inputs get past the file references into the rest
// of the loader.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "models/core/base/error.h"
#include "models/ground/ground_section.h"
#include "validation/particles/dem_section.h"
#include "models/core/io/npy_io.h"
#include "models/core/io/png_io.h"

// The common loader with the sections of the ground model and the particle
// references (the fuzz build links only what these need).
static const repose::SectionTypes kSections = {repose::ground_model_section_type(), repose::dem_section_type()};
#include "models/core/config/scene_loader.h"

namespace {

std::string scene_dir() {
  static const std::string dir = "/dev/shm/repose-fuzz-scene-" + std::to_string(getpid());
  return dir;
}

void write_referenced_files() {
  std::filesystem::create_directories(scene_dir());
  std::ofstream(scene_dir() + "/cube.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
                                              "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  repose::ArrayXXdR heights(8, 16);
  for (int j = 0; j < 8; ++j) {
    for (int i = 0; i < 16; ++i) heights(j, i) = 0.01 + 0.001 * i + 0.002 * j;
  }
  repose::write_npy_2d(scene_dir() + "/heights_16x8.npy", heights);
  repose::write_png16(scene_dir() + "/heights_16x8.png", heights * 1.0e5);
}

void remove_scene_dir() {
  std::error_code ec;
  std::filesystem::remove_all(scene_dir(), ec);
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  write_referenced_files();
  std::atexit(remove_scene_dir);
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)repose::load_scene_from_string(text, scene_dir() + "/scene.yaml", kSections);
  } catch (const repose::InputError&) {
  }
  return 0;
}
