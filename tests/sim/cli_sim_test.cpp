// The simulation subcommands end to end through the swarf executable.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "cli/cli_test_util.h"
#include "swarf/core/io.h"
#include "swarf/gcode/gcode.h"

namespace swarf {
namespace {

using swarf::testing::run_swarf;
using swarf::testing::TempDir;

const char* kSlot = "G21 G90 G17\nS3000 M3\nG0 X-10 Y20 Z25\nG0 Z18\nG1 X40 F1200\nG0 Z25\nM30\n";

TEST(SimCli, SimulateWritesForcesReportAndVolume) {
  TempDir dir;
  dir.write("slot.nc", kSlot);
  const auto r = run_swarf("simulate " + dir.file("slot.nc") +
                           " --stock box:0,0,0,60,40,20 --tool flat:10 --flutes 4 --pitch 0.1"
                           " --sample-stride 5 --forces " +
                           dir.file("f.csv") + " --report " + dir.file("out") + " -q");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto summary = read_file(dir.file("out/summary.json"));
  ASSERT_TRUE(summary.ok());
  const auto j = nlohmann::json::parse(*summary);
  const double want = 2.0 * (10.0 * 40.0 + kPi * 25.0 / 2.0);
  EXPECT_NEAR(j["removed_mm3"].get<double>(), want, 0.005 * want);
  EXPECT_GT(j["peak_force_n"].get<double>(), 0.0);
  EXPECT_EQ(j["collisions"].get<int>(), 0);
  const auto forces = read_file(dir.file("f.csv"));
  ASSERT_TRUE(forces.ok());
  EXPECT_EQ(forces->rfind("t_s,fx_n,fy_n,fz_n,f_n,move\n", 0), 0u);
  EXPECT_TRUE(read_file(dir.file("out/forces.svg")).ok());
  EXPECT_TRUE(read_file(dir.file("out/stock_top.png")).ok());
}

TEST(SimCli, ScheduleFeedSlowsAnOverloadedCut) {
  TempDir dir;
  dir.write("slot.nc", kSlot);
  const auto r = run_swarf("schedule-feed " + dir.file("slot.nc") +
                           " --stock box:0,0,0,60,40,20 --tool flat:10 --flutes 4 --max-force 150"
                           " -o " +
                           dir.file("slow.nc") + " --report " + dir.file("out") + " -q");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(*read_file(dir.file("out/summary.json")));
  EXPECT_GT(j["peak_force_before_n"].get<double>(), 150.0);
  EXPECT_LT(j["peak_force_after_n"].get<double>(), 150.0 * 1.02);
  EXPECT_LT(j["time_gained_s"].get<double>(), 0.0);
  const auto prog = read_gcode(dir.file("slow.nc"));
  ASSERT_TRUE(prog.ok()) << prog.status().to_string();
  double slowest = 1e9;
  for (const Move& m : prog->moves) {
    if (m.kind != MoveKind::kRapid) slowest = std::min(slowest, m.feed_mm_min);
  }
  EXPECT_LT(slowest, 1200.0);
}

TEST(SimCli, FitCoefficientsWritesJsonAndRejectsBadCsv) {
  TempDir dir;
  dir.write("cuts.csv",
            "spindle_rpm,feed_mm_min,axial_depth_mm,radial_depth_mm,fx_n,fy_n,fz_n,mode\n"
            "3000,600,3,10,-80,300,-20,slot\n3000,1200,3,10,-140,560,-35,slot\n"
            "3000,1800,3,10,-200,820,-50,slot\n3000,600,3,3,-60,150,-10,down\n"
            "3000,1200,3,3,-100,260,-18,down\n3000,1800,3,3,-140,370,-26,down\n");
  const auto r = run_swarf("fit-coefficients " + dir.file("cuts.csv") +
                           " --tool flat:10 --flutes 4 -o " + dir.file("k.json") + " -q");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(*read_file(dir.file("k.json")));
  EXPECT_TRUE(j.contains("ktc_n_mm2"));
  EXPECT_TRUE(j.contains("kae_n_mm"));
  dir.write("bad.csv", "spindle_rpm,feed\n1,2\n");
  const auto bad = run_swarf("fit-coefficients " + dir.file("bad.csv") + " --tool flat:10 -o " +
                             dir.file("k2.json"));
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("bad.csv"), std::string::npos) << bad.out;
}

}  // namespace
}  // namespace swarf
