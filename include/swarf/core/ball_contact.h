// A ball of radius r lowered onto a point or a segment: the height of its centre when it
// first touches (the exact contacts shared by the drop-cutter and the tri-slice scans).
#pragma once

#include <cmath>
#include <limits>

#include "swarf/core/vec.h"

namespace swarf {

/// Centre height of a ball of radius r held over p when it rests on the interior of segment
/// a-b (the foot of the perpendicular from the centre inside the segment), -infinity when it
/// cannot (out of reach, or a vertical segment: its end points decide). The end points are
/// not tried.
inline double ball_on_segment_centre(Vec3 a, Vec3 b, Vec2 p, double r) {
  constexpr double kNone = -std::numeric_limits<double>::infinity();
  const Vec3 e = b - a;
  const double len = norm(e);
  if (len <= 0.0) return kNone;
  const double ux = e.x / len, uy = e.y / len, uz = e.z / len;
  const double a2 = ux * ux + uy * uy;  // 1 - uz^2, computed without cancellation
  if (a2 < 1e-14) return kNone;
  const double qx = p.x - a.x, qy = p.y - a.y;
  const double A = qx * ux + qy * uy;
  // The centre rises until its distance to the line is r: the larger root of a quadratic in
  // its height. The discriminant A^2 uz^2 - a2 (B - A^2 - r^2), B = qx^2 + qy^2, equals
  // a2 r^2 - (qx uy - qy ux)^2 (Lagrange's identity a2 B - A^2 = cross^2). Written so, it has
  // no difference of large squares: a ball exactly r from an edge (a grid point at a whole
  // distance from an axis-aligned wall) gets disc = 0, not a rounding error of either sign
  // that dropped the contact or lifted it by sqrt(1e-15).
  const double cr = qx * uy - qy * ux;
  const double disc = a2 * r * r - cr * cr;
  if (disc < 0.0) return kNone;
  const double s = (A * uz + std::sqrt(disc)) / a2;  // centre height above a.z
  const double t = A + s * uz;                       // foot of the perpendicular along the edge
  if (t < 0.0 || t > len) return kNone;
  return a.z + s;
}

}  // namespace swarf
