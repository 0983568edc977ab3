#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli/cli_test_util.h"

namespace swarf {
namespace {

using testing::run_swarf;
using testing::TempDir;

TEST(Cli, PrintsItsVersion) {
  const auto r = run_swarf("--version");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("swarf 0."), std::string::npos);
}

TEST(Cli, HelpListsTheOperations) {
  const auto r = run_swarf("--help");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("run"), std::string::npos);
}

TEST(Cli, UnknownSubcommandIsABadInputExit) {
  const auto r = run_swarf("frobnicate x");
  EXPECT_EQ(r.status, 2) << r.out;
}

TEST(CliJob, MissingJobFileIsNamed) {
  TempDir dir;
  const auto r = run_swarf("run " + dir.file("nope.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("nope.json"), std::string::npos) << r.out;
}

TEST(CliJob, SyntaxErrorNamesLineAndColumn) {
  TempDir dir;
  dir.write("job.json", "{\n  \"part\": \"a.json\",\n  \"tool\": flat\n}\n");
  const auto r = run_swarf("run " + dir.file("job.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("job.json:3:"), std::string::npos) << r.out;
  EXPECT_EQ(dir.entries(), 1u);  // nothing written beside the job
}

TEST(CliJob, UnknownKeysAndOperationsAreRejected) {
  TempDir dir;
  dir.write("a.json", R"({"part": "p.json", "operaton": {"type": "pocket"}})");
  auto r = run_swarf("run " + dir.file("a.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("unknown key \"operaton\""), std::string::npos) << r.out;

  dir.write("b.json", R"({"part": "p.json", "operation": {"type": "teleport"}})");
  r = run_swarf("run " + dir.file("b.json"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("unknown operation type \"teleport\""), std::string::npos) << r.out;
}

TEST(CliSummary, MachineTimeCountsTheMachinesAcceleration) {
  // The contour's rings have corners and retracts: on a machine that accelerates at
  // 200 mm/s^2 the program takes longer than at its feeds; with no limit it takes as long.
  TempDir dir;
  const std::string pocket = std::string(SWARF_SOURCE_DIR) + "/examples/l-pocket-islands.json";
  auto summary = [&](const std::string& machine) {
    const auto r = run_swarf("contour " + pocket + " --tool flat:10 --depth 3 " + machine + " -o " +
                             dir.file("p.nc") + " --report " + dir.file("rep"));
    EXPECT_EQ(r.status, 0) << r.out;
    return nlohmann::json::parse(testing::read_file(dir.file("rep/summary.json")));
  };
  const auto slow = summary("--accel 200 --junction-deviation 0");
  const auto free = summary("--accel 0");
  const auto rapid = summary("--accel 0 --rapid-rate 2500");
  EXPECT_GT(slow["machine_time_s"].get<double>(), 1.01 * slow["machining_time_s"].get<double>());
  EXPECT_DOUBLE_EQ(free["machine_time_s"].get<double>(), free["machining_time_s"].get<double>());
  EXPECT_DOUBLE_EQ(slow["machining_time_s"].get<double>(), free["machining_time_s"].get<double>());
  // Half the rapid rate: the rapids take twice as long (their time at 5000 mm/min is what
  // near-instant rapids save), the feeds as long.
  const auto instant = summary("--accel 0 --rapid-rate 1e12");
  const double rapids_s =
      free["machining_time_s"].get<double>() - instant["machining_time_s"].get<double>();
  EXPECT_GT(rapids_s, 1.0);
  EXPECT_NEAR(rapid["machining_time_s"].get<double>(),
              free["machining_time_s"].get<double>() + rapids_s, 1e-6);

  // The same machine from a job file.
  dir.write("job.json", R"({"part": ")" + pocket + R"(", "tool": "flat:10",
      "operation": {"type": "contour", "depth": 3},
      "machine": {"accel_mm_s2": 200, "junction_deviation_mm": 0},
      "outputs": {"gcode": "j.nc", "report": "jrep"}})");
  const auto r = run_swarf("run " + dir.file("job.json"));
  ASSERT_EQ(r.status, 0) << r.out;
  const auto job = nlohmann::json::parse(testing::read_file(dir.file("jrep/summary.json")));
  EXPECT_DOUBLE_EQ(job["machine_time_s"].get<double>(), slow["machine_time_s"].get<double>());
}

}  // namespace
}  // namespace swarf
