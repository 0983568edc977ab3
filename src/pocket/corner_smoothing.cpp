// Output smoothing of the cutting moves' corners (our addition to seed 000's post-processing,
// after its Chaikin smoothing of the links, 6.6): where the pass turns by more than a few
// degrees between two steps, the moves either side are replaced by pieces of a centripetal
// Catmull-Rom curve through the same points.
//
// Why: a pass is a polyline of steps 0.4-0.6 mm long, and where it curves tightly (the
// trochoid-like loops in a channel not much wider than the tool, the turns at a front's
// ends) it turns 10-20 degrees at each step's end. The tool's contact arc on the front half
// of its disk jumps by the turn at every corner and creeps back along the next move: a
// saw-tooth as tall as the turn about the target, where the band at a 5 % stepover is +-5
// degrees. Random pocket 1520 (ø16 at 5 %, channels round four islands): 54 % of the cut
// followed turns over 10 degrees, and the independent sweep read 73 % of the cut within
// +-20 % by the contact arc (84.5 % by removal). The curve through the same points turns a
// few degrees per piece instead, and moves no point of the path: each piece lies within
// about a hundredth of a millimetre of the chord it replaces, on the outside of the turn.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "pocket/adaptive_internal.h"

namespace swarf::pocket {
namespace {

// The heading change at b of the path a -> b -> c, degrees (0 for a zero-length side).
double turn_deg(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 u = b - a, v = c - b;
  const double lu = norm(u), lv = norm(v);
  if (lu < 1e-12 || lv < 1e-12) return 0.0;
  const double cs = std::clamp(dot(u, v) / (lu * lv), -1.0, 1.0);
  return rad_to_deg(std::acos(cs));
}

// The point at t in [0, 1] of the centripetal Catmull-Rom segment from p1 to p2 (Barry and
// Goldman's pyramid, knots spaced by the square root of the chord): it passes through p1
// and p2 with continuous tangents and, unlike the uniform kind, makes no cusp or loop
// within a segment.
Vec2 catmull_rom(Vec2 p0, Vec2 p1, Vec2 p2, Vec2 p3, double t) {
  const auto knot = [](double ti, Vec2 a, Vec2 b) {
    return ti + std::sqrt(std::max(1e-12, norm(b - a)));
  };
  const double t0 = 0.0, t1 = knot(t0, p0, p1), t2 = knot(t1, p1, p2), t3 = knot(t2, p2, p3);
  const double tt = t1 + (t2 - t1) * t;
  const auto lerp = [tt](Vec2 a, Vec2 b, double ta, double tb) {
    return a * ((tb - tt) / (tb - ta)) + b * ((tt - ta) / (tb - ta));
  };
  const Vec2 a1 = lerp(p0, p1, t0, t1), a2 = lerp(p1, p2, t1, t2), a3 = lerp(p2, p3, t2, t3);
  const Vec2 b1 = lerp(a1, a2, t0, t2), b2 = lerp(a2, a3, t1, t3);
  return lerp(b1, b2, t1, t2);
}

// A move the smoothing may replace: a straight cutting feed at the floor of its layer.
bool smoothable(const Move& mv, const Vec3& from) {
  return mv.kind == MoveKind::kFeed && mv.cutting && std::abs(mv.end.z - from.z) < 1e-9 &&
         norm(mv.end.xy() - from.xy()) > 1e-9;
}

}  // namespace

void smooth_cutting_corners(const Model& m, Toolpath& tp, double max_turn_deg) {
  // Turns sharper than this are corners (a pass's end turning back, a reversal): the curve
  // would swing wide round them, so the smoothing stops there.
  constexpr double kCornerDeg = 60.0;
  constexpr int kMostPieces = 8;
  if (tp.moves.size() < 2 || max_turn_deg <= 0.0) return;
  const double least = m.radius_mm + m.wall_stock_mm - 1e-7;
  std::vector<Move> out(1, tp.moves.front());
  std::size_t i = 1;
  while (i < tp.moves.size()) {
    if (!smoothable(tp.moves[i], tp.moves[i - 1].end)) {
      out.push_back(tp.moves[i++]);
      continue;
    }
    // A run of smoothable moves i .. j - 1, its points p[0] (where it starts) .. p[n].
    std::size_t j = i;
    while (j < tp.moves.size() && smoothable(tp.moves[j], tp.moves[j - 1].end))
      ++j;
    std::vector<Vec2> p;
    p.reserve(j - i + 1);
    p.push_back(tp.moves[i - 1].end.xy());
    for (std::size_t k = i; k < j; ++k)
      p.push_back(tp.moves[k].end.xy());
    const std::size_t n = p.size() - 1;
    std::vector<double> turn(n + 1, 0.0);
    for (std::size_t k = 1; k < n; ++k)
      turn[k] = turn_deg(p[k - 1], p[k], p[k + 1]);
    // Points within two pixels of the walls' offset: the passes along a wall sit exactly on
    // it (snap_to_wall_offset), and a curve between two of them would bow off it and leave
    // a sliver on the wall.
    std::vector<char> on_wall(n + 1, 0);
    for (std::size_t k = 0; k <= n; ++k)
      on_wall[k] = m.walls.distance(p[k]) < least + 2.0 * m.h ? 1 : 0;
    for (std::size_t k = 0; k < n; ++k) {
      const Move& mv = tp.moves[i + k];
      // The neighbours beyond the run's ends mirrored: the curve leaves and meets the
      // straight there along the move itself. The moves into and out of a corner stay
      // straight (they are a pass's end and the next one's start, or a step back).
      const bool corner = turn[k] > kCornerDeg || turn[k + 1] > kCornerDeg;
      const bool open_before = k > 0, open_after = k + 1 < n;
      // (turn[0] and turn[n], the run's ends, are 0.)
      const int pieces = std::min(
          kMostPieces,
          static_cast<int>(std::ceil(std::max(turn[k], turn[k + 1]) / max_turn_deg - 1e-9)));
      if (pieces <= 1 || corner || on_wall[k] || on_wall[k + 1]) {
        out.push_back(mv);
        continue;
      }
      const Vec2 p0 = open_before ? p[k - 1] : p[k] * 2.0 - p[k + 1];
      const Vec2 p3 = open_after ? p[k + 2] : p[k + 1] * 2.0 - p[k];
      std::vector<Vec2> q;
      bool clear = true;
      Vec2 prev = p[k];
      for (int s = 1; s <= pieces && clear; ++s) {
        const Vec2 v = s == pieces
                           ? p[k + 1]
                           : catmull_rom(p0, p[k], p[k + 1], p3, static_cast<double>(s) / pieces);
        clear = keeps_off_walls(m, prev, v, least + m.h);
        q.push_back(v);
        prev = v;
      }
      if (!clear) {
        out.push_back(mv);
        continue;
      }
      for (const Vec2& v : q) {
        Move piece = mv;
        piece.end = {v.x, v.y, mv.end.z};
        out.push_back(piece);
      }
    }
    i = j;
  }
  tp.moves = std::move(out);
}

}  // namespace swarf::pocket
