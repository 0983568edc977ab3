// Arc fitting: runs of short XY lines at constant height become G2/G3 arcs, which shrinks
// programs and lets the control run at the programmed feed instead of stalling on
// thousands of tiny segments.
#include <algorithm>
#include <cmath>
#include <optional>

#include "swarf/toolpath/postprocess.h"

namespace swarf {
namespace {

/// Below this chord between an arc's start and end a control may read the arc as a full
/// circle once the coordinates are rounded (RS-274: equal start and end = full turn).
constexpr double kMinArcChordMm = 0.01;

struct Circle {
  Vec2 center;
  double radius;
};

/// Circle through three points; nothing when they are (nearly) collinear.
std::optional<Circle> circle_through(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 ab = b - a, ac = c - a;
  const double d = 2.0 * cross(ab, ac);
  const double scale = norm_sq(ab) * norm_sq(ac);
  if (!(d * d > 1e-24 * scale) || scale == 0.0) return std::nullopt;
  const double ab2 = norm_sq(ab), ac2 = norm_sq(ac);
  const Vec2 off{(ac.y * ab2 - ab.y * ac2) / d, (ab.x * ac2 - ac.x * ab2) / d};
  return Circle{a + off, norm(off)};
}

struct FitArc {
  Vec2 center;
  bool clockwise;
};

/// Whether points pts[a..b] lie on one circular arc within the tolerance. The circle is
/// the one through the first, middle and last points, so its start and end radii are equal
/// and the arc ends exactly on the original end points.
std::optional<FitArc> fit(const std::vector<Vec2>& pts, std::size_t a, std::size_t b,
                          const ArcFitOptions& o) {
  if (distance(pts[a], pts[b]) < kMinArcChordMm) return std::nullopt;
  const std::size_t mid = a + (b - a) / 2;
  const auto circle = circle_through(pts[a], pts[mid], pts[b]);
  if (!circle || circle->radius < o.min_radius_mm || circle->radius > o.max_radius_mm) {
    return std::nullopt;
  }
  const double turn = cross(pts[mid] - pts[a], pts[b] - pts[mid]);
  const bool cw = turn < 0.0;
  const Vec2 c = circle->center;
  const double r = circle->radius;
  double swept = 0.0;
  for (std::size_t k = a; k < b; ++k) {
    const Vec2 p = pts[k], q = pts[k + 1];
    if (k > a && !(std::abs(distance(p, c) - r) <= o.tolerance_mm)) return std::nullopt;
    // The arc bulges away from the chord most at the chord's middle: the sagitta.
    if (!(std::abs(distance((p + q) * 0.5, c) - r) <= o.tolerance_mm)) return std::nullopt;
    // Points must advance monotonically around the centre in the arc's direction, else a
    // zig-zag of points on the circle would be taken for an arc.
    const Vec2 u = p - c, v = q - c;
    double step = std::atan2(cross(u, v), dot(u, v));
    if (cw) step = -step;
    if (step < 0.0) return std::nullopt;
    swept += step;
  }
  // Less than a full turn: an arc ending where it started would be read as a full circle.
  if (!(swept < 2.0 * kPi - 1e-6)) return std::nullopt;
  return FitArc{c, cw};
}

bool fittable(const Move& m) {
  return m.kind == MoveKind::kFeed;
}

}  // namespace

Toolpath fit_arcs(const Toolpath& path, const ArcFitOptions& options) {
  Toolpath out = path;
  out.moves.clear();
  const auto& moves = path.moves;
  const std::size_t min_lines = static_cast<std::size_t>(std::max(options.min_points, 2));
  std::size_t i = 0;
  while (i < moves.size()) {
    // The first move's start is unknown; arcs need a start.
    if (i == 0 || !fittable(moves[i]) || moves[i].end.z != moves[i - 1].end.z) {
      out.moves.push_back(moves[i++]);
      continue;
    }
    // A run of XY feed lines at one height with one feed and cutting flag.
    const double z = moves[i - 1].end.z;
    std::size_t j = i;
    while (j < moves.size() && fittable(moves[j]) && moves[j].end.z == z &&
           moves[j].feed_mm_min == moves[i].feed_mm_min && moves[j].cutting == moves[i].cutting) {
      ++j;
    }
    std::vector<Vec2> pts;
    pts.reserve(j - i + 1);
    pts.push_back(moves[i - 1].end.xy());
    for (std::size_t k = i; k < j; ++k)
      pts.push_back(moves[k].end.xy());
    const std::size_t m = pts.size() - 1;  // lines in the run
    // The arc over lines a .. a + n - 1 of the run, as a move.
    auto as_move = [&](std::size_t a, std::size_t n, const FitArc& f) {
      Move arc = moves[i + a];
      arc.kind = MoveKind::kArc;
      arc.plane = ArcPlane::kXY;
      arc.end = moves[i + a + n - 1].end;  // exactly the original end point
      arc.center = {f.center.x, f.center.y, z};
      arc.clockwise = f.clockwise;
      return arc;
    };
    auto fit_ok = [&](std::size_t a, std::size_t n) -> std::optional<FitArc> {
      auto f = fit(pts, a, a + n, options);
      if (f && options.accept && !options.accept(pts[a], as_move(a, n, *f))) return std::nullopt;
      return f;
    };
    std::size_t a = 0;
    while (a < m) {
      // Greedy: the longest arc from point a. Doubling then bisection finds it with
      // O(log n) fits of O(n) each instead of trying every length (a 10^5-point circle).
      std::size_t good = 0;
      std::optional<FitArc> good_arc;
      if (a + min_lines <= m) good_arc = fit_ok(a, min_lines);
      if (good_arc) {
        good = min_lines;
        std::size_t bad = m - a + 1;
        std::size_t probe = std::min(2 * good, m - a);
        while (probe > good && probe < bad) {
          if (auto arc = fit_ok(a, probe)) {
            good = probe;
            good_arc = arc;
            probe = std::min(2 * probe, m - a);
          } else {
            bad = probe;
          }
        }
        while (bad - good > 1) {
          const std::size_t probe2 = good + (bad - good) / 2;
          if (auto arc = fit_ok(a, probe2)) {
            good = probe2;
            good_arc = arc;
          } else {
            bad = probe2;
          }
        }
      }
      if (!good_arc) {
        out.moves.push_back(moves[i + a]);
        ++a;
        continue;
      }
      Move arc = as_move(a, good, *good_arc);
      // Annotations are peaks: keep the largest over the replaced lines (fmax skips NaN).
      for (std::size_t k = i + a; k < i + a + good; ++k) {
        arc.engagement_deg = std::fmax(arc.engagement_deg, moves[k].engagement_deg);
        arc.force_n = std::fmax(arc.force_n, moves[k].force_n);
      }
      out.moves.push_back(arc);
      a += good;
    }
    i = j;
  }
  return out;
}

}  // namespace swarf
