// Arc fitting that keeps the tool off the pocket's walls. The generic fit (toolpath/arc_fit)
// holds each replaced point within its tolerance of the arc (5 um by default), and the
// adaptive path keeps only 2 um off a wall it rides (kWallClearanceMm), so an arc fitted to
// a pass along a round island could run up to 3 um into it: the sweep of 49 random pockets
// with --arcs found 1-4 um on 37 of them. Here every candidate arc is checked against every
// wall edge by exact arc-to-segment distance and vetoed when it comes nearer than the tool
// radius plus the wall stock; the lines stay there.
#include <algorithm>
#include <cmath>

#include "pocket/geometry.h"
#include "swarf/pocket/adaptive.h"
#include "toolpath/arc_geometry.h"

namespace swarf {
namespace {

// A fitted XY arc (toolpath/arc_geometry's start angle and signed sweep), with its ends and
// the radius at its start.
struct Arc {
  detail::ArcGeometry g;
  Vec2 c, p0, p1;
  double r = 0.0;
  bool covers(Vec2 q) const {  // whether the ray from c through q meets the arc
    double t = std::atan2(q.y - c.y, q.x - c.x) - g.start_angle;
    if (g.sweep < 0.0) t = -t;
    t = std::fmod(t, 2.0 * kPi);
    if (t < 0.0) t += 2.0 * kPi;
    return t <= std::abs(g.sweep);
  }
};

Arc arc_of(Vec2 start, const Move& m) {
  Arc a;
  a.g = detail::arc_geometry(Vec3{start.x, start.y, m.end.z}, m);
  a.c = a.g.center;
  a.p0 = start;
  a.p1 = m.end.xy();
  a.r = a.g.start_radius;
  return a;
}

// Distance from point q to the arc.
double point_arc_distance(const Arc& a, Vec2 q) {
  if (a.covers(q)) return std::abs(distance(a.c, q) - a.r);
  return std::min(distance(q, a.p0), distance(q, a.p1));
}

// Exact distance between the arc and segment [e0, e1]: the nearer of the end points of each
// to the other, and, where the segment's line misses the circle, the circle's point nearest
// the line; 0 where the segment crosses the arc.
double arc_segment_distance(const Arc& a, Vec2 e0, Vec2 e1) {
  double d = std::min({pocket::point_segment_distance(a.p0, e0, e1),
                       pocket::point_segment_distance(a.p1, e0, e1), point_arc_distance(a, e0),
                       point_arc_distance(a, e1)});
  const Vec2 u = e1 - e0;
  const double len2 = dot(u, u);
  if (len2 <= 0.0) return d;
  const double t = dot(a.c - e0, u) / len2;
  const Vec2 foot = e0 + u * t;
  const double h = distance(a.c, foot);
  if (h >= a.r) {
    if (t > 0.0 && t < 1.0 && h > 0.0) {
      const Vec2 q = a.c + (foot - a.c) * (a.r / h);
      if (a.covers(q)) d = std::min(d, h - a.r);
    }
    return d;
  }
  // The line crosses the circle at foot +- w along it.
  const double w = std::sqrt(a.r * a.r - h * h) / std::sqrt(len2);
  for (double tt : {t - w, t + w})
    if (tt >= 0.0 && tt <= 1.0 && a.covers(e0 + u * tt)) return 0.0;
  return d;
}

}  // namespace

Toolpath fit_pocket_arcs(const Toolpath& path, const Pocket& pocket, double tool_radius_mm,
                         double wall_stock_mm, ArcFitOptions options) {
  const double limit = tool_radius_mm + wall_stock_mm;
  struct Edge {
    Vec2 a, b, lo, hi;
  };
  std::vector<Edge> edges;
  for (const Ring& ring : pocket.region.rings) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
      edges.push_back({a,
                       b,
                       {std::min(a.x, b.x), std::min(a.y, b.y)},
                       {std::max(a.x, b.x), std::max(a.y, b.y)}});
    }
  }
  auto previous = options.accept;
  options.accept = [&edges, limit, previous](Vec2 start, const Move& m) {
    if (previous && !previous(start, m)) return false;
    const Arc a = arc_of(start, m);
    // The arc lies within its circle's box; edges farther than `limit` from that box
    // cannot come nearer than `limit` to the arc.
    const Vec2 lo = a.c - Vec2{a.r + limit, a.r + limit}, hi = a.c + Vec2{a.r + limit, a.r + limit};
    for (const Edge& e : edges) {
      if (e.hi.x < lo.x || e.lo.x > hi.x || e.hi.y < lo.y || e.lo.y > hi.y) continue;
      if (arc_segment_distance(a, e.a, e.b) < limit) return false;
    }
    return true;
  };
  return fit_arcs(path, options);
}

}  // namespace swarf
