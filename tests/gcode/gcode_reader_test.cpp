// The G-code reader on hand-written programs with hand-computed results.
#include <gtest/gtest.h>

#include <cmath>

#include "swarf/gcode/gcode.h"
#include "swarf/toolpath/metrics.h"

namespace swarf {
namespace {

Toolpath parse_ok(std::string_view text) {
  auto r = parse_gcode(text, "t.nc");
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.ok() ? *r : Toolpath{};
}

std::string parse_error(std::string_view text, std::string_view name = "prog.nc") {
  auto r = parse_gcode(text, name);
  EXPECT_FALSE(r.ok()) << "accepted:\n" << text;
  return r.ok() ? std::string() : r.status().message();
}

TEST(GcodeReader, SyntaxCommentsCaseNumbersAndTapeMarks) {
  const Toolpath p = parse_ok(
      "%\n"
      "O0042 (program number)\n"
      "N10 g21 g90 (metric; absolute)\r\n"
      "N20 T4 M6 ; tool four\n"
      "n30 s9000 m3 m8\n"
      "\n"
      "G 0 X 1 0 Y-.5 Z+5.\n"
      "/G1 Z-1 F100\n"
      "G1X12.5F200.\n"
      "M30\n"
      "G1 X999 (after the end: ignored)\n"
      "%\n");
  ASSERT_EQ(p.moves.size(), 3u);
  EXPECT_EQ(p.moves[0].kind, MoveKind::kRapid);
  EXPECT_EQ(p.moves[0].end, (Vec3{10.0, -0.5, 5.0}));
  EXPECT_EQ(p.moves[1].kind, MoveKind::kPlunge);  // block delete off: executed
  EXPECT_EQ(p.moves[1].feed_mm_min, 100.0);
  EXPECT_EQ(p.moves[2].end, (Vec3{12.5, -0.5, -1.0}));
  EXPECT_EQ(p.moves[2].feed_mm_min, 200.0);
  EXPECT_EQ(p.tool_number, 4);
  EXPECT_EQ(p.spindle_rpm, 9000.0);
  EXPECT_EQ(p.coolant, Coolant::kFlood);
  EXPECT_EQ(p.clearance_z_mm, 5.0);
}

TEST(GcodeReader, KindsFromGeometry) {
  const Toolpath p = parse_ok(
      "G21 G90 G0 X0 Y0 Z5\n"
      "G1 Z-1 F100\n"         // straight down: plunge
      "X10 Z-2\n"             // down while moving: ramp
      "X20\n"                 // level: feed
      "Z3\n"                  // up: feed
      "G2 X20 Y0 Z1 I5 J0\n"  // full circle with a change of height: helix
      "G3 X30 Y0 I5 J0\n");   // half circle: arc
  ASSERT_EQ(p.moves.size(), 7u);
  EXPECT_EQ(p.moves[1].kind, MoveKind::kPlunge);
  EXPECT_EQ(p.moves[2].kind, MoveKind::kRamp);
  EXPECT_EQ(p.moves[3].kind, MoveKind::kFeed);
  EXPECT_EQ(p.moves[4].kind, MoveKind::kFeed);
  EXPECT_EQ(p.moves[5].kind, MoveKind::kHelix);
  EXPECT_TRUE(p.moves[5].clockwise);
  EXPECT_EQ(p.moves[5].center.xy(), (Vec2{25.0, 0.0}));
  EXPECT_NEAR(move_length(p.moves[4].end, p.moves[5]), std::hypot(10.0 * kPi, 2.0), 1e-9);
  EXPECT_EQ(p.moves[6].kind, MoveKind::kArc);
  EXPECT_FALSE(p.moves[6].clockwise);
  EXPECT_NEAR(move_length(p.moves[5].end, p.moves[6]), 5.0 * kPi, 1e-9);
}

TEST(GcodeReader, InchesAndIncrementalDistances) {
  const Toolpath p = parse_ok(
      "G20 G90 G0 X1 Y2 Z0.5\n"
      "G91 G1 X1 F10\n"   // 10 in/min
      "G2 X1 Y1 I0 J1\n"  // quarter, centre one inch up (I, J always incremental)
      "G21 G0 X5\n");
  ASSERT_EQ(p.moves.size(), 4u);
  EXPECT_NEAR(p.moves[0].end.x, 25.4, 1e-12);
  EXPECT_NEAR(p.moves[0].end.y, 50.8, 1e-12);
  EXPECT_NEAR(p.moves[1].end.x, 50.8, 1e-12);
  EXPECT_NEAR(p.moves[1].feed_mm_min, 254.0, 1e-12);
  EXPECT_NEAR(p.moves[2].center.y, 76.2, 1e-12);
  EXPECT_NEAR(p.moves[2].end.x, 76.2, 1e-12);
  EXPECT_NEAR(p.moves[2].end.y, 76.2, 1e-12);
  EXPECT_NEAR(p.moves[3].end.x, 81.2, 1e-12);  // G91 still in force, now in mm
}

TEST(GcodeReader, RadiusFormatBothSigns) {
  // From (10, 0) to (0, 10): the short way round a circle of radius 10 is a quarter turn
  // about the origin; R negative asks for the long way, about (10, 10).
  const Toolpath p = parse_ok(
      "G0 X10 Y0 Z0\n"
      "G3 X0 Y10 R10 F100\n"
      "G0 X10 Y0\n"
      "G3 X0 Y10 R-10\n"
      "G0 X10 Y0\n"
      "G2 X0 Y10 R10\n"
      "G0 X10 Y0\n"
      "G2 X0 Y10 R-10\n");
  ASSERT_EQ(p.moves.size(), 8u);
  const Vec3 start{10, 0, 0};
  EXPECT_NEAR(distance(p.moves[1].center.xy(), Vec2{0, 0}), 0.0, 1e-9);
  EXPECT_NEAR(move_length(start, p.moves[1]), 5.0 * kPi, 1e-9);
  EXPECT_NEAR(distance(p.moves[3].center.xy(), Vec2{10, 10}), 0.0, 1e-9);
  EXPECT_NEAR(move_length(start, p.moves[3]), 15.0 * kPi, 1e-9);
  EXPECT_NEAR(distance(p.moves[5].center.xy(), Vec2{10, 10}), 0.0, 1e-9);
  EXPECT_NEAR(move_length(start, p.moves[5]), 5.0 * kPi, 1e-9);
  EXPECT_NEAR(distance(p.moves[7].center.xy(), Vec2{0, 0}), 0.0, 1e-9);
  EXPECT_NEAR(move_length(start, p.moves[7]), 15.0 * kPi, 1e-9);
}

TEST(GcodeReader, OtherPlanesAndAbsoluteCentres) {
  const Toolpath p = parse_ok(
      "G0 X10 Y0 Z0\n"
      "G18 G2 X0 Z10 I-10 K0 F100\n"   // ZX plane, centre at the origin
      "G19 G3 Y5 Z15 J0 K5\n"          // YZ plane, centre (y 0, z 15)
      "G17 G90.1 G3 X-10 Y5 I-5 J5\n"  // absolute centre (-5, 5)
      "G91.1 G2 X0 Y15 I0 J10\n");     // incremental again: centre (-10, 15)
  ASSERT_EQ(p.moves.size(), 5u);
  EXPECT_EQ(p.moves[1].plane, ArcPlane::kZX);
  EXPECT_NEAR(p.moves[1].center.x, 0.0, 1e-12);
  EXPECT_NEAR(p.moves[1].center.z, 0.0, 1e-12);
  EXPECT_NEAR(move_length({10, 0, 0}, p.moves[1]), 5.0 * kPi, 1e-9);  // G18 cw seen from +Y
  EXPECT_EQ(p.moves[2].plane, ArcPlane::kYZ);
  EXPECT_NEAR(p.moves[2].center.y, 0.0, 1e-12);
  EXPECT_NEAR(p.moves[2].center.z, 15.0, 1e-12);
  EXPECT_NEAR(p.moves[3].center.x, -5.0, 1e-12);
  EXPECT_NEAR(p.moves[3].center.y, 5.0, 1e-12);
  EXPECT_NEAR(p.moves[4].center.x, -10.0, 1e-12);
  EXPECT_NEAR(p.moves[4].center.y, 15.0, 1e-12);
}

TEST(GcodeReader, HarmlessModalCodesAccepted) {
  const Toolpath p = parse_ok(
      "G17 G21 G90 G94 G40 G49 G80 G54\nG64 P0.01\nG61\nG43 H2\nG4 P0.5\nG98\n"
      "G0 X1\nM9\nM5\nM0\nM1\nM2\n");
  EXPECT_EQ(p.moves.size(), 1u);
}

// Returns to stored positions and machine coordinates, as real posts write them (Fanuc
// "G91 G28 Z0", "G53 G0 Z0"), worked out by hand with a work offset.
TEST(GcodeReader, HomeReturnsAndMachineCoordinates) {
  GcodeReadOptions o;
  o.work_offset = {100.0, 50.0, -200.0};  // program origin in machine coordinates
  o.g28_home = {0.0, 0.0, 0.0};           // machine home
  o.g30_home = {10.0, 20.0, -5.0};
  auto r = parse_gcode(
      "G21 G90 G0 X1 Y2 Z3\n"
      "G1 Z-4 F100\n"
      "G91 G28 Z0\n"   // intermediate = here; then Z to home Z: machine 0 = program 200
      "G90 G28 X5\n"   // X via 5 to home X (program -100); Y, Z stay
      "G53 G0 Z-10\n"  // machine Z -10 = program 190
      "G28.1\n"        // stores here (machine) as the G28 position
      "G0 X0 Y0 Z0\n"
      "G28\n"   // all axes back to the stored point
      "G30\n",  // all axes to G30's position (program -90, -30, 195)
      "home.nc", o);
  ASSERT_TRUE(r.ok()) << r.status().message();
  const auto& m = r->moves;
  ASSERT_EQ(m.size(), 12u);
  EXPECT_EQ(m[2].end, (Vec3{1, 2, -4}));  // G91 G28 Z0: the intermediate point
  EXPECT_EQ(m[3].end, (Vec3{1, 2, 200}));
  EXPECT_EQ(m[4].end, (Vec3{5, 2, 200}));
  EXPECT_EQ(m[5].end, (Vec3{-100, 2, 200}));
  EXPECT_EQ(m[6].end, (Vec3{-100, 2, 190}));
  EXPECT_EQ(m[7].end, (Vec3{0, 0, 0}));
  EXPECT_EQ(m[8].end, (Vec3{0, 0, 0}));  // no axis words: the intermediate point is here
  EXPECT_EQ(m[9].end, (Vec3{-100, 2, 190}));
  EXPECT_EQ(m[10].end, (Vec3{-100, 2, 190}));
  EXPECT_EQ(m[11].end, (Vec3{-90, -30, 195}));
  for (std::size_t k = 2; k < m.size(); ++k)
    EXPECT_EQ(m[k].kind, MoveKind::kRapid) << k;
}

TEST(GcodeReader, ErrorsNameSourceAndLine) {
  EXPECT_EQ(parse_error("G21\nG0 X0 Y0\nG2 X1 Y1 F100\n"), "prog.nc:3: G2 without I, J, K or R");
  EXPECT_NE(parse_error("G0 X0\nG41 D1 G1 X5 F100\n").find("prog.nc:2: G41 (cutter radius"),
            std::string::npos);
  EXPECT_NE(parse_error("G81 X1 Y1 Z-2 R1 F100\n").find(":1: G81 (canned cycle)"),
            std::string::npos);
  EXPECT_NE(parse_error("G0 X0\nG28 G0 X1\n").find(":2: two motion G-codes"), std::string::npos);
  EXPECT_NE(parse_error("G0 X0\nG2 X2 I1 F10\nG53 X5\n").find(":3: G53 needs G0 or G1"),
            std::string::npos);
  EXPECT_NE(parse_error("G92 X0\n").find("G92"), std::string::npos);
  EXPECT_NE(parse_error("G5 X1\n").find("unsupported G-code G5"), std::string::npos);
  EXPECT_NE(parse_error("G0 X0\nG1 X10\n").find(":2: G1 without a feed rate"), std::string::npos);
  EXPECT_NE(parse_error("X10\n").find("without a motion mode"), std::string::npos);
  EXPECT_NE(parse_error("G0 X1 (open\n").find("without ')'"), std::string::npos);
  EXPECT_NE(parse_error("G0 X#1\n").find("parameters"), std::string::npos);
  EXPECT_NE(parse_error("G0 X1 X2\n").find("two X words"), std::string::npos);
  EXPECT_NE(parse_error("G0 A10\n").find("axis A"), std::string::npos);
  EXPECT_NE(parse_error("G0 X\n").find("without a number"), std::string::npos);
  EXPECT_NE(parse_error("o100 sub\n").find("subroutines"), std::string::npos);
  EXPECT_NE(parse_error("G0 X0 Y0\nG2 X10 Y0 I5 J0 K1 F10\n").find("K word in a G17 arc"),
            std::string::npos);
  EXPECT_NE(parse_error("G0 X0 Y0\nG2 X10 Y1 I5 J0 F10\n").find("off the arc"), std::string::npos);
  EXPECT_NE(parse_error("G0 X0 Y0\nG2 X30 Y0 R10 F10\n").find("radius R"), std::string::npos);
  EXPECT_NE(parse_error("G0 G1 X1 F1\n").find("two motion"), std::string::npos);
  EXPECT_NE(parse_error("G0 X1e5\n").find("unsupported word E"), std::string::npos);
  EXPECT_NE(parse_error("G0 X99999999999\n").find("bad number"), std::string::npos);
}

TEST(GcodeReader, StartPositionAndMissingFile) {
  const auto r = parse_gcode("G91 G0 X1\n", "t.nc", {.start = {5, 6, 7}});
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->moves[0].end, (Vec3{6, 6, 7}));
  const auto missing = read_gcode("/nonexistent/x.nc");
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().code(), Error::kIo);
  EXPECT_NE(missing.status().message().find("/nonexistent/x.nc"), std::string::npos);
}

TEST(GcodeReader, HandWrittenFileGivesHandComputedMetrics) {
  const auto r = read_gcode(SWARF_TEST_DATA_DIR "/gcode/rounded_rectangle.ngc");
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r->tool_number, 2);
  EXPECT_EQ(r->spindle_rpm, 18000.0);
  EXPECT_EQ(r->coolant, Coolant::kMist);
  EXPECT_EQ(r->clearance_z_mm, 5.0);
  const ToolpathMetrics m = compute_metrics(*r);
  const double contour = 2.0 * (16.0 + 6.0) + 4.0 * kPi;
  EXPECT_NEAR(m.cutting_length_mm, contour + 6.0, 1e-9);  // plunge from Z5 to Z-1
  EXPECT_NEAR(
      m.machining_time_s,
      6.0 / 200.0 * 60.0 + contour / 600.0 * 60.0 + (std::hypot(2.0, 0.0) + 6.0) / 5000.0 * 60.0,
      1e-9);
  EXPECT_EQ(m.lift_offs, 0u);
}

}  // namespace
}  // namespace swarf
