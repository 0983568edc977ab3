// Private: the geometry of G2/G3 arcs in any of the three planes, shared by the toolpath
// (lengths, sampling), the G-code writer (linearising for grbl), the reader and the
// pocket's wall check of fitted arcs (pocket/pocket_arcs.cpp).
#pragma once

#include <cmath>

#include "swarf/core/vec.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf::detail {

/// The axes of an arc plane as (first, second, normal) indices into Vec3, ordered so that
/// counter-clockwise in (first, second) is counter-clockwise seen from the normal's +
/// side, as RS-274 defines G2/G3 in G17 (X, Y), G18 (Z, X) and G19 (Y, Z).
struct PlaneAxes {
  int u;
  int v;
  int w;
};

constexpr PlaneAxes plane_axes(ArcPlane plane) {
  switch (plane) {
    case ArcPlane::kZX:
      return {2, 0, 1};
    case ArcPlane::kYZ:
      return {1, 2, 0};
    case ArcPlane::kXY:
    default:
      return {0, 1, 2};
  }
}

/// An arc from `start` about `center` to `end`, expressed in its plane.
struct ArcGeometry {
  PlaneAxes axes;
  Vec2 center;         ///< in (u, v)
  double start_angle;  ///< radians, of start about center
  double sweep;        ///< signed radians: > 0 counter-clockwise; never 0 (start == end: full turn)
  double start_radius;
  double end_radius;
  double start_w;  ///< normal coordinate at the start
  double dw;       ///< change of the normal coordinate (helix pitch over the whole arc)

  /// Exact length: the helix of mean radius unrolled, sqrt((sweep * r)^2 + dw^2).
  double length() const {
    const double r = 0.5 * (start_radius + end_radius);
    return std::hypot(sweep * r, dw);
  }
};

inline ArcGeometry arc_geometry(Vec3 start, const Move& move) {
  ArcGeometry g{};
  g.axes = plane_axes(move.plane);
  const Vec2 s{start[g.axes.u], start[g.axes.v]};
  const Vec2 e{move.end[g.axes.u], move.end[g.axes.v]};
  g.center = {move.center[g.axes.u], move.center[g.axes.v]};
  const Vec2 rs = s - g.center;
  const Vec2 re = e - g.center;
  g.start_radius = norm(rs);
  g.end_radius = norm(re);
  g.start_angle = std::atan2(rs.y, rs.x);
  // Angle from rs to re in (-pi, pi]; then brought into the move's direction. Equal start
  // and end points are a full circle, as G2/G3 defines them.
  double a = std::atan2(cross(rs, re), dot(rs, re));
  if (move.clockwise) {
    if (a >= 0.0) a -= 2.0 * kPi;
  } else {
    if (a <= 0.0) a += 2.0 * kPi;
  }
  g.sweep = a;
  g.start_w = start[g.axes.w];
  g.dw = move.end[g.axes.w] - start[g.axes.w];
  return g;
}

/// The point at parameter t in [0, 1] along the arc. The radius goes linearly from the
/// start's to the end's, so that t = 1 lands on the end point even when the two radii
/// differ a little (rounded G-code, fitted arcs).
inline Vec3 arc_point(const ArcGeometry& g, double t) {
  const double angle = g.start_angle + t * g.sweep;
  const double r = g.start_radius + t * (g.end_radius - g.start_radius);
  Vec3 p;
  p[g.axes.u] = g.center.x + r * std::cos(angle);
  p[g.axes.v] = g.center.y + r * std::sin(angle);
  p[g.axes.w] = g.start_w + t * g.dw;
  return p;
}

}  // namespace swarf::detail
