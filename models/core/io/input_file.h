#pragma once
// The one gate every file the program reads passes through (scenes,
// calibration and experiment files, meshes, height maps, LIGGGHTS dumps and
// logs, and whatever the next models read): the path must name a regular
// file (not a FIFO, a device, a socket or a directory) of at most the size
// bound of its kind, and no read ever goes past that bound, even when the
// file grows while it is read.
//
// Why: a FIFO given as a calibration file made open() wait forever for a
// writer, and /dev/zero was read until memory ran out (4.2 GB, bad_alloc).
// The file is opened without blocking and checked on the open descriptor
// (fstat), so nothing can swap the path between the check and the read.
//
//   const std::string text = read_input_file(path, input_kind::kScene);
//   InputFile f = InputFile::open(path, input_kind::kNpy);  // for readers
//   f.read(buffer, n);                                     // that stream
//
// Every failure is one InputError line: "PATH: REASON", e.g.
//   calib.yaml: is a FIFO (named pipe), not a regular calibration file
//   /dev/zero: is a character device, not a regular calibration file
//   big.yaml: is 20000000 bytes, more than a scene file may be (16777216 bytes)

#include <cstdint>
#include <istream>
#include <memory>
#include <streambuf>
#include <string>

namespace repose {

// What a file is read as (for messages) and how large it may be. The bounds
// are far above any real input of the kind and far below what would exhaust
// memory; what a file's contents then ask for (a shape, a pixel count, a
// particle count) is checked separately before allocating (memory_budget.h).
struct InputKind {
  const char* name;         // "scene", "calibration", ".npy", ... in messages
  std::uint64_t max_bytes;  // a larger file is refused before reading
};

namespace input_kind {
inline constexpr std::uint64_t kMiB = std::uint64_t{1} << 20;
// YAML text: yaml-cpp holds about 85 bytes of nodes per byte of text
// (measured: 16 MiB of scene YAML took 1.36 GB and 19 s to parse), so the
// bound keeps parsing under about 700 MB; real scenes are kilobytes.
inline constexpr InputKind kScene{"scene", 8 * kMiB};
inline constexpr InputKind kCalibration{"calibration", 8 * kMiB};
inline constexpr InputKind kExperiment{"experiment", 8 * kMiB};
// Calibration references (numbers in small YAML files).
inline constexpr InputKind kReference{"reference", 8 * kMiB};
// JSON records of earlier runs (manifest.json, liggghts_manifest.json).
inline constexpr InputKind kRunRecord{"run record", 64 * kMiB};
// OBJ/STL: a binary STL of 10 million triangles is 500 MB.
inline constexpr InputKind kMesh{"mesh", 512 * kMiB};
// A float64 array of 16384^2 (the largest grid) is 2 GiB plus its header.
inline constexpr InputKind kNpy{".npy", 2048 * kMiB + kMiB};
// A 16-bit grey 16384^2 PNG stored without compression is 512 MiB.
inline constexpr InputKind kPng{"PNG", 640 * kMiB};
// LIGGGHTS text output: about 100 bytes per particle and frame.
inline constexpr InputKind kLiggghtsDump{"LIGGGHTS dump", 4096 * kMiB};
inline constexpr InputKind kLiggghtsLog{"LIGGGHTS log", 1024 * kMiB};
}  // namespace input_kind

// An open, checked input file. Reads stop at size(), the size found when it
// was opened (at most kind.max_bytes): a file that grows meanwhile is read
// as it was; one that shrinks ends early (the parser reports it truncated).
class InputFile {
 public:
  // Throws InputError "PATH: REASON": no such file, not a directory on the
  // way, permission denied, a directory, a FIFO, a device, a socket, or
  // larger than kind.max_bytes. Never blocks (a FIFO fails at once).
  static InputFile open(const std::string& path, const InputKind& kind);

  InputFile(InputFile&& other) noexcept;
  InputFile& operator=(InputFile&& other) noexcept;
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;
  ~InputFile();

  const std::string& path() const { return path_; }
  const InputKind& kind() const { return kind_; }
  std::uint64_t size() const { return size_; }
  std::uint64_t position() const { return position_; }
  std::uint64_t remaining() const { return size_ - position_; }

  // Reads up to n bytes into `into`; fewer only at size() or where the file
  // ended early. Throws InputError on a read error.
  std::size_t read(void* into, std::size_t n);
  // The rest of the file, up to size().
  std::string read_rest();

 private:
  InputFile(int fd, std::string path, const InputKind& kind, std::uint64_t size)
      : fd_(fd), path_(std::move(path)), kind_(kind), size_(size) {}

  int fd_ = -1;
  std::string path_;
  InputKind kind_;
  std::uint64_t size_ = 0;
  std::uint64_t position_ = 0;
};

// The whole file as bytes, through InputFile::open's checks.
std::string read_input_file(const std::string& path, const InputKind& kind);

// A std::istream over a checked InputFile, for line-based parsers
// (std::getline). It ends at the file's size() like InputFile::read.
class InputStream : public std::istream {
 public:
  InputStream(const std::string& path, const InputKind& kind);
  ~InputStream() override;
  const InputFile& file() const;

 private:
  class Buffer;
  std::unique_ptr<Buffer> buffer_;
};

// The same checks without reading, for callers that hand the path to a
// library that opens it itself. Prefer InputFile: a path checked here can
// still be replaced before the library opens it.
void require_regular_file(const std::string& path, const InputKind& kind);
// As above, with the kind's bound looked up by its name ("scene", "mesh",
// ".npy", "PNG", ...; an unknown name gets the largest bound).
void require_regular_file(const std::string& path, const char* kind_name);

}  // namespace repose
