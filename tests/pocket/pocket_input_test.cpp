#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <vector>

#include "pocket/geometry.h"
#include "swarf/pocket/pocket_input.h"

namespace swarf {
namespace {

double region_area(const Pocket& p) {
  double a = 0.0;
  for (const Ring& r : p.region.rings)
    a += pocket::ring_area(r);
  return a;
}

TEST(PocketInput, JsonSquareWithIslandIsOrientedAndHasTheRightArea) {
  // Outer given clockwise, island counter-clockwise: both must be turned around.
  auto p = parse_pocket_json(
      R"({"outer": [[0,0],[0,10],[10,10],[10,0]], "islands": [[[2,2],[4,2],[4,4],[2,4]]]})",
      "sq.json");
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  ASSERT_EQ(p->region.rings.size(), 2u);
  EXPECT_GT(pocket::ring_area(p->region.rings[0]), 0.0);
  EXPECT_LT(pocket::ring_area(p->region.rings[1]), 0.0);
  EXPECT_NEAR(region_area(*p), 100.0 - 4.0, 1e-12);
}

TEST(PocketInput, SelfIntersectingOutlineIsRejectedWithThePlace) {
  auto p = parse_pocket_json(R"({"outer": [[0,0],[10,10],[10,0],[0,10]]})", "bow.json");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.status().code(), Error::kBadInput);
  EXPECT_NE(p.status().message().find("bow.json"), std::string::npos);
  EXPECT_NE(p.status().message().find("intersects itself"), std::string::npos);
  EXPECT_NE(p.status().message().find("(5, 5)"), std::string::npos) << p.status().message();
}

// (An island crossing the outer boundary is merged into it: merged_islands_test.cpp.)
TEST(PocketInput, IslandOutsideTheOuterIsRejected) {
  auto b = parse_pocket_json(
      R"({"outer": [[0,0],[10,0],[10,10],[0,10]], "islands": [[[20,2],[22,2],[22,4]]]})", "y.json");
  ASSERT_FALSE(b.ok());
  EXPECT_NE(b.status().message().find("outside"), std::string::npos);
  EXPECT_FALSE(parse_pocket_json("{\"outer\": [[0,0],[1,1]]}", "z.json").ok());
  EXPECT_FALSE(parse_pocket_json("not json", "z.json").ok());
}

TEST(PocketInput, SvgPathWithRelativeArcsMakesACircleOfTheRightArea) {
  // A ring of two half circles, radius 20, with a square hole given as an absolute polygon.
  const char* svg = R"(<svg xmlns="http://www.w3.org/2000/svg">
    <path d="M 0 0 a20,20 0 1,0 40,0 a 20 20 0 1 0 -40 0 z"/>
    <polygon points="15,-5 25,-5 25,5 15,5"/></svg>)";
  auto p = parse_pocket_svg(svg, "c.svg", {.arc_tolerance_mm = 0.001});
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  ASSERT_EQ(p->island_count(), 1u);
  EXPECT_NEAR(region_area(*p), kPi * 400.0 - 100.0, kPi * 400.0 * 2e-4);
}

// A drawing of several pockets side by side: a loop outside every larger one starts an
// outline of its own, the loops inside an outline are its islands; the region holds the
// outlines as parts, largest first, and a note says how many. A loop touching another
// outline from outside is neither, and is refused.
TEST(PocketInput, SvgWithSeparateOutlinesIsOneRegionInParts) {
  auto p = parse_pocket_svg(R"(<svg><rect x="2" y="2" width="30" height="20"/>
    <circle cx="55" cy="15" r="10"/><circle cx="55" cy="15" r="3"/>
    <rect x="75" y="5" width="20" height="30"/></svg>)",
                            "three.svg", {.arc_tolerance_mm = 0.001});
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  ASSERT_EQ(p->region.rings.size(), 4u);
  EXPECT_EQ(p->island_count(), 1u);
  EXPECT_NEAR(pocket::ring_area(p->region.rings[0]), 600.0, 1e-9);  // the largest first
  EXPECT_NEAR(pocket::ring_area(p->region.rings[1]), 600.0, 1e-9);
  EXPECT_NEAR(region_area(*p), 1200.0 + kPi * (100.0 - 9.0), kPi * 100.0 * 2e-4);
  ASSERT_EQ(p->notes.size(), 1u);
  EXPECT_NE(p->notes[0].find("3 separate outlines"), std::string::npos) << p->notes[0];
  // The ring's island is still the circle's: a drawing of one outline is read as before.
  auto one = parse_pocket_svg(
      R"(<svg><circle cx="55" cy="15" r="10"/><circle cx="55" cy="15" r="3"/></svg>)", "o.svg");
  ASSERT_TRUE(one.ok());
  EXPECT_TRUE(one->notes.empty());
  auto touching = parse_pocket_svg(
      R"(<svg><rect x="0" y="0" width="30" height="20"/><rect x="30" y="5" width="10" height="10"/></svg>)",
      "t.svg");
  ASSERT_FALSE(touching.ok());
  EXPECT_NE(touching.status().message().find("t.svg: a closed loop of the drawing (the 2. largest) "
                                             "touches outline 1 from outside"),
            std::string::npos)
      << touching.status().message();
  // A loop with no points among separate outlines is named, not read past (the fuzzer's
  // input crashed the classification of session 53's first version).
  auto empty = parse_pocket_svg(R"(<svg><rect x="0" y="0" width="10" height="10"/>
    <polygon points=""/><rect x="20" y="0" width="10" height="10"/></svg>)",
                                "e.svg");
  ASSERT_FALSE(empty.ok());
  EXPECT_NE(empty.status().message().find("fewer than 3 distinct points"), std::string::npos)
      << empty.status().message();
}

TEST(PocketInput, SvgHVAndRelativeLinesAndOpenPolylines) {
  auto p = parse_pocket_svg(R"(<svg><path d="m10 10 h30 v-20 l-30,0 Z"/></svg>)", "r.svg");
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  EXPECT_NEAR(region_area(*p), 600.0, 1e-9);
  auto open = parse_pocket_svg(R"(<svg><polyline points="0,0 10,0 10,10"/></svg>)", "o.svg");
  ASSERT_FALSE(open.ok());
  EXPECT_NE(open.status().message().find("o.svg:1"), std::string::npos);
  EXPECT_NE(open.status().message().find("open"), std::string::npos);
  EXPECT_FALSE(parse_pocket_svg(R"(<svg><path d="M0 0 L10 0 L10 10"/></svg>)", "p.svg").ok());
  auto unknown = parse_pocket_svg(R"(<svg><path d="M0 0 L10 0 B10 10 Z"/></svg>)", "q.svg");
  ASSERT_FALSE(unknown.ok());
  EXPECT_NE(unknown.status().message().find("path command 'B'"), std::string::npos);
}

// Cubic and quadratic Bezier segments, flattened to the tolerance; S and T reflect the last
// control point. Truths: a circle of four cubic quarters (radius within 0.03 % of 10 mm), the
// same written with S, and the area of a quadratic segment over its chord (2/3 of its control
// triangle).
TEST(PocketInput, SvgBezierCurvesFlattenToTheirArea) {
  const CurveInputOptions fine{.arc_tolerance_mm = 0.0005};
  auto c = parse_pocket_svg(R"(<svg><path d="M10,0 C10,5.5228 5.5228,10 0,10
      C-5.5228,10 -10,5.5228 -10,0 C-10,-5.5228 -5.5228,-10 0,-10 C5.5228,-10 10,-5.5228 10,0Z"/>
      </svg>)",
                            "c.svg", fine);
  ASSERT_TRUE(c.ok()) << c.status().to_string();
  EXPECT_NEAR(region_area(*c), kPi * 100.0, kPi * 100.0 * 1e-3);
  for (const Vec2& q : c->outer())
    EXPECT_NEAR(norm(q), 10.0, 10.0 * 3e-4 + 0.0005);
  auto s = parse_pocket_svg(R"(<svg><path d="M10,0 C10,5.5228 5.5228,10 0,10
      S-10,5.5228 -10,0 S-5.5228,-10 0,-10 s10,4.4772 10,10z"/></svg>)",
                            "s.svg", fine);
  ASSERT_TRUE(s.ok()) << s.status().to_string();
  EXPECT_NEAR(region_area(*s), region_area(*c), 1e-6);
  // Q up to (5, 10) and back down by T, whose reflected control is (15, -10): 100/3 + 100/3.
  auto q = parse_pocket_svg(R"(<svg><path d="M0,0 Q5,10 10,0 T0,0 Z"/></svg>)", "q.svg", fine);
  ASSERT_TRUE(q.ok()) << q.status().to_string();
  EXPECT_NEAR(region_area(*q), 200.0 / 3.0, 0.05);
}

// transform attributes on shapes and on enclosing groups (as drawing programs write layers),
// and <ellipse>. A group's transform ends with its </g>: the square after it is untouched
// (were it scaled and moved with the circle it would lie outside the outer boundary).
TEST(PocketInput, SvgTransformsOfShapesAndGroupsAndEllipses) {
  auto p = parse_pocket_svg(R"svg(<svg>
      <rect x="0" y="0" width="100" height="50"/>
      <g transform="translate(50,25) scale(2)"><g><circle cx="0" cy="0" r="5"/></g></g>
      <rect x="10" y="10" width="5" height="5"/>
      <rect x="0" y="0" width="10" height="4" transform="translate(80,30) rotate(90)"/>
      <ellipse cx="25" cy="25" rx="6" ry="3" transform="rotate(90, 25, 25)"/></svg>)svg",
                            "t.svg", {.arc_tolerance_mm = 0.0005});
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  ASSERT_EQ(p->island_count(), 4u);
  EXPECT_NEAR(region_area(*p), 5000.0 - kPi * 100.0 - 25.0 - 40.0 - kPi * 18.0, 0.1);
  // The rotated rectangle: x from 76 to 80, y from 30 to 40 (SVG), so -40 to -30 here.
  bool found = false;
  for (std::size_t k = 1; k < p->region.rings.size(); ++k) {
    Box2 b;
    for (const Vec2& q : p->region.rings[k])
      b.add(q);
    if (std::abs(b.min.x - 76.0) < 1e-9 && std::abs(b.max.x - 80.0) < 1e-9 &&
        std::abs(b.min.y + 40.0) < 1e-9 && std::abs(b.max.y + 30.0) < 1e-9)
      found = true;
  }
  EXPECT_TRUE(found);
  auto bad = parse_pocket_svg(
      R"svg(<svg><rect width="5" height="5" transform="rotate(1,2)"/></svg>)svg", "b.svg");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("b.svg:1"), std::string::npos);
  EXPECT_NE(bad.status().message().find("transform"), std::string::npos);
}

// User units are mm unless the root <svg> has a viewBox and a width in an absolute unit.
TEST(PocketInput, SvgViewBoxAndAbsoluteWidthScaleUserUnitsToMm) {
  auto a = parse_pocket_svg(
      R"(<svg width="20mm" height="10mm" viewBox="0 0 80 40"><rect width="80" height="40"/></svg>)",
      "a.svg");
  ASSERT_TRUE(a.ok()) << a.status().to_string();
  EXPECT_NEAR(region_area(*a), 200.0, 1e-9);
  auto b = parse_pocket_svg(
      R"(<svg width="1in" viewBox="10 10 96 96"><rect x="10" y="10" width="96" height="96"/></svg>)",
      "b.svg");
  ASSERT_TRUE(b.ok()) << b.status().to_string();
  EXPECT_NEAR(region_area(*b), 25.4 * 25.4, 1e-9);
  Box2 box;
  for (const Vec2& q : b->outer())
    box.add(q);
  EXPECT_NEAR(box.min.x, 0.0, 1e-12);
  EXPECT_NEAR(box.max.x, 25.4, 1e-12);
  auto c = parse_pocket_svg(
      R"(<svg width="100%" viewBox="0 0 8 4"><rect width="8" height="4"/></svg>)", "c.svg");
  ASSERT_TRUE(c.ok()) << c.status().to_string();
  EXPECT_NEAR(region_area(*c), 32.0, 1e-9);
}

std::string dxf(const std::string& entities) {
  return "0\nSECTION\n2\nENTITIES\n" + entities + "0\nENDSEC\n0\nEOF\n";
}

// $INSUNITS in the HEADER: a 2 x 1 inch rectangle with a 0.25 inch circle island is read in
// mm; a unit that is not a length is refused with the file and line.
TEST(PocketInput, DxfDrawingUnitsAreHonoured) {
  const std::string e =
      "0\nLWPOLYLINE\n90\n4\n70\n1\n10\n0\n20\n0\n10\n2\n20\n0\n10\n2\n20\n1\n10\n0\n20\n1\n"
      "0\nCIRCLE\n10\n1\n20\n0.5\n40\n0.25\n";
  auto header = [](const std::string& units) {
    return "0\nSECTION\n2\nHEADER\n9\n$ACADVER\n1\nAC1015\n9\n$INSUNITS\n70\n" + units +
           "\n0\nENDSEC\n";
  };
  auto in = parse_pocket_dxf(header("1") + dxf(e), "in.dxf", {.arc_tolerance_mm = 0.0005});
  ASSERT_TRUE(in.ok()) << in.status().to_string();
  const double r = 0.25 * 25.4;
  EXPECT_NEAR(region_area(*in), 2 * 25.4 * 25.4 - kPi * r * r, 0.0005 * 2 * kPi * r);
  const Box2 box = bounds(in->region);
  EXPECT_NEAR(box.max.x, 50.8, 1e-9);
  EXPECT_NEAR(box.max.y, 25.4, 1e-9);
  // Millimetres and unitless drawings read as they are; centimetres scale by 10.
  auto mm = parse_pocket_dxf(header("4") + dxf(e), "mm.dxf");
  auto none = parse_pocket_dxf(dxf(e), "none.dxf");
  auto cm = parse_pocket_dxf(header("5") + dxf(e), "cm.dxf");
  ASSERT_TRUE(mm.ok() && none.ok() && cm.ok());
  EXPECT_NEAR(bounds(mm->region).max.x, 2.0, 1e-12);
  EXPECT_NEAR(bounds(none->region).max.x, 2.0, 1e-12);
  EXPECT_NEAR(bounds(cm->region).max.x, 20.0, 1e-12);
  auto bad = parse_pocket_dxf(header("19") + dxf(e), "ly.dxf");
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("ly.dxf:12"), std::string::npos)
      << bad.status().to_string();
  EXPECT_NE(bad.status().message().find("$INSUNITS"), std::string::npos);
}

TEST(PocketInput, DxfLinesAndArcChainIntoASlotShape) {
  // A stadium: two lines and two half-circle arcs of radius 5, written in scrambled order
  // and directions, chained into one loop. Area = 20*10 + pi*25.
  const std::string e =
      "0\nLINE\n8\n0\n10\n0\n20\n-5\n11\n20\n21\n-5\n"
      "0\nLINE\n8\n0\n10\n0\n20\n5\n11\n20\n21\n5\n"
      "0\nARC\n8\n0\n10\n20\n20\n0\n40\n5\n50\n270\n51\n90\n"
      "0\nARC\n8\n0\n10\n0\n20\n0\n40\n5\n50\n90\n51\n270\n";
  auto p = parse_pocket_dxf(dxf(e), "s.dxf", {.arc_tolerance_mm = 0.0005});
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  // Chords inside the arc lose at most tolerance x arc length of area.
  EXPECT_NEAR(region_area(*p), 200.0 + kPi * 25.0, 0.0005 * 2.0 * kPi * 5.0);
}

TEST(PocketInput, DxfLwpolylineBulgeAndCircleIsland) {
  // Closed LWPOLYLINE: square 0..20 whose top edge bulges out by a half circle (bulge 1),
  // and a circle island of radius 2.
  const std::string e =
      "0\nLWPOLYLINE\n90\n4\n70\n1\n10\n0\n20\n0\n10\n20\n20\n0\n10\n20\n20\n20\n42\n1\n"
      "10\n0\n20\n20\n"
      "0\nCIRCLE\n10\n10\n20\n10\n40\n2\n";
  auto p = parse_pocket_dxf(dxf(e), "b.dxf", {.arc_tolerance_mm = 0.0005});
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  EXPECT_EQ(p->island_count(), 1u);
  EXPECT_NEAR(region_area(*p), 400.0 + kPi * 50.0 - kPi * 4.0, 0.02);
}

// The R12 forms and curves: POLYLINE/VERTEX/SEQEND with a bulge (a spline frame control
// point, VERTEX flag 16, is not on the curve and is skipped), a full ELLIPSE island and a
// rational quadratic SPLINE island that is an exact circle (nine control points, weights 1
// and sqrt(2)/2): every flattened point on radius 3 to rounding.
TEST(PocketInput, DxfPolylineEllipseAndNurbsSpline) {
  auto vertex = [](double x, double y, double bulge, int flags) {
    return "0\nVERTEX\n10\n" + std::to_string(x) + "\n20\n" + std::to_string(y) + "\n42\n" +
           std::to_string(bulge) + "\n70\n" + std::to_string(flags) + "\n";
  };
  std::string e = "0\nPOLYLINE\n66\n1\n70\n1\n" + vertex(0, 0, 0, 0) + vertex(60, 0, 1, 0) +
                  vertex(100, 100, 0, 16) + vertex(60, 30, 0, 0) + vertex(0, 30, 0, 0) +
                  "0\nSEQEND\n";
  e += "0\nELLIPSE\n10\n15\n20\n15\n11\n8\n21\n0\n40\n0.5\n41\n0\n42\n6.283185307179586\n";
  const double w = std::sqrt(0.5);
  const double cx = 40, cy = 15, r = 3;
  const double pts[9][2] = {{1, 0},   {1, 1},  {0, 1},  {-1, 1}, {-1, 0},
                            {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
  e += "0\nSPLINE\n70\n11\n71\n2\n72\n12\n73\n9\n";
  for (double k : {0.0, 0.0, 0.0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1.0, 1.0, 1.0})
    e += "40\n" + std::to_string(k) + "\n";
  for (int k = 0; k < 9; ++k) {
    e += "41\n" + std::to_string(k % 2 == 0 ? 1.0 : w) + "\n";
    e += "10\n" + std::to_string(cx + r * pts[k][0]) + "\n20\n" +
         std::to_string(cy + r * pts[k][1]) + "\n";
  }
  auto p = parse_pocket_dxf(dxf(e), "r12.dxf", {.arc_tolerance_mm = 0.0005});
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  ASSERT_EQ(p->island_count(), 2u);
  // 60 x 30 with a half disc of radius 15 on the right; minus the ellipse 8 x 4 and the circle.
  EXPECT_NEAR(region_area(*p), 1800.0 + kPi * 112.5 - kPi * 32.0 - kPi * 9.0, 0.05);
  bool circle = false;
  for (std::size_t k = 1; k < p->region.rings.size(); ++k) {
    const Ring& ring = p->region.rings[k];
    if (distance(ring.front(), {cx, cy}) > 3.5) continue;
    circle = true;
    for (const Vec2& q : ring)
      EXPECT_NEAR(distance(q, {cx, cy}), r, 1e-5);  // std::to_string keeps 6 decimals
  }
  EXPECT_TRUE(circle);
  auto fit_only = parse_pocket_dxf(
      dxf("0\nSPLINE\n70\n8\n71\n3\n74\n3\n11\n0\n21\n0\n11\n5\n21\n5\n11\n10\n21\n0\n"), "f.dxf");
  ASSERT_FALSE(fit_only.ok());
  EXPECT_NE(fit_only.status().message().find("f.dxf"), std::string::npos);
  EXPECT_NE(fit_only.status().message().find("fit points"), std::string::npos);
}

// Angles and parameters far beyond a turn (found by the fuzzer: a loop adding turns to
// 1e72 never ended) are taken modulo a turn: equal start and end make a whole ellipse.
TEST(PocketInput, DxfHugeAnglesAreTakenModuloATurn) {
  const std::string e =
      "0\nLWPOLYLINE\n90\n4\n70\n1\n10\n0\n20\n0\n10\n100\n20\n0\n10\n100\n20\n100\n10\n0\n20\n"
      "100\n0\nELLIPSE\n10\n50\n20\n50\n11\n10\n21\n0\n40\n0.5\n41\n1e300\n42\n1e300\n";
  auto p = parse_pocket_dxf(dxf(e), "h.dxf", {.arc_tolerance_mm = 0.0005});
  ASSERT_TRUE(p.ok()) << p.status().to_string();
  EXPECT_NEAR(region_area(*p), 10000.0 - kPi * 50.0, 0.03);  // chords: perimeter x tol
  auto arc = parse_pocket_dxf(dxf("0\nARC\n10\n0\n20\n0\n40\n5\n50\n1e300\n51\n-"
                                  "1e300\n0\nLINE\n10\n0\n20\n0\n11\n1\n21\n1\n"),
                              "a.dxf");
  EXPECT_FALSE(arc.ok());  // returns (an open chain), rather than spinning
}

TEST(PocketInput, DxfOpenChainIsRejectedWithItsEnds) {
  const std::string e =
      "0\nLINE\n10\n0\n20\n0\n11\n10\n21\n0\n0\nLINE\n10\n10\n20\n0\n11\n10\n21\n10\n";
  auto p = parse_pocket_dxf(dxf(e), "open.dxf");
  ASSERT_FALSE(p.ok());
  EXPECT_EQ(p.status().code(), Error::kBadInput);
  EXPECT_NE(p.status().message().find("open outline"), std::string::npos);
  EXPECT_NE(p.status().message().find("(0, 0)"), std::string::npos) << p.status().message();
}

// One drawing, three formats: the JSON's coordinates, an SVG of the same loops with y
// negated (the SVG reader flips y so that the drawing keeps its look) and a DXF of
// LWPOLYLINEs give the same pocket to the last bit (same rings, same order, same start
// points), so the same toolpath: a user may export from any program.
TEST(PocketInput, TheSameDrawingAsJsonSvgAndDxfGivesTheSamePocket) {
  const std::vector<Ring> rings = {
      {{0.125, 0.5}, {80.3333, 0.5}, {80.3333, 30.75}, {35.1, 30.75}, {35.1, 70.2}, {0.125, 70.2}},
      {{10.5, 10.25}, {10.5, 18.125}, {20.75, 18.125}, {20.75, 10.25}},  // clockwise
      {{50.0, 12.0}, {62.5, 14.0}, {58.0, 22.0}}};  // counter-clockwise: each is turned round
  std::ostringstream json, svg, dxf;
  for (std::ostringstream* o : {&json, &svg, &dxf})
    o->precision(17);
  json << "{\"outer\": [";
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\">\n";
  dxf << "0\nSECTION\n2\nENTITIES\n";
  for (std::size_t k = 0; k < rings.size(); ++k) {
    json << (k == 1 ? "], \"islands\": [[" : k > 1 ? ", [" : "");
    svg << "<polygon points=\"";
    dxf << "0\nLWPOLYLINE\n8\n0\n90\n" << rings[k].size() << "\n70\n1\n";
    for (std::size_t q = 0; q < rings[k].size(); ++q) {
      const Vec2 v = rings[k][q];
      json << (q ? ", [" : "[") << v.x << ", " << v.y << "]";
      svg << (q ? " " : "") << v.x << "," << -v.y;
      dxf << "10\n" << v.x << "\n20\n" << v.y << "\n";
    }
    json << (k == 0 ? "" : "]");
    svg << "\"/>\n";
  }
  json << "]}";
  svg << "</svg>\n";
  dxf << "0\nENDSEC\n0\nEOF\n";
  auto a = parse_pocket_json(json.str(), "p.json");
  auto b = parse_pocket_svg(svg.str(), "p.svg");
  auto c = parse_pocket_dxf(dxf.str(), "p.dxf");
  ASSERT_TRUE(a.ok()) << a.status().to_string() << "\n" << json.str();
  ASSERT_TRUE(b.ok()) << b.status().to_string();
  ASSERT_TRUE(c.ok()) << c.status().to_string();
  ASSERT_EQ(a->region.rings.size(), 3u);
  EXPECT_EQ(a->island_count(), 2u);
  for (const Pocket* other : {&b.value(), &c.value()}) {
    ASSERT_EQ(other->region.rings.size(), a->region.rings.size()) << other->source;
    for (std::size_t k = 0; k < a->region.rings.size(); ++k) {
      const Ring& x = a->region.rings[k];
      const Ring& y = other->region.rings[k];
      ASSERT_EQ(x.size(), y.size()) << other->source << " ring " << k;
      for (std::size_t q = 0; q < x.size(); ++q) {
        EXPECT_EQ(x[q].x, y[q].x) << other->source << " ring " << k << " point " << q;
        EXPECT_EQ(x[q].y, y[q].y) << other->source << " ring " << k << " point " << q;
      }
    }
  }
}

}  // namespace
}  // namespace swarf
