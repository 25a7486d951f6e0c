#include "models/core/run/repository_path.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

namespace repose {
namespace {

namespace fs = std::filesystem;

TEST(RepositoryPath, PathsInsideTheRepositoryBecomeRelative) {
  const std::string root = REPOSE_SOURCE_DIR;
  EXPECT_EQ(repository_relative(root + "/experiments/scenes/dem_indent.yaml"), "experiments/scenes/dem_indent.yaml");
  EXPECT_EQ(repository_relative(root + "/data/../data/dem_indent"), "data/dem_indent");
  EXPECT_EQ(repository_relative("/usr/bin/python3"), "/usr/bin/python3");  // outside: unchanged
  EXPECT_EQ(repository_relative(""), "");
}

// Committed records (data/) name no path of the machine that made them.
TEST(RepositoryPath, CommittedDataHoldsNoAbsolutePath) {
  const std::regex absolute(R"re("(/(work|tmp|root|home|usr)/[^"]*)")re");
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(fs::path(REPOSE_SOURCE_DIR) / "data")) {
    const std::string ext = entry.path().extension().string();
    if (!entry.is_regular_file() || (ext != ".json" && ext != ".md" && ext != ".in")) continue;
    ++files;
    std::ifstream in(entry.path());
    std::stringstream text;
    text << in.rdbuf();
    std::smatch m;
    const std::string s = text.str();
    EXPECT_FALSE(std::regex_search(s, m, absolute)) << entry.path() << ": " << m.str();
    EXPECT_EQ(s.find(REPOSE_SOURCE_DIR), std::string::npos) << entry.path();
  }
  EXPECT_GE(files, 10);
}

}  // namespace
}  // namespace repose
