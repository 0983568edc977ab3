// Shared by the G-code tests: a path with every kind of move, a random path generator and
// a comparison of a written-and-read-back path against the original.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "swarf/gcode/gcode.h"
#include "toolpath/arc_geometry.h"

namespace swarf::testing {

inline constexpr Dialect kAllDialects[] = {Dialect::kIso, Dialect::kFanuc, Dialect::kLinuxCnc,
                                           Dialect::kGrbl};

/// The blocks of a program with comments removed, one string per non-empty block.
inline std::vector<std::string> blocks_without_comments(const std::string& program) {
  std::vector<std::string> out;
  std::istringstream in(program);
  std::string line;
  while (std::getline(in, line)) {
    std::string b;
    bool in_comment = false;
    for (char c : line) {
      if (c == '(') in_comment = true;
      if (!in_comment) b += c;
      if (c == ')') in_comment = false;
    }
    if (const auto semi = b.find(';'); semi != std::string::npos) b.erase(semi);
    while (!b.empty() && b.back() == ' ')
      b.pop_back();
    if (!b.empty()) out.push_back(b);
  }
  return out;
}

/// A short path with rapids, a plunge, a helix, a ramp, feeds at two rates, arcs both ways,
/// a full circle, and arcs in G18 and G19. Starts at clearance and ends retracted.
inline Toolpath sample_path() {
  Toolpath p;
  p.name = "sample";
  p.tool_number = 3;
  p.tool_diameter_mm = 6.0;
  p.tool_description = "flat endmill";
  p.spindle_rpm = 12000.0;
  p.clearance_z_mm = 5.0;
  p.rapid_to({15.0, 10.0, 5.0});
  p.rapid_to({15.0, 10.0, 1.0});
  p.plunge_to(0.0, 250.0);
  p.arc_to({15.0, 10.0, -1.5}, {12.0, 10.0}, false, 400.0);  // one helical turn down
  p.ramp_to({20.0, 10.0, -2.0}, 400.0);
  p.feed_to({30.0, 10.0, -2.0}, 900.0);
  p.arc_to({35.0, 15.0, -2.0}, {30.0, 15.0}, false, 900.0);  // quarter ccw
  p.arc_to({40.0, 20.0, -2.0}, {40.0, 15.0}, true, 900.0);   // quarter cw
  p.feed_to({40.0, 20.0, -1.0}, 900.0, false);               // up, in air
  p.arc_to({40.0, 20.0, -1.0}, {38.0, 20.0}, true, 700.0);   // full circle
  Move zx;
  zx.kind = MoveKind::kArc;
  zx.plane = ArcPlane::kZX;
  zx.end = {44.0, 20.0, -1.0};
  zx.center = {42.0, 20.0, -1.0};
  zx.clockwise = true;
  zx.feed_mm_min = 700.0;
  p.moves.push_back(zx);  // half circle over the top in X-Z
  Move yz = zx;
  yz.plane = ArcPlane::kYZ;
  yz.end = {44.0, 23.0, -1.0};
  yz.center = {44.0, 21.5, -1.0};
  yz.clockwise = false;
  p.moves.push_back(yz);
  p.feed_to({10.0, 23.0, -1.0}, 1200.0);
  p.retract();
  return p;
}

/// A random path (fixed seed by the caller) of every kind of move, with arcs of at least
/// 10 degrees and radii of at least 1 mm so that rounding to 4 decimals keeps kinds.
inline Toolpath random_path(std::mt19937& rng, int moves) {
  std::uniform_real_distribution<double> coord(-50.0, 50.0);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::uniform_int_distribution<int> pick(0, 7);
  const double feeds[] = {100.0, 250.5, 800.0, 1500.0};
  Toolpath p;
  p.clearance_z_mm = 10.0;
  p.rapid_to({coord(rng), coord(rng), 10.0});
  for (int i = 0; i < moves; ++i) {
    const Vec3 s = p.position();
    const double f = feeds[rng() % 4];
    switch (pick(rng)) {
      case 0:
        p.rapid_to({coord(rng), coord(rng), p.clearance_z_mm});
        break;
      case 1:
        p.plunge_to(s.z - 0.2 - 2.0 * unit(rng), f);
        break;
      case 2:
        p.ramp_to({s.x + coord(rng) * 0.1, s.y + 1.0 + unit(rng), s.z - 0.1 - unit(rng)}, f);
        break;
      case 3:
        p.feed_to({coord(rng), coord(rng), s.z + (unit(rng) < 0.3 ? 0.5 : 0.0)}, f);
        break;
      case 4:
      case 5: {  // XY arc or helix
        const double r = 1.0 + 10.0 * unit(rng);
        const double a0 = 2.0 * kPi * unit(rng);
        const Vec2 c = s.xy() - Vec2{r * std::cos(a0), r * std::sin(a0)};
        const bool cw = unit(rng) < 0.5;
        const double sweep = deg_to_rad(10.0 + 330.0 * unit(rng)) * (cw ? -1.0 : 1.0);
        const Vec2 e = c + Vec2{r * std::cos(a0 + sweep), r * std::sin(a0 + sweep)};
        const double dz = unit(rng) < 0.5 ? 0.0 : -0.1 - unit(rng);
        p.arc_to({e.x, e.y, s.z + dz}, c, cw, f);
        break;
      }
      default: {  // an arc in G18 or G19, in plane
        Move m;
        m.kind = MoveKind::kArc;
        m.plane = unit(rng) < 0.5 ? ArcPlane::kZX : ArcPlane::kYZ;
        const detail::PlaneAxes ax = detail::plane_axes(m.plane);
        const double r = 1.0 + 5.0 * unit(rng);
        const double a0 = 2.0 * kPi * unit(rng);
        const bool cw = unit(rng) < 0.5;
        const double sweep = deg_to_rad(10.0 + 300.0 * unit(rng)) * (cw ? -1.0 : 1.0);
        m.center = s;
        m.center[ax.u] = s[ax.u] - r * std::cos(a0);
        m.center[ax.v] = s[ax.v] - r * std::sin(a0);
        m.end = s;
        m.end[ax.u] = m.center[ax.u] + r * std::cos(a0 + sweep);
        m.end[ax.v] = m.center[ax.v] + r * std::sin(a0 + sweep);
        m.clockwise = cw;
        m.feed_mm_min = f;
        p.moves.push_back(m);
      }
    }
  }
  p.retract();
  return p;
}

inline bool grbl_linearises(const Move& m, Vec3 start) {
  return m.is_arc() && (m.plane != ArcPlane::kXY || m.end.z != start.z);
}

/// The read-back path must be the original: [G0 Z clearance] then the same moves (kinds,
/// ends, centres, directions, feeds) within `tol`. With grbl, arcs it cannot run come back
/// as G1 lines whose points lie within 0.001 mm (+ rounding) of the original arc.
inline void expect_same_moves(const Toolpath& original, const Toolpath& read, Dialect dialect,
                              double tol) {
  EXPECT_EQ(read.moves[0].kind, MoveKind::kRapid);
  EXPECT_NEAR(read.moves[0].end.z, original.clearance_z_mm, tol);
  std::size_t k = 1;
  Vec3 start = original.moves[0].end;
  for (std::size_t i = 0; i < original.moves.size(); ++i) {
    const Move& m = original.moves[i];
    SCOPED_TRACE("original move " + std::to_string(i) + " (" + std::string(move_kind_name(m.kind)) +
                 ")");
    if (dialect == Dialect::kGrbl && i > 0 && grbl_linearises(m, start)) {
      const detail::ArcGeometry g = detail::arc_geometry(start, m);
      const double r = g.start_radius;
      while (true) {
        ASSERT_LT(k, read.moves.size());
        const Move& l = read.moves[k++];
        EXPECT_EQ(l.is_arc(), false);
        EXPECT_NEAR(l.feed_mm_min, m.feed_mm_min, 0.05);
        const Vec2 q{l.end[g.axes.u] - g.center.x, l.end[g.axes.v] - g.center.y};
        EXPECT_NEAR(norm(q), r, 0.001 + tol);
        double turned = std::atan2(q.y, q.x) - g.start_angle;  // progress along the arc
        while (g.sweep > 0 && turned < -1e-9)
          turned += 2 * kPi;
        while (g.sweep < 0 && turned > 1e-9)
          turned -= 2 * kPi;
        const double t = std::clamp(turned / g.sweep, 0.0, 1.0);
        if (distance(l.end, m.end) > tol) {
          EXPECT_NEAR(l.end[g.axes.w], g.start_w + t * g.dw, 0.001 + tol);
        } else {
          break;
        }
      }
      start = m.end;
      continue;
    }
    if (i > 0 && !m.is_arc() && std::abs(m.end.x - start.x) < 0.5 * tol &&
        std::abs(m.end.y - start.y) < 0.5 * tol && std::abs(m.end.z - start.z) < 0.5 * tol) {
      continue;  // a move of nothing once rounded is not written
    }
    ASSERT_LT(k, read.moves.size());
    const Move& r = read.moves[k++];
    EXPECT_EQ(r.kind, m.kind);
    EXPECT_NEAR(r.end.x, m.end.x, tol);
    EXPECT_NEAR(r.end.y, m.end.y, tol);
    EXPECT_NEAR(r.end.z, m.end.z, tol);
    if (m.kind != MoveKind::kRapid) {
      EXPECT_NEAR(r.feed_mm_min, m.feed_mm_min, 0.05);
    }
    if (m.is_arc()) {
      EXPECT_EQ(r.clockwise, m.clockwise);
      EXPECT_EQ(r.plane, m.plane);
      const detail::PlaneAxes ax = detail::plane_axes(m.plane);
      EXPECT_NEAR(r.center[ax.u], m.center[ax.u], tol);
      EXPECT_NEAR(r.center[ax.v], m.center[ax.v], tol);
    }
    start = m.end;
  }
  // Nothing more but an optional final retract.
  for (; k < read.moves.size(); ++k)
    EXPECT_EQ(read.moves[k].kind, MoveKind::kRapid);
}

}  // namespace swarf::testing
