#pragma once
// A run folder written atomically. Files are written into a fresh hidden
// sibling `.NAME.tmp-PID-XXXXXX` of the target; commit() renames it into
// place. Until then the target is untouched, so a run that fails, throws or
// is killed leaves the old result or nothing, never a half-written folder
// that a later run would trust.
//
//   OutputDirectory out = OutputDirectory::open("runs/a", force);
//   write_npy_2d(out.path("height.npy"), h);
//   out.commit();
//
// A run ended by SIGTERM, SIGINT or SIGHUP removes its temporary before it
// dies (interrupt_cleanup.h). Temporaries of runs killed otherwise (SIGKILL,
// a crash: their process is gone) are removed by the next open() of the
// same target. Not for folders shared between machines: the
// liveness check of a temporary's owner is by process id on this host.

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace repose {

class OutputDirectory {
 public:
  // Refuses (InputError naming the path) a target that is a file, or a
  // non-empty directory unless force. Creates missing parent directories.
  static OutputDirectory open(const std::string& target, bool force);

  OutputDirectory(OutputDirectory&& other) noexcept;
  OutputDirectory& operator=(OutputDirectory&&) = delete;
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;
  // Without commit(): removes the temporary; the target stays as it was.
  ~OutputDirectory();

  // Where to write the file `name` (relative, no ".."; parent folders are
  // created) before commit().
  std::string path(std::string_view name) const;
  // Moves the finished folder into place. When replacing (force), the old
  // folder is moved aside first and removed only after the rename succeeded.
  void commit();

  const std::filesystem::path& target() const { return target_; }
  const std::filesystem::path& temporary() const { return temporary_; }
  bool committed() const { return committed_; }

 private:
  OutputDirectory(std::filesystem::path target, std::filesystem::path temporary, bool force);

  std::filesystem::path target_;
  std::filesystem::path temporary_;  // empty once committed or moved from
  bool force_ = false;
  bool committed_ = false;
  int interrupt_slot_ = -1;  // remove_on_interrupt's slot for temporary_
};

// Writes one file atomically: `write` gets a temporary path beside `path`
// (`.NAME.tmp-PID-XXXXXX`), which is renamed onto `path` when write returns;
// if write throws, the temporary is removed and `path` is left as it was.
void write_file_atomically(const std::string& path, const std::function<void(const std::string& temporary)>& write);

}  // namespace repose
