#include "validation/liggghts/liggghts_thermo.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "models/core/base/error.h"
#include "tests/support/temp_dir.h"

namespace repose {
namespace {

TEST(LiggghtsThermo, JoinsTheBlocksOfTheLastStyle) {
  const test_support::TempDir temp;
  const std::filesystem::path& dir = temp.path;
  const std::string log = (dir / "log.liggghts").string();
  std::ofstream(log) << "LIGGGHTS (Version x)\n"
                        "Step Atoms KinEng\n0 5 0\nLoop time of 0\n"
                        "thermo_style custom step atoms ke f_obj0[3]\n"
                        "Step Atoms KinEng obj0[3]\n0 5 1e-3 0\n100 5 2e-3 0.5\nLoop time of 1\n\n"
                        "Step Atoms KinEng obj0[3]\n100 5 2e-3 0.5\n200 5 1e-4 -0.25\nLoop time of 1\n";
  const ThermoTable t = read_thermo_table(log);
  ASSERT_EQ(t.columns.size(), 4u);
  EXPECT_EQ(t.column("obj0[3]"), 3);
  EXPECT_EQ(t.column("nothing"), -1);
  ASSERT_EQ(t.rows.size(), 3u);  // step 100 once
  EXPECT_EQ(t.rows[2][0], 200);
  EXPECT_EQ(t.rows[2][3], -0.25);
  std::ofstream(log) << "no thermo here\n";
  EXPECT_THROW(read_thermo_table(log), InputError);
}

}  // namespace
}  // namespace repose
