// Bad files and bad parameters: one clear line naming the input and the fault, exit status
// 2, and no output file left behind (issue 2, item 8).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "cli/cli_test_util.h"

namespace swarf {
namespace {

using testing::run_swarf;
using testing::TempDir;

const std::string kPocket = std::string(SWARF_SOURCE_DIR) + "/examples/l-pocket-islands.json";

struct Case {
  const char* name;
  std::string args;    // {dir} is replaced by the temp folder
  const char* needle;  // must appear in the message
};

class CliRejects : public ::testing::TestWithParam<Case> {};

TEST_P(CliRejects, WithExitTwoAMessageAndNoOutput) {
  TempDir dir;
  dir.write("truncated.stl", "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n");
  dir.write("short-binary.stl", std::string(84, '\0') + std::string("\x05\0\0\0", 4));
  dir.write("bad-arc.nc", "G0 X0 Y0 Z5\nG1 Z-1 F100\nG2 X10 Y0\n");
  dir.write("bad-word.nc", "G0 X0 Y0 Z5\nG1 X1 Q\n");
  dir.write("job-syntax.json", "{\"part\": \"a\",, }");
  dir.write("open-pocket.json", R"({"outer": [[0,0],[10,0]], "islands": []})");
  dir.write("job-machine.json", R"({"part": ")" + kPocket +
                                    R"(", "tool": "flat:10", "operation": {"type": "contour"},
      "machine": {"accel_mm_s2": -1000}, "outputs": {"gcode": "o.nc"}})");
  std::string args = GetParam().args;
  for (std::size_t p; (p = args.find("{dir}")) != std::string::npos;)
    args.replace(p, 5, dir.file(""));
  const std::size_t before = dir.entries();
  const auto r = run_swarf(args);
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_NE(r.out.find(GetParam().needle), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("wrote"), std::string::npos) << r.out;
  EXPECT_EQ(dir.entries(), before) << "a partial output was left behind: " << r.out;
}

INSTANTIATE_TEST_SUITE_P(
    BadInput, CliRejects,
    ::testing::Values(
        Case{"TruncatedAsciiStl", "rough {dir}truncated.stl --tool flat:10 -o {dir}o.nc",
             "truncated.stl: line"},
        Case{"ShortBinaryStl", "surface {dir}short-binary.stl --tool ball:8 -o {dir}o.nc",
             "short-binary.stl"},
        Case{"GcodeArcWithoutCentre",
             "simulate {dir}bad-arc.nc --tool ball:8 --stock box:0,0,-10,50,50,0 --report {dir}r",
             "bad-arc.nc:3"},
        Case{"GcodeBadWord",
             "schedule-feed {dir}bad-word.nc --tool flat:10 --stock box:0,0,-10,50,50,0 "
             "--max-force 100 -o {dir}o.nc",
             "bad-word.nc:2"},
        Case{"JobSyntax", "run {dir}job-syntax.json", "job-syntax.json:1:"},
        Case{"OpenPocketOutline", "pocket {dir}open-pocket.json --tool flat:6 -o {dir}o.nc",
             "open-pocket.json"},
        Case{"ToolLargerThanThePocket", "pocket " + kPocket + " --tool flat:200 -o {dir}o.nc",
             "tool too large"},
        Case{"NegativeStepover", "pocket " + kPocket + " --tool flat:10 --stepover -1 -o {dir}o.nc",
             "stepover"},
        Case{"StepdownAboveFluteLength",
             "pocket " + kPocket +
                 " --tool flat:10 --flute-length 20 --depth 30 --stepdown 25 -o {dir}o.nc",
             "flute length"},
        Case{"UnknownDialect",
             "pocket " + kPocket + " --tool flat:10 --dialect heidenhain -o {dir}o.nc",
             "heidenhain"},
        Case{"BadToolSpec", "pocket " + kPocket + " --tool flat:-2 -o {dir}o.nc", "tool"},
        Case{"NotANumber", "pocket " + kPocket + " --tool flat:10 --depth deep -o {dir}o.nc",
             "--depth: 'deep' is not a number"},
        Case{"MissingInput", "rough {dir}nope.stl --tool flat:10 -o {dir}o.nc", "nope.stl"},
        Case{"NegativeAcceleration",
             "contour " + kPocket + " --tool flat:10 --accel -5 -o {dir}o.nc",
             "--accel: '-5' must be a number 0 or more"},
        Case{"NegativeAccelerationInJob", "run {dir}job-machine.json",
             "job-machine.json: machine.accel_mm_s2 must be a number 0 or more"}),
    [](const ::testing::TestParamInfo<Case>& p) { return std::string(p.param.name); });

TEST(CliOutputs, ASuccessfulRunWritesEveryRequestedFile) {
  TempDir dir;
  const auto r = run_swarf("contour " + kPocket + " --tool flat:10 --depth 3 --dialect fanuc -o " +
                           dir.file("p.nc") + " --csv " + dir.file("p.csv") + " --svg " +
                           dir.file("p.svg") + " --report " + dir.file("rep"));
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* f : {"p.nc", "p.csv", "p.svg", "rep/summary.json", "rep/toolpath.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir.file(f))) << f;
}

}  // namespace
}  // namespace swarf
