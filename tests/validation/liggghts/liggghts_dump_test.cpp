#include "validation/liggghts/liggghts_dump.h"

#include <sys/stat.h>

#include <cstdlib>
#include <utility>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

namespace fs = std::filesystem;

class LiggghtsDump : public ::testing::Test {
 protected:
  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p) << text;
    return p.string();
  }

  // The message of the InputError reading `text` throws, or "" when it does not throw.
  std::string error_of(const std::string& text) {
    try {
      read_dump_file(write("bad.txt", text));
    } catch (const InputError& e) {
      return e.what();
    }
    return {};
  }

  test_support::TempDir temp_;
  const fs::path dir_ = temp_.path;
};

const std::string kHeader =
    "ITEM: TIMESTEP\n500\nITEM: NUMBER OF ATOMS\n2\nITEM: BOX BOUNDS ff ff ff\n0 0.04\n0 0.04\n0 0.05\n";

TEST_F(LiggghtsDump, ReadsColumnsInAnyOrder) {
  const std::string path = write("d.txt", kHeader +
                                              "ITEM: ATOMS radius z id x vx y\n"
                                              "0.002 0.01 7 0.011 5 0.012\n"
                                              "0.0018 0.02 3 0.021 6 0.022\n");
  const auto frames = read_dump_file(path);
  ASSERT_EQ(frames.size(), 1u);
  const DumpFrame& f = frames[0];
  EXPECT_EQ(f.timestep, 500);
  EXPECT_DOUBLE_EQ(f.box_hi_m[2], 0.05);
  ASSERT_EQ(f.grains.size(), 2);
  EXPECT_EQ(f.id[0], 7);
  EXPECT_EQ(f.type[0], 1);  // absent: 1
  EXPECT_DOUBLE_EQ(f.grains.position_m(0, 0), 0.011);
  EXPECT_DOUBLE_EQ(f.grains.position_m(0, 1), 0.012);
  EXPECT_DOUBLE_EQ(f.grains.position_m(0, 2), 0.01);
  EXPECT_DOUBLE_EQ(f.grains.radius_m[1], 0.0018);
  EXPECT_EQ(f.id[1], 3);
}

TEST_F(LiggghtsDump, ReadsSeveralFramesAndTheLast) {
  const std::string frame = kHeader + "ITEM: ATOMS id type x y z radius\n1 1 0 0 0.1 0.002\n2 1 0 0 0.2 0.002\n";
  std::string second = frame;
  second.replace(second.find("500"), 3, "900");
  const std::string path = write("d.txt", frame + second);
  EXPECT_EQ(read_dump_file(path).size(), 2u);
  EXPECT_EQ(read_last_dump_frame(path).timestep, 900);
}

TEST_F(LiggghtsDump, RefusesMalformedFilesWithTheReason) {
  const std::string atoms = "ITEM: ATOMS id type x y z radius\n";
  struct Case {
    std::string text;
    std::string expected;
  } cases[] = {
      {kHeader + atoms + "1 1 0 0 0.1 0.002\n", "truncated"},                          // one row of two
      {kHeader + atoms + "1 1 0 0 0.1 0.002\n2 1 0 0\n", "expected 6 columns"},      // short row
      {kHeader + atoms + "1 1 0 0 0.1 0.002\n2 1 0 0 0.2 0.002\n3 1 0 0 0.3 0.002\n", "more rows"},
      {kHeader + atoms + "1 1 0 zero 0.1 0.002\n2 1 0 0 0.2 0.002\n", "y: expected a number, got 'zero'"},
      {kHeader + atoms + "1 1 0 0 nan 0.002\n2 1 0 0 0.2 0.002\n", "non-finite"},
      {kHeader + atoms + "1 1 0 0 0.1 -0.002\n2 1 0 0 0.2 0.002\n", "radius: expected a positive"},
      {kHeader + "ITEM: ATOMS id type x y radius\n1 1 0 0 0.002\n2 1 0 0 0.002\n", "missing column 'z'"},
      {"ITEM: TIMESTEP\n500\nITEM: NUMBER OF ATOMS\n", "truncated"},
      {"ITEM: TIMESTEP\n500\nITEM: NUMBER OF ATOMS\ntwo\n", "expected an integer, got 'two'"},
      {"hello\n", "expected 'ITEM: TIMESTEP'"},
  };
  for (const Case& c : cases) {
    const std::string message = error_of(c.text);
    EXPECT_NE(message.find(c.expected), std::string::npos) << "expected '" << c.expected << "' in: " << message;
    EXPECT_NE(message.find("bad.txt:"), std::string::npos) << message;
  }
  EXPECT_THROW(read_dump_file((dir_ / "missing.txt").string()), InputError);
  EXPECT_THROW(read_last_dump_frame(write("empty.txt", "")), InputError);
}

// A count the file cannot hold was allocated first (a few bytes declaring
// 10^15 atoms ended in bad_alloc); now it is refused from the file's size.
TEST_F(LiggghtsDump, RefusesACountTheFileCannotHoldBeforeAllocating) {
  const std::string message = error_of(
      "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n1000000000000000\nITEM: BOX BOUNDS ff ff ff\n0 1\n0 1\n0 1\n"
      "ITEM: ATOMS id x y z radius\n1 0 0 0 0.1\n");
  EXPECT_NE(message.find("NUMBER OF ATOMS 1000000000000000 is more rows than the file can hold"), std::string::npos)
      << message;
}

// A FIFO waited forever for a writer; a directory or device is no dump either.
TEST_F(LiggghtsDump, RefusesFilesThatAreNotRegularFiles) {
  const std::string fifo = (dir_ / "dump.0.txt").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  for (const auto& [path, reason] : {std::pair<std::string, std::string>{fifo, "is a FIFO (named pipe)"},
                                     {"/dev/zero", "is a character device"},
                                     {dir_.string(), "is a directory"}}) {
    try {
      read_dump_file(path);
      ADD_FAILURE() << path << " was read";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find(path + ": " + reason), std::string::npos) << e.what();
    }
  }
}

TEST_F(LiggghtsDump, ListsDumpFilesByStep) {
  for (const char* name : {"dump.1000.txt", "dump.200.txt", "dump.30.txt", "other.txt"}) write(name, "");
  const auto files = list_dump_files(dir_.string());
  ASSERT_EQ(files.size(), 3u);
  EXPECT_EQ(fs::path(files[0]).filename(), "dump.30.txt");
  EXPECT_EQ(fs::path(files[2]).filename(), "dump.1000.txt");
}

}  // namespace
}  // namespace repose
