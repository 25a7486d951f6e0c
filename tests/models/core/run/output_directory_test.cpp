#include "models/core/run/output_directory.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/core/base/error.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

using test_support::read_all;

struct TempDir : test_support::TempDir {
  TempDir() : test_support::TempDir("repose_outdir") {}
};

std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
  return names;
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

TEST(OutputDirectory, NothingAppearsBeforeCommitAndAllAfter) {
  TempDir dir;
  const fs::path target = dir.path / "run";
  {
    OutputDirectory out = OutputDirectory::open(target.string(), false);
    write_text(out.path("a.txt"), "A");
    write_text(out.path("sub/b.txt"), "B");
    EXPECT_FALSE(fs::exists(target));
    EXPECT_EQ(out.temporary().parent_path(), dir.path);
    EXPECT_EQ(out.temporary().filename().string().rfind(".run.tmp-", 0), 0u);
    out.commit();
    EXPECT_TRUE(out.committed());
  }
  EXPECT_EQ(read_all(target / "a.txt"), "A");
  EXPECT_EQ(read_all(target / "sub" / "b.txt"), "B");
  EXPECT_EQ(names_in(dir.path), std::vector<std::string>{"run"});  // no temporaries left
}

TEST(OutputDirectory, WithoutCommitTheTemporaryIsRemovedAndNoTargetMade) {
  TempDir dir;
  const fs::path target = dir.path / "run";
  try {
    OutputDirectory out = OutputDirectory::open(target.string(), false);
    write_text(out.path("a.txt"), "A");
    throw std::runtime_error("the run failed");
  } catch (const std::runtime_error&) {
  }
  EXPECT_TRUE(fs::is_empty(dir.path));
}

TEST(OutputDirectory, RefusesNonEmptyTargetUnlessForced) {
  TempDir dir;
  const fs::path target = dir.path / "run";
  fs::create_directory(target);
  write_text((target / "old.txt").string(), "old");
  try {
    OutputDirectory::open(target.string(), false);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find(target.string()), std::string::npos) << message;
    EXPECT_NE(message.find("--force"), std::string::npos) << message;
  }
  EXPECT_EQ(read_all(target / "old.txt"), "old");

  // forced but not committed: the old result stays
  {
    OutputDirectory out = OutputDirectory::open(target.string(), true);
    write_text(out.path("new.txt"), "new");
  }
  EXPECT_EQ(names_in(target), std::vector<std::string>{"old.txt"});

  // forced and committed: replaced as a whole, nothing aside remains
  {
    OutputDirectory out = OutputDirectory::open(target.string() + "/", true);
    write_text(out.path("new.txt"), "new");
    out.commit();
  }
  EXPECT_EQ(names_in(target), std::vector<std::string>{"new.txt"});
  EXPECT_EQ(names_in(dir.path), std::vector<std::string>{"run"});
}

TEST(OutputDirectory, AcceptsAnEmptyExistingFolderAndRefusesAFile) {
  TempDir dir;
  fs::create_directory(dir.path / "empty");
  {
    OutputDirectory out = OutputDirectory::open((dir.path / "empty").string(), false);
    write_text(out.path("x"), "x");
    out.commit();
  }
  EXPECT_EQ(read_all(dir.path / "empty" / "x"), "x");

  write_text((dir.path / "file").string(), "f");
  EXPECT_THROW(OutputDirectory::open((dir.path / "file").string(), true), InputError);
  EXPECT_EQ(read_all(dir.path / "file"), "f");
}

TEST(OutputDirectory, CreatesMissingParents) {
  TempDir dir;
  const fs::path target = dir.path / "a" / "b" / "run";
  OutputDirectory out = OutputDirectory::open(target.string(), false);
  write_text(out.path("x"), "x");
  out.commit();
  EXPECT_EQ(read_all(target / "x"), "x");
}

TEST(OutputDirectory, NamesOutsideTheFolderAreRefused) {
  TempDir dir;
  OutputDirectory out = OutputDirectory::open((dir.path / "run").string(), false);
  EXPECT_THROW(out.path("../escape"), std::logic_error);
  EXPECT_THROW(out.path("/abs"), std::logic_error);
}

// A child process writes part of a run and is killed (SIGKILL: no destructor,
// no clean-up). The target must not exist (or keep its old contents); only a
// hidden temporary may remain, and the next open() removes it.
void run_child_and_kill_it(const fs::path& target, bool force) {
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(ready[0]);
    try {
      OutputDirectory out = OutputDirectory::open(target.string(), force);
      write_text(out.path("manifest.json"), "{\"half\": ");
      char byte = 1;
      if (::write(ready[1], &byte, 1) != 1) ::_exit(3);
      for (;;) ::pause();  // a long run, never committed
    } catch (...) {
      ::_exit(2);  // never return into the test runner from the child
    }
  }
  ::close(ready[1]);
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1);
  ::close(ready[0]);
  ASSERT_EQ(::kill(child, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status));
}

TEST(OutputDirectory, KilledRunLeavesNoTargetAndItsTemporaryIsCleanedLater) {
  TempDir dir;
  const fs::path target = dir.path / "run";
  run_child_and_kill_it(target, false);
  EXPECT_FALSE(fs::exists(target));
  const std::vector<std::string> left = names_in(dir.path);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].rfind(".run.tmp-", 0), 0u) << left[0];

  OutputDirectory again = OutputDirectory::open(target.string(), false);
  for (const auto& name : names_in(dir.path)) {
    EXPECT_EQ(dir.path / name, again.temporary()) << "stale temporary not removed: " << name;
  }
}

TEST(OutputDirectory, KilledForcedRunKeepsTheOldResult) {
  TempDir dir;
  const fs::path target = dir.path / "run";
  fs::create_directory(target);
  write_text((target / "manifest.json").string(), "{\"old\": true}");
  run_child_and_kill_it(target, true);
  EXPECT_EQ(read_all(target / "manifest.json"), "{\"old\": true}");
  EXPECT_EQ(names_in(target), std::vector<std::string>{"manifest.json"});
}

TEST(WriteFileAtomically, ReplacesTheFileOnlyWhenTheWriterSucceeds) {
  TempDir dir;
  const std::string path = (dir.path / "image.png").string();
  write_file_atomically(path, [](const std::string& temporary) { write_text(temporary, "first"); });
  EXPECT_EQ(read_all(path), "first");
  EXPECT_THROW(write_file_atomically(path,
                                     [](const std::string& temporary) {
                                       write_text(temporary, "half");
                                       throw std::runtime_error("writer failed");
                                     }),
               std::runtime_error);
  EXPECT_EQ(read_all(path), "first");
  EXPECT_EQ(names_in(dir.path), std::vector<std::string>{"image.png"});
}

}  // namespace
}  // namespace repose
