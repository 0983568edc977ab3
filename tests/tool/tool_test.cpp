#include <gtest/gtest.h>

#include <cmath>

#include "swarf/tool/library.h"
#include "swarf/tool/tool.h"

namespace swarf {
namespace {

TEST(ToolSpec, ParsesTheThreeKinds) {
  Result<Tool> flat = parse_tool_spec("flat:10");
  ASSERT_TRUE(flat.ok()) << flat.status().to_string();
  EXPECT_EQ(flat->kind, ToolKind::kFlat);
  EXPECT_DOUBLE_EQ(flat->diameter_mm, 10.0);
  EXPECT_DOUBLE_EQ(flat->corner_radius_mm, 0.0);

  Result<Tool> ball = parse_tool_spec("ball:8");
  ASSERT_TRUE(ball.ok());
  EXPECT_DOUBLE_EQ(ball->corner_radius_mm, 4.0);

  Result<Tool> bull = parse_tool_spec("bull:12:2");
  ASSERT_TRUE(bull.ok());
  EXPECT_EQ(bull->kind, ToolKind::kBull);
  EXPECT_DOUBLE_EQ(bull->corner_radius_mm, 2.0);
}

TEST(ToolSpec, RejectsNonsenseWithAMessageNamingTheFault) {
  struct Case {
    const char* spec;
    const char* needle;
  } cases[] = {
      {"flat", "KIND:DIAMETER"},
      {"drill:5", "unknown kind"},
      {"flat:abc", "not a number"},
      {"flat:-3", "positive"},
      {"bull:10", "needs a corner radius"},
      {"bull:10:5", "below the tool radius"},
      {"ball:8:3", "half its diameter"},
      {"flat:10:1", "no corner radius"},
      {"flat:nan", "not a number"},
      {"flat:10:1:2", "KIND:DIAMETER"},
  };
  for (const Case& c : cases) {
    Result<Tool> t = parse_tool_spec(c.spec);
    ASSERT_FALSE(t.ok()) << c.spec;
    EXPECT_EQ(t.status().code(), Error::kBadParameter) << c.spec;
    EXPECT_NE(t.status().message().find(c.needle), std::string::npos)
        << c.spec << " -> " << t.status().message();
  }
}

TEST(ToolProfile, BallHeightIsTheSphere) {
  const Tool t = ball_mill(8.0);
  for (double r : {0.0, 1.0, 2.5, 3.9, 4.0}) {
    EXPECT_NEAR(t.height_at(r), 4.0 - std::sqrt(16.0 - r * r), 1e-12) << r;
    EXPECT_NEAR(t.width_at(t.height_at(r)), r, 1e-9) << r;
  }
  EXPECT_TRUE(std::isinf(t.height_at(4.01)));
}

TEST(ToolProfile, BullNoseHasAFlatBottomAndATorusCorner) {
  Result<Tool> t = parse_tool_spec("bull:10:2");
  ASSERT_TRUE(t.ok());
  EXPECT_DOUBLE_EQ(t->height_at(2.9), 0.0);  // inside the flat of radius 3
  // At r = 4 the corner circle centred at (3, 2) gives h = 2 - sqrt(4 - 1).
  EXPECT_NEAR(t->height_at(4.0), 2.0 - std::sqrt(3.0), 1e-12);
  EXPECT_NEAR(t->height_at(5.0), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(t->width_at(10.0), 5.0);
  EXPECT_DOUBLE_EQ(t->width_at(0.0), 3.0);
}

TEST(ToolLibrary, RoundTripsThroughJson) {
  ToolLibrary lib;
  Tool a = flat_mill(10);
  a.number = 3;
  a.flutes = 3;
  a.name = "roughing";
  Tool b = ball_mill(6);
  b.number = 7;
  b.helix_angle_deg = 40;
  lib.tools = {a, b};
  Result<ToolLibrary> back = parse_tool_library(tool_library_json(lib), "mem.json");
  ASSERT_TRUE(back.ok()) << back.status().to_string();
  ASSERT_EQ(back->tools.size(), 2u);
  ASSERT_NE(back->find(7), nullptr);
  EXPECT_EQ(back->find(7)->kind, ToolKind::kBall);
  EXPECT_DOUBLE_EQ(back->find(7)->helix_angle_deg, 40.0);
  EXPECT_EQ(back->find(3)->name, "roughing");
  EXPECT_EQ(back->find(4), nullptr);
}

TEST(ToolLibrary, RejectsMalformedFilesNamingThePlace) {
  struct Case {
    const char* json;
    const char* needle;
  } cases[] = {
      {"{", "not valid JSON"},
      {"[]", "\"tools\" array"},
      {R"({"tools": []})", "no tools"},
      {R"({"tools": [{"number": 1, "kind": "flat"}]})", "tools[0]: missing \"diameter\""},
      {R"({"tools": [{"number": 1, "kind": "saw", "diameter": 3}]})", "unknown kind"},
      {R"({"tools": [{"number": 1, "kind": "flat", "diameter": 3},
                     {"number": 1, "kind": "flat", "diameter": 4}]})",
       "appears twice"},
      {R"({"tools": [{"number": 1, "kind": "flat", "diameter": "3"}]})", "must be a number"},
      {R"({"tools": [{"number": 2, "kind": "flat", "diameter": -1}]})", "tools[0]: tool: diameter"},
  };
  for (const Case& c : cases) {
    Result<ToolLibrary> lib = parse_tool_library(c.json, "lib.json");
    ASSERT_FALSE(lib.ok()) << c.json;
    EXPECT_EQ(lib.status().code(), Error::kBadInput);
    EXPECT_NE(lib.status().message().find("lib.json"), std::string::npos);
    EXPECT_NE(lib.status().message().find(c.needle), std::string::npos) << lib.status().message();
  }
}

}  // namespace
}  // namespace swarf
