#include <gtest/gtest.h>

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

}  // namespace
}  // namespace swarf
