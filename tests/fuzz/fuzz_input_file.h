#pragma once
// The parsers read files, so each fuzz input is written to a file in memory
// (/dev/shm) first. Only InputError may escape a parser: anything else
// (a crash, a sanitizer report, another exception) is a finding.

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace repose::fuzz {

// One path per process (a target uses one suffix); removed at exit.
inline const std::string& input_path(const char* suffix) {
  static const std::string path = "/dev/shm/repose-fuzz-" + std::to_string(getpid()) + suffix;
  static const bool cleanup_registered = std::atexit([] { std::remove(path.c_str()); }) == 0;
  (void)cleanup_registered;
  return path;
}

inline const std::string& write_input(const std::uint8_t* data, std::size_t size, const char* suffix) {
  const std::string& path = input_path(suffix);
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) std::abort();
  if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
  std::fclose(f);
  return path;
}

}  // namespace repose::fuzz
