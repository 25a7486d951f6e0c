#include "models/core/io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "models/core/base/error.h"

namespace repose {
namespace {

constexpr std::array kKnownKinds = {
    input_kind::kScene, input_kind::kCalibration, input_kind::kExperiment, input_kind::kReference, input_kind::kRunRecord,
    input_kind::kMesh,  input_kind::kNpy,         input_kind::kPng,        input_kind::kLiggghtsDump,
    input_kind::kLiggghtsLog,
};

InputKind kind_named(const char* name) {
  InputKind largest = kKnownKinds.front();
  for (const InputKind& k : kKnownKinds) {
    if (std::strcmp(k.name, name) == 0) return k;
    if (k.max_bytes > largest.max_bytes) largest = k;
  }
  return {name, largest.max_bytes};
}

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  throw InputError(fmt::format("{}: {}", path, reason));
}

// Why open() or stat() failed, in words a user can act on.
std::string open_failure(int error) {
  switch (error) {
    case ENOENT: return "no such file";
    case ENOTDIR: return "no such file (a part of the path is not a directory)";
    case EACCES: return "cannot be read: permission denied";
    case ELOOP: return "cannot be read: too many symbolic links";
    default: return fmt::format("cannot be read: {}", std::strerror(error));
  }
}

// Why a file of this type is not read; empty for a regular file.
std::string type_refusal(mode_t mode, const InputKind& kind) {
  if (S_ISREG(mode)) return {};
  if (S_ISDIR(mode)) return fmt::format("is a directory, not a {} file", kind.name);
  const char* what = S_ISFIFO(mode)  ? "a FIFO (named pipe)"
                     : S_ISCHR(mode) ? "a character device"
                     : S_ISBLK(mode) ? "a block device"
                     : S_ISSOCK(mode) ? "a socket"
                                      : "not a file";
  return fmt::format("is {}, not a regular {} file", what, kind.name);
}

// The size of a regular file, or throws for any other type or a size over the bound.
std::uint64_t checked_size(const std::string& path, const struct stat& st, const InputKind& kind) {
  const std::string refusal = type_refusal(st.st_mode, kind);
  if (!refusal.empty()) fail(path, refusal);
  const auto size = static_cast<std::uint64_t>(st.st_size);
  if (size > kind.max_bytes) {
    fail(path, fmt::format("is {} bytes, more than a {} file may have ({} bytes)", size, kind.name, kind.max_bytes));
  }
  return size;
}

}  // namespace

InputFile InputFile::open(const std::string& path, const InputKind& kind) {
  // stat first, so that a device or FIFO is never even opened (opening some
  // devices has effects); then check the opened descriptor again, so that
  // the file read is the file checked.
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail(path, open_failure(errno));
  checked_size(path, st, kind);
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) fail(path, open_failure(errno));
  InputFile file(fd, path, kind, 0);
  if (::fstat(fd, &st) != 0) fail(path, open_failure(errno));
  file.size_ = checked_size(path, st, kind);
  ::fcntl(fd, F_SETFL, ::fcntl(fd, F_GETFL) & ~O_NONBLOCK);
  return file;
}

InputFile::InputFile(InputFile&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      path_(std::move(other.path_)),
      kind_(other.kind_),
      size_(other.size_),
      position_(other.position_) {}

InputFile& InputFile::operator=(InputFile&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = std::exchange(other.fd_, -1);
    path_ = std::move(other.path_);
    kind_ = other.kind_;
    size_ = other.size_;
    position_ = other.position_;
  }
  return *this;
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

std::size_t InputFile::read(void* into, std::size_t n) {
  REPOSE_DEMAND(fd_ >= 0);
  auto* out = static_cast<char*>(into);
  std::size_t done = 0;
  const std::size_t wanted = static_cast<std::size_t>(std::min<std::uint64_t>(n, remaining()));
  while (done < wanted) {
    const ssize_t got = ::read(fd_, out + done, wanted - done);
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) fail(path_, fmt::format("read failed: {}", std::strerror(errno)));
    if (got == 0) break;  // the file shrank since it was opened
    done += static_cast<std::size_t>(got);
  }
  position_ += done;
  return done;
}

std::string InputFile::read_rest() {
  std::string text(static_cast<std::size_t>(remaining()), '\0');
  text.resize(read(text.data(), text.size()));
  return text;
}

std::string read_input_file(const std::string& path, const InputKind& kind) {
  return InputFile::open(path, kind).read_rest();
}

// A read buffer over an InputFile for std::istream.
class InputStream::Buffer : public std::streambuf {
 public:
  explicit Buffer(InputFile file) : file_(std::move(file)), data_(64 * 1024) {}
  const InputFile& file() const { return file_; }

 protected:
  int_type underflow() override {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    const std::size_t got = file_.read(data_.data(), data_.size());
    if (got == 0) return traits_type::eof();
    setg(data_.data(), data_.data(), data_.data() + got);
    return traits_type::to_int_type(*gptr());
  }

 private:
  InputFile file_;
  std::vector<char> data_;
};

InputStream::InputStream(const std::string& path, const InputKind& kind)
    : std::istream(nullptr), buffer_(std::make_unique<Buffer>(InputFile::open(path, kind))) {
  rdbuf(buffer_.get());
  exceptions(std::ios::badbit);  // a read error propagates as its InputError, not as a silent end of file
}

InputStream::~InputStream() = default;

const InputFile& InputStream::file() const { return buffer_->file(); }

void require_regular_file(const std::string& path, const InputKind& kind) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0) fail(path, open_failure(errno));
  checked_size(path, st, kind);
}

void require_regular_file(const std::string& path, const char* kind_name) {
  require_regular_file(path, kind_named(kind_name));
}

}  // namespace repose
