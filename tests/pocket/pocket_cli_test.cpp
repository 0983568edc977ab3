// `swarf pocket` end to end: the G-code it writes, read back by the G-code reader, swept by
// the independent checker (the issue's "high-resolution sweep of the final G-code").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "cli/cli_test_util.h"
#include "pocket/sweep_checker.h"
#include "swarf/gcode/gcode.h"
#include "swarf/pocket/pocket_input.h"

namespace swarf {
namespace {

TEST(PocketCli, GcodeOfTheKirimotoPocketSweepsClean) {
  testing::TempDir dir;
  const std::string in = std::string(SWARF_TEST_DATA_DIR) + "/pocket/kirimoto_pocket.json";
  const auto r = testing::run_swarf("pocket " + in +
                                    " --tool flat:10 --stepover 2 --depth 4 --stepdown 2"
                                    " --dialect linuxcnc -o " +
                                    dir.file("out.nc") + " --csv " + dir.file("steps.csv") +
                                    " --report " + dir.file("rep"));
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* f :
       {"rep/engagement.png", "rep/engagement.svg", "rep/summary.json", "steps.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir.file(f))) << f;
  auto tp = read_gcode(dir.file("out.nc"));
  ASSERT_TRUE(tp.ok()) << tp.status().to_string();
  auto pocket = read_pocket(in);
  ASSERT_TRUE(pocket.ok());
  const auto s = testing::sweep_check(pocket->region, 5.0, *tp, 53.13, 0.1, 0.3);
  EXPECT_LE(s.max_gouge_mm, 0.15 + 0.1);  // generator pixel (0.125) + checker pixel, rounded
  EXPECT_LE(s.residual_mm2, 4 * 1.2);
  EXPECT_EQ(s.slot_length_mm, 0.0);
  EXPECT_GT(s.cutting_length_mm, 500.0);
}

// Several plunge points (run in parallel): the summary names each one's time and the one
// kept, and the G-code is the same byte for byte with one thread or two.
TEST(PocketCli, PlungeCandidatesAreReportedAndThreadsChangeNothing) {
  testing::TempDir dir;
  const std::string in = std::string(SWARF_TEST_DATA_DIR) + "/pocket/kirimoto_pocket.json";
  const std::string common = "pocket " + in + " --tool flat:10 --stepover 2 --depth 3" +
                             " --plunge-candidates 3 --threads ";
  const auto r1 =
      testing::run_swarf(common + "1 -o " + dir.file("a.nc") + " --report " + dir.file("rep"));
  const auto r2 = testing::run_swarf(common + "2 -o " + dir.file("b.nc"));
  ASSERT_EQ(r1.status, 0) << r1.out;
  ASSERT_EQ(r2.status, 0) << r2.out;
  EXPECT_EQ(testing::read_file(dir.file("a.nc")), testing::read_file(dir.file("b.nc")));
  const auto j = nlohmann::json::parse(testing::read_file(dir.file("rep/summary.json")));
  const auto times = j.at("plunge_candidate_time_s").get<std::vector<double>>();
  ASSERT_EQ(times.size(), 3u);
  EXPECT_EQ(j.at("plunge_candidate_kept").get<long>(),
            std::min_element(times.begin(), times.end()) - times.begin());
}

// A square just wider than the tool: by default it is entered straight down and the summary
// says so; with --no-straight-plunge there is no way in, a bad-input exit that writes nothing.
TEST(PocketCli, StraightPlungeIsCountedAndCanBeTurnedOff) {
  testing::TempDir dir;
  dir.write("tight.json", R"({"outer": [[0, 0], [6.25, 0], [6.25, 6.25], [0, 6.25]]})");
  const std::string common = "pocket " + dir.file("tight.json") + " --tool flat:6 --depth 3 ";
  const auto on =
      testing::run_swarf(common + "-o " + dir.file("on.nc") + " --report " + dir.file("rep"));
  ASSERT_EQ(on.status, 0) << on.out;
  const auto j = nlohmann::json::parse(testing::read_file(dir.file("rep/summary.json")));
  EXPECT_EQ(j.at("straight_plunges").get<int>(), 1);
  EXPECT_NE(on.out.find("centre-cutting"), std::string::npos) << on.out;
  const auto off = testing::run_swarf(common + "--no-straight-plunge -o " + dir.file("off.nc"));
  EXPECT_EQ(off.status, 2) << off.out;
  EXPECT_NE(off.out.find("no entry found"), std::string::npos) << off.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("off.nc")));
}

// Reachable material left uncut is said, not only counted in the summary: a square chamber
// just wider than a ø6 behind a 3 mm neck, with --no-straight-plunge (no helix or ramp fits
// there). Where everything is cut, nothing is said.
TEST(PocketCli, MaterialLeftUncutIsSaid) {
  testing::TempDir dir;
  dir.write("chamber.json",
            R"({"outer": [[0, 0], [40, 0], [40, 13.5], [43, 13.5], [43, 11.875], [49.25, 11.875],
                          [49.25, 18.125], [43, 18.125], [43, 16.5], [40, 16.5], [40, 30],
                          [0, 30]]})");
  const std::string common = "pocket " + dir.file("chamber.json") + " --tool flat:6 --depth 3 ";
  const auto off = testing::run_swarf(common + "--no-straight-plunge -o " + dir.file("off.nc") +
                                      " --report " + dir.file("rep"));
  ASSERT_EQ(off.status, 0) << off.out;
  const auto j = nlohmann::json::parse(testing::read_file(dir.file("rep/summary.json")));
  EXPECT_GT(j.at("material_left_mm2").get<double>(), 25.0);  // the chamber, 6.25 mm square
  EXPECT_NE(off.out.find("left uncut"), std::string::npos) << off.out;
  const auto on = testing::run_swarf(common + "-o " + dir.file("on.nc"));
  ASSERT_EQ(on.status, 0) << on.out;
  EXPECT_EQ(on.out.find("left uncut"), std::string::npos) << on.out;
}

// The Kiri:Moto pocket (ø10 at 2 mm, 3 mm deep) through the CLI with `flags`, its G-code
// read back and swept; no gouge beyond the pixels, no slot.
testing::SweepReport kirimoto_swept(const testing::TempDir& dir, const std::string& name,
                                    const std::string& flags) {
  const std::string in = std::string(SWARF_TEST_DATA_DIR) + "/pocket/kirimoto_pocket.json";
  const std::string out = dir.file(name);
  const auto r = testing::run_swarf("pocket " + in + " --tool flat:10 --stepover 2 --depth 3 -o " +
                                    out + flags);
  EXPECT_EQ(r.status, 0) << r.out;
  auto pocket = read_pocket(in);
  auto tp = read_gcode(out);
  EXPECT_TRUE(pocket.ok() && tp.ok());
  if (!pocket.ok() || !tp.ok()) return {};
  const auto s = testing::sweep_check(pocket->region, 5.0, *tp, 53.13, 0.1, 0.3);
  EXPECT_LE(s.max_gouge_mm, 0.25);
  EXPECT_EQ(s.slot_length_mm, 0.0);
  return s;
}

// --one-way reaches the generator: the G-code read back and swept is climb throughout, where
// both ways (the default) a few passes come back conventional.
TEST(PocketCli, OneWayMakesEveryPassClimb) {
  testing::TempDir dir;
  EXPECT_LT(kirimoto_swept(dir, "both.nc", "").climb_share, 0.95);
  EXPECT_GE(kirimoto_swept(dir, "one.nc", " --one-way").climb_share, 0.97);
}

// --smooth-links reaches the generator: the G-code read back and swept turns back fewer
// times per metre of floor pass (measured 29.0 -> 8.7).
TEST(PocketCli, SmoothLinksTurnBackLess) {
  testing::TempDir dir;
  const testing::SweepReport straight = kirimoto_swept(dir, "straight.nc", "");
  const testing::SweepReport smooth = kirimoto_swept(dir, "smooth.nc", " --smooth-links");
  EXPECT_LT(smooth.reversals / smooth.floor_length_mm,
            0.8 * straight.reversals / straight.floor_length_mm);
}

// --link-feed sets the F word of the links over cleared floor (5000 by default), and a
// negative one is a bad parameter that writes nothing.
TEST(PocketCli, LinkFeedSetsTheFeedOfTheLinks) {
  testing::TempDir dir;
  const std::string common = "pocket " + std::string(SWARF_TEST_DATA_DIR) +
                             "/pocket/kirimoto_pocket.json --tool flat:10 --depth 3 ";
  const auto def = testing::run_swarf(common + "-o " + dir.file("def.nc"));
  ASSERT_EQ(def.status, 0) << def.out;
  const auto slow = testing::run_swarf(common + "--link-feed 2000 -o " + dir.file("slow.nc"));
  ASSERT_EQ(slow.status, 0) << slow.out;
  const std::string a = testing::read_file(dir.file("def.nc"));
  const std::string b = testing::read_file(dir.file("slow.nc"));
  EXPECT_NE(a.find("F5000"), std::string::npos);
  EXPECT_EQ(b.find("F5000"), std::string::npos);
  EXPECT_NE(b.find("F2000"), std::string::npos);
  const auto bad = testing::run_swarf(common + "--link-feed -1 -o " + dir.file("bad.nc"));
  EXPECT_EQ(bad.status, 2) << bad.out;
  EXPECT_NE(bad.out.find("link_feed"), std::string::npos) << bad.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("bad.nc")));
}

// A ball or bull-nose end mill cuts the flat-end path without a gouge but not a flat floor:
// the run says so, with the cusp height between passes (a ø10 ball at 1 mm stepover: 5 -
// sqrt(25 - 0.25) = 0.0251 mm), which a flat end mill's run does not mention.
TEST(PocketCli, RoundEndedMillsAreToldWhatTheyLeaveOnTheFloor) {
  testing::TempDir dir;
  const std::string common = "pocket " + std::string(SWARF_TEST_DATA_DIR) +
                             "/pocket/kirimoto_pocket.json --stepover 1 --depth 3 ";
  const auto ball = testing::run_swarf(common + "--tool ball:10 -o " + dir.file("b.nc") +
                                       " --report " + dir.file("rep"));
  ASSERT_EQ(ball.status, 0) << ball.out;
  EXPECT_NE(ball.out.find("fillet"), std::string::npos) << ball.out;
  const auto j = nlohmann::json::parse(testing::read_file(dir.file("rep/summary.json")));
  EXPECT_NEAR(j.at("floor_cusp_mm").get<double>(), 5.0 - std::sqrt(25.0 - 0.25), 1e-9);
  const auto flat = testing::run_swarf(common + "--tool flat:10 -o " + dir.file("f.nc"));
  ASSERT_EQ(flat.status, 0) << flat.out;
  EXPECT_EQ(flat.out.find("fillet"), std::string::npos) << flat.out;
  // The program's tool-change comment names the tool loaded (it said "flat" for any).
  EXPECT_NE(testing::read_file(dir.file("b.nc")).find("ball end mill"), std::string::npos);
  // The same path: the tool's end shape changes nothing in the plan (comments aside, which
  // name the tool).
  auto moves = [](const std::string& gcode) {
    std::string out;
    std::size_t at = 0;
    while (at < gcode.size()) {
      std::size_t end = gcode.find('\n', at);
      if (end == std::string::npos) end = gcode.size();
      if (gcode[at] != '(') out += gcode.substr(at, end - at + 1);
      at = end + 1;
    }
    return out;
  };
  EXPECT_EQ(moves(testing::read_file(dir.file("b.nc"))),
            moves(testing::read_file(dir.file("f.nc"))));
}

TEST(PocketCli, OpenOutlineIsABadInputExitNamingTheFile) {
  testing::TempDir dir;
  dir.write("open.svg", "<svg><polyline points=\"0,0 10,0 10,10\"/></svg>");
  const auto r = testing::run_swarf("pocket " + dir.file("open.svg") + " --tool flat:6 -o " +
                                    dir.file("o.nc"));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("open.svg"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("o.nc")));
}

TEST(ContourCli, WritesGcode) {
  testing::TempDir dir;
  const std::string in = std::string(SWARF_TEST_DATA_DIR) + "/pocket/kirimoto_pocket.json";
  const auto r =
      testing::run_swarf("contour " + in + " --tool flat:10 --stepover 2 -o " + dir.file("c.nc"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_TRUE(read_gcode(dir.file("c.nc")).ok());
}

TEST(ContourCli, WholeDepthBeyondTheFlutesIsABadParameterExit) {
  testing::TempDir dir;
  const std::string in = std::string(SWARF_TEST_DATA_DIR) + "/pocket/kirimoto_pocket.json";
  const auto r = testing::run_swarf("contour " + in +
                                    " --tool flat:10 --flute-length 8 --depth 12 --stepdown 0 -o " +
                                    dir.file("c.nc"));
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find("bad parameter"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("flute"), std::string::npos) << r.out;
  EXPECT_FALSE(std::filesystem::exists(dir.file("c.nc")));
}

}  // namespace
}  // namespace swarf
