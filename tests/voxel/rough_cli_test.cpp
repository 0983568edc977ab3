// swarf rough end to end: the G-code it writes, read back, keeps off the part.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli/cli_test_util.h"
#include "swarf/gcode/gcode.h"
#include "swarf/mesh/stl.h"
#include "swarf/toolpath/metrics.h"
#include "voxel/voxel_test_util.h"

namespace swarf {
namespace {

TEST(RoughCli, FanucProgramReadBackKeepsOffTheKirimotoPocket) {
  testing::TempDir dir;
  const std::string stl = std::string(SWARF_TEST_DATA_DIR) + "/voxel/kirimoto_pocket-test.stl";
  const auto run = testing::run_swarf(
      "rough " + stl +
      " --tool flat:10 --stepover 4 --stepdown 2 --stock-to-leave 3 --margin 20 --sequence ga "
      "--rotate 0,20,45 --seed 1 --dialect fanuc -o " +
      dir.file("out.nc") + " --csv " + dir.file("path.csv") + " --report " + dir.file("rep"));
  ASSERT_EQ(run.status, 0) << run.out;
  const auto summary = nlohmann::json::parse(testing::read_file(dir.file("rep/summary.json")));
  for (const char* key : {"lift_offs", "air_length_mm", "total_length_mm", "orientations"}) {
    EXPECT_TRUE(summary.contains(key)) << key;
  }
  EXPECT_EQ(summary["orientations"].size(), 3u);
  EXPECT_FALSE(testing::read_file(dir.file("rep/strategies.csv")).empty());
  EXPECT_FALSE(testing::read_file(dir.file("path.csv")).empty());

  const std::string program = testing::read_file(dir.file("out.nc"));
  EXPECT_EQ(program.front(), '%');  // FANUC framing
  GcodeReadOptions ro;
  ro.start = {0.0, 0.0, 200.0};
  auto tp = parse_gcode(program, "out.nc", ro);
  ASSERT_TRUE(tp.ok()) << tp.status().to_string();
  // Whatever feed angle won, the program is in the part's own frame.
  auto part = read_stl(stl);
  ASSERT_TRUE(part.ok());
  const voxel_test::PartHeights heights(part->mesh);
  std::size_t bad = 0;
  voxel_test::for_each_tool_position(*tp, 0.5, [&](Vec3 p) {
    if (heights.max_in_disk(p.x, p.y, 8.0) > p.z - 3.0 + 1e-3) ++bad;  // 4 decimals in G-code
  });
  EXPECT_EQ(bad, 0u);
  // The lift-offs the summary reports are the ones in the program.
  tp->clearance_z_mm = 18.0 + 5.0;
  EXPECT_EQ(compute_metrics(*tp).lift_offs, summary["lift_offs"].get<std::size_t>());
}

TEST(RoughCli, StockBoxIsParsedAndChecked) {
  const std::string stl = std::string(SWARF_TEST_DATA_DIR) + "/voxel/kirimoto_pocket-test.stl";
  const auto ok = testing::run_swarf("rough " + stl +
                                     " --tool flat:10 --stepover 5 --stock box:-60,-60,0,60,60,20");
  EXPECT_EQ(ok.status, 0) << ok.out;
  const auto malformed = testing::run_swarf("rough " + stl + " --tool flat:10 --stock box:1,2");
  EXPECT_EQ(malformed.status, 2) << malformed.out;
  // A stock that does not hold the part's footprint.
  const auto small =
      testing::run_swarf("rough " + stl + " --tool flat:10 --stock box:-10,-10,0,10,10,20");
  EXPECT_EQ(small.status, 2) << small.out;
}

TEST(RoughCli, OpenMeshIsRefusedWithExitStatus2) {
  const auto run = testing::run_swarf("rough " + std::string(SWARF_SOURCE_DIR) +
                                      "/tests/data/voxel/open_box.stl --tool flat:10");
  EXPECT_EQ(run.status, 2) << run.out;
  EXPECT_NE(run.out.find("closed"), std::string::npos) << run.out;
}

}  // namespace
}  // namespace swarf
