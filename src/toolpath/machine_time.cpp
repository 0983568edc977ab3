// The time a program takes on a machine that cannot change speed at once: a trapezoidal
// speed profile along the path with look-ahead and grbl's junction deviation at the corners
// (LinuxCNC rounds corners within its G64 tolerance to much the same effect).
//
// The feed-only time (machining_time_s) charges nothing for a reversal; a machine has to
// stop there and start again, and slows down for every sharp corner. This is what makes a
// smooth toolpath faster on the machine than a jagged one of the same length, so it is the
// time to compare strategies by.
//
// Model (our own statement of the usual one):
// - every move is a block of length L with a top speed: its feed; on an arc of radius r
//   also the speed whose centripetal acceleration v^2 / r is the machine's acceleration a;
// - the speed at the junction of two blocks is at most that of the arc that rounds the
//   corner tangent to both blocks and passing the junction deviation d from the corner: for
//   a corner whose inside angle is phi, that arc's radius is R = d sin(phi/2) / (1 -
//   sin(phi/2)) and its speed sqrt(a R); a reversal (phi = 0) stops, a straight joint
//   (phi = 180 degrees) costs nothing, and no junction is faster than either block;
// - the tool is at rest at the start, at the end and on both sides of a move with no feed;
// - within these limits every block accelerates and brakes at a, with look-ahead over the
//   whole path (a backward pass then a forward pass over the junction speeds), and its time
//   follows from the trapezoid (or triangle) of its speed.
// Real controllers look ahead over a limited number of blocks and limit jerk as well, so
// this is a lower bound of what they take; their axes may also accelerate differently.
#include <algorithm>
#include <cmath>
#include <vector>

#include "swarf/toolpath/metrics.h"
#include "toolpath/arc_geometry.h"

namespace swarf {
namespace {

// A move as the planner sees it: length, top speed (mm/s), unit directions at its ends.
struct Block {
  double length = 0.0;
  double top_speed = 0.0;
  Vec3 dir_start;
  Vec3 dir_end;
  bool stop_before = false;  // a move with no feed came before it: it starts at rest
};

Vec3 unit(Vec3 v) {
  const double n = norm(v);
  return n > 0.0 ? v / n : Vec3{};
}

// Unit tangent of an arc or helix at parameter t in [0, 1] of its sweep.
Vec3 arc_tangent(const detail::ArcGeometry& g, double t) {
  const double angle = g.start_angle + t * g.sweep;
  const double r = g.start_radius + t * (g.end_radius - g.start_radius);
  // d/dt of the point: in the plane (-sin, cos) * r * sweep (plus the radius' change, left
  // out: it is a rounding of fitted or read-back arcs), along the normal dw.
  Vec3 d;
  d[g.axes.u] = -std::sin(angle) * r * g.sweep;
  d[g.axes.v] = std::cos(angle) * r * g.sweep;
  d[g.axes.w] = g.dw;
  return unit(d);
}

// Time to run a block of length len from speed v0 to v1, cruising at most at top, with
// acceleration accel. The planner guarantees |v1^2 - v0^2| <= 2 accel len (up to rounding).
double block_time(double len, double v0, double v1, double top, double accel) {
  const double peak_sq = accel * len + 0.5 * (v0 * v0 + v1 * v1);
  if (peak_sq >= top * top) {
    // Trapezoid: up to top, cruise, down. The time of accelerating from v to top over the
    // distance it takes, beyond len / top, is (top - v)^2 / (2 accel top).
    return len / top + ((top - v0) * (top - v0) + (top - v1) * (top - v1)) / (2.0 * accel * top);
  }
  // Triangle: up to the peak, then straight down.
  const double peak = std::max({std::sqrt(peak_sq), v0, v1});
  return (2.0 * peak - v0 - v1) / accel;
}

}  // namespace

double machine_time_s(const Toolpath& path, const MetricsOptions& options) {
  const double accel = options.accel_mm_s2;
  const bool limited = std::isfinite(accel) && accel > 0.0;
  const double deviation = std::max(0.0, options.junction_deviation_mm);
  const double rapid = options.rapid_mm_min / 60.0;

  std::vector<Block> blocks;
  blocks.reserve(path.moves.size());
  bool stop_next = false;
  for (std::size_t i = 1; i < path.moves.size(); ++i) {
    const Vec3 start = path.moves[i - 1].end;
    const Move& move = path.moves[i];
    const double speed = move.kind == MoveKind::kRapid ? rapid : move.feed_mm_min / 60.0;
    const double len = move_length(start, move);
    if (!(len > 1e-9)) continue;  // no length, no direction: the neighbours meet directly
    if (!(speed > 0.0) || !std::isfinite(speed)) {
      // No defined time (compute_metrics leaves it out too, as it does rapids when there
      // is no rapid rate); the machine stops either side.
      stop_next = true;
      continue;
    }
    Block b;
    b.length = len;
    b.top_speed = speed;
    b.stop_before = stop_next;
    stop_next = false;
    if (move.is_arc()) {
      const detail::ArcGeometry g = detail::arc_geometry(start, move);
      b.dir_start = arc_tangent(g, 0.0);
      b.dir_end = arc_tangent(g, 1.0);
      // The in-plane part of the speed turns on the radius: v_plane^2 / r <= accel.
      const double r = 0.5 * (g.start_radius + g.end_radius);
      const double planar = std::abs(g.sweep) * r;
      if (limited && r > 0.0 && planar > 0.0)
        b.top_speed = std::min(b.top_speed, std::sqrt(accel * r) * len / planar);
    } else {
      b.dir_start = b.dir_end = unit(move.end - start);
    }
    blocks.push_back(b);
  }
  if (!limited) {
    double t = 0.0;
    for (const Block& b : blocks)
      t += b.length / b.top_speed;
    return t;
  }

  // Speeds at the junctions: junction k is the start of block k, junction n the end.
  const std::size_t n = blocks.size();
  if (n == 0) return 0.0;
  std::vector<double> v(n + 1, 0.0);
  for (std::size_t k = 1; k < n; ++k) {
    const Block& before = blocks[k - 1];
    const Block& after = blocks[k];
    if (after.stop_before) continue;
    double limit = std::min(before.top_speed, after.top_speed);
    // cos of the turn between the two directions; the inside angle phi is pi - turn, so
    // sin(phi / 2) = cos(turn / 2) = sqrt((1 + cos turn) / 2).
    const double cos_turn = dot(before.dir_end, after.dir_start);
    const double s = std::sqrt(std::clamp(0.5 * (1.0 + cos_turn), 0.0, 1.0));
    if (s < 1.0 - 1e-12) limit = std::min(limit, std::sqrt(accel * deviation * s / (1.0 - s)));
    v[k] = limit;
  }
  // Backward: every block can brake to the speed at its end; forward: reach it from its start.
  for (std::size_t k = n; k-- > 0;)
    v[k] = std::min(v[k], std::sqrt(v[k + 1] * v[k + 1] + 2.0 * accel * blocks[k].length));
  for (std::size_t k = 0; k < n; ++k)
    v[k + 1] = std::min(v[k + 1], std::sqrt(v[k] * v[k] + 2.0 * accel * blocks[k].length));
  double t = 0.0;
  for (std::size_t k = 0; k < n; ++k)
    t += block_time(blocks[k].length, v[k], v[k + 1], blocks[k].top_speed, accel);
  return t;
}

}  // namespace swarf
