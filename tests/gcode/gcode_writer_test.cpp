// The G-code writer: dialect rules, safety, modal suppression and number format. Read-back
// checks use the reader; the independent check against LinuxCNC is rs274_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <regex>

#include "gcode/gcode_test_util.h"
#include "swarf/gcode/gcode.h"

namespace swarf {
namespace {

using testing::blocks_without_comments;
using testing::kAllDialects;
using testing::sample_path;

std::string write(Dialect d, bool line_numbers = false) {
  GcodeOptions o;
  o.dialect = d;
  o.title = "Sample (part 1)";
  o.line_numbers = line_numbers;
  return write_gcode(sample_path(), o);
}

bool has_word(const std::vector<std::string>& blocks, const std::string& pattern) {
  const std::regex re("(^|[ ])" + pattern + "($|[ ])");
  return std::any_of(blocks.begin(), blocks.end(),
                     [&](const std::string& b) { return std::regex_search(b, re); });
}

TEST(GcodeDialect, NamesRoundTrip) {
  for (Dialect d : kAllDialects) {
    const auto parsed = parse_dialect(dialect_name(d));
    ASSERT_TRUE(parsed.ok());
    EXPECT_EQ(*parsed, d);
  }
  EXPECT_EQ(*parse_dialect("LinuxCNC"), Dialect::kLinuxCnc);
  const auto bad = parse_dialect("heidenhain");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("heidenhain"), std::string::npos);
}

TEST(GcodeWriter, FanucFraming) {
  const std::string g = write(Dialect::kFanuc);
  EXPECT_EQ(g.rfind("%\nO1000 (SAMPLE [PART 1])\n", 0), 0u) << g.substr(0, 60);
  EXPECT_NE(g.find("G21 G90 G17 G40 G49 G80 G94 G54\n"), std::string::npos);
  EXPECT_TRUE(g.size() > 8 && g.substr(g.size() - 6) == "M30\n%\n");
  const auto b = blocks_without_comments(g);
  EXPECT_TRUE(has_word(b, "T3 M6"));
  EXPECT_TRUE(has_word(b, "G43 H3"));
  EXPECT_TRUE(has_word(b, "S12000 M3"));
  EXPECT_TRUE(has_word(b, "M8"));
  EXPECT_TRUE(has_word(b, "G18"));
  EXPECT_TRUE(has_word(b, "G19"));
}

TEST(GcodeWriter, LinuxCncBlendingAndToolLength) {
  const std::string g = write(Dialect::kLinuxCnc);
  const auto b = blocks_without_comments(g);
  EXPECT_TRUE(has_word(b, "G64 P0.0100"));
  EXPECT_TRUE(has_word(b, "G17 G21 G90 G94"));
  const auto t = std::find(b.begin(), b.end(), "T3 M6");
  ASSERT_NE(t, b.end());
  EXPECT_EQ(*(t + 1), "G43 H3");  // length offset right after the change
  EXPECT_EQ(b.back(), "M2");
  EXPECT_EQ(write(Dialect::kIso).find("G64"), std::string::npos);
}

TEST(GcodeWriter, GrblHasNoToolWordsLineNumbersOrNonXyArcs) {
  const std::string g = write(Dialect::kGrbl, /*line_numbers=*/true);
  const auto b = blocks_without_comments(g);
  for (const std::string& block : b) {
    EXPECT_EQ(block.find('T'), std::string::npos) << block;
    EXPECT_EQ(block.find("M6"), std::string::npos) << block;
    EXPECT_EQ(block.find('N'), std::string::npos) << block;
    EXPECT_EQ(block.find("G18"), std::string::npos) << block;
    EXPECT_EQ(block.find("G19"), std::string::npos) << block;
    EXPECT_EQ(block.find("G43"), std::string::npos) << block;
    EXPECT_EQ(block.find("G64"), std::string::npos) << block;
  }
  EXPECT_NE(g.find("(tool T3"), std::string::npos);  // the tool only as a comment
  // Every arc grbl gets is in XY at one height: no Z word on a G2/G3 block.
  const auto read = parse_gcode(g, "grbl.nc");
  ASSERT_TRUE(read.ok()) << read.status().message();
  for (const Move& m : read->moves) {
    if (m.is_arc()) {
      EXPECT_EQ(m.plane, ArcPlane::kXY);
      EXPECT_EQ(m.kind, MoveKind::kArc);
    }
  }
}

TEST(GcodeWriter, NeverWritesRNegativeZeroOrRepeatedFeeds) {
  Toolpath p = sample_path();
  p.moves.insert(p.moves.end() - 1, Move{});
  p.moves[p.moves.size() - 2].end = {-0.00001, -0.00004, -0.000049};  // rounds to zero
  p.moves[p.moves.size() - 2].feed_mm_min = 1200.0;
  for (Dialect d : kAllDialects) {
    GcodeOptions o;
    o.dialect = d;
    const std::string g = write_gcode(p, o);
    EXPECT_EQ(g.find("-0.0000"), std::string::npos);
    const auto b = blocks_without_comments(g);
    int feeds_written = 0;
    std::string last_f;
    for (const std::string& block : b) {
      EXPECT_EQ(block.find('R'), std::string::npos) << block;
      const auto f = block.find('F');
      if (f == std::string::npos) continue;
      const std::string fw = block.substr(f, block.find(' ', f) - f);
      EXPECT_NE(fw, last_f) << "F repeated unchanged: " << block;
      last_f = fw;
      ++feeds_written;
    }
    EXPECT_GE(feeds_written, 5);  // 250, 400, 900, 700, 1200
  }
}

TEST(GcodeWriter, CoordinatesHaveTheAskedDecimals) {
  Toolpath p;
  p.rapid_to({1.0 / 3.0, 2.0, 5.0});
  p.plunge_to(-1.0, 100.0);
  GcodeOptions o;
  o.decimals = 3;
  const std::string g = write_gcode(p, o);
  EXPECT_NE(g.find("X0.333 Y2.000"), std::string::npos) << g;
  o.decimals = 0;  // still with a point: Fanuc reads "X2" as 2 least increments
  o.dialect = Dialect::kFanuc;
  EXPECT_NE(write_gcode(p, o).find("X0. Y2."), std::string::npos);
}

TEST(GcodeWriter, RetractsToClearanceBeforeTheFirstXyMove) {
  Toolpath p = sample_path();
  p.moves.erase(p.moves.begin());  // first move now descends diagonally: (15, 10, 1)
  p.moves.front().end.x = 3.0;
  for (Dialect d : kAllDialects) {
    GcodeOptions o;
    o.dialect = d;
    const auto read = parse_gcode(write_gcode(p, o), "t.nc", {.start = {100, 100, -20}});
    ASSERT_TRUE(read.ok()) << read.status().message();
    Vec3 pos{100, 100, -20};
    for (const Move& m : read->moves) {
      if (m.end.xy() != pos.xy()) {  // the first XY move starts at clearance, as a rapid
        EXPECT_EQ(pos.z, p.clearance_z_mm);
        EXPECT_EQ(m.kind, MoveKind::kRapid);
        EXPECT_EQ(m.end.z, p.clearance_z_mm);
        break;
      }
      pos = m.end;
    }
    // And the program ends at clearance.
    EXPECT_EQ(read->moves.back().end.z, p.clearance_z_mm);
  }
}

TEST(GcodeWriter, ToolChangesBetweenToolpaths) {
  Toolpath a = sample_path();
  Toolpath b = sample_path();
  b.tool_number = 7;
  b.coolant = Coolant::kMist;
  b.spindle_rpm = 8000.4;
  const Toolpath both[] = {a, b};
  GcodeOptions o;
  const auto blocks = blocks_without_comments(write_gcode(both, o));
  const auto t7 = std::find(blocks.begin(), blocks.end(), "T7 M6");
  ASSERT_NE(t7, blocks.end());
  EXPECT_EQ(*(t7 - 1), "M5");  // spindle stopped before the change
  EXPECT_TRUE(has_word({t7, blocks.end()}, "S8000 M3"));
  EXPECT_TRUE(has_word({t7, blocks.end()}, "M7"));
  // The same tool twice: no second change.
  const Toolpath same[] = {a, a};
  const auto blocks2 = blocks_without_comments(write_gcode(same, o));
  EXPECT_EQ(std::count(blocks2.begin(), blocks2.end(), "T3 M6"), 1);
  o.dialect = Dialect::kGrbl;  // grbl pauses for a manual change
  const auto grbl = blocks_without_comments(write_gcode(both, o));
  EXPECT_NE(std::find(grbl.begin(), grbl.end(), "M0"), grbl.end());
}

TEST(GcodeWriter, LineNumbersOnBlocksOnly) {
  for (Dialect d : {Dialect::kIso, Dialect::kFanuc, Dialect::kLinuxCnc}) {
    const auto b = blocks_without_comments(write(d, true));
    long last = 0;
    for (const std::string& block : b) {
      if (block == "%" || block[0] == 'O') continue;
      ASSERT_EQ(block[0], 'N') << block;
      const long n = std::stol(block.substr(1));
      EXPECT_EQ(n, last + 10);
      last = n;
    }
  }
}

TEST(GcodeWriter, SliverArcNeverBecomesAFullCircle) {
  // An arc whose start and end round to the same coordinates would read as 360 degrees.
  Toolpath p;
  p.rapid_to({10.0, 0.0, 0.0});
  const double a = 1e-6;  // radians: a 10 nm chord
  p.arc_to({10.0 * std::cos(a), 10.0 * std::sin(a), 0.0}, {0.0, 0.0}, false, 500.0);
  for (Dialect d : kAllDialects) {
    GcodeOptions o;
    o.dialect = d;
    const auto read = parse_gcode(write_gcode(p, o), "sliver.nc");
    ASSERT_TRUE(read.ok()) << read.status().message();
    Vec3 pos;
    double length = 0.0;
    for (std::size_t i = 0; i < read->moves.size(); ++i) {
      if (i > 0 && read->moves[i].kind != MoveKind::kRapid) {
        length += move_length(pos, read->moves[i]);
      }
      pos = read->moves[i].end;
    }
    EXPECT_LT(length, 1e-3);
  }
}

TEST(GcodeWriter, Deterministic) {
  for (Dialect d : kAllDialects)
    EXPECT_EQ(write(d, true), write(d, true));
}

}  // namespace
}  // namespace swarf
