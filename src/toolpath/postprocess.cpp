// Post-processing shared by every strategy: Douglas-Peucker simplification, Chaikin corner
// cutting, and fitting circular arcs to runs of short lines.
#include "swarf/toolpath/postprocess.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace swarf {
namespace {

template <class V>
double distance_to_segment(V p, V a, V b) {
  const V ab = b - a;
  const double len_sq = norm_sq(ab);
  if (len_sq <= 0.0) return distance(p, a);
  const double t = std::clamp(dot(p - a, ab) / len_sq, 0.0, 1.0);
  return distance(p, a + ab * t);
}

/// Marks the points Douglas-Peucker keeps. Iterative with an explicit stack: toolpaths
/// reach 10^6 points and a recursive version would overflow the call stack on a spiral.
/// The distance is to the segment, not the infinite line, so that a point beyond an end
/// (a path doubling back) is measured truly and never dropped while farther than the
/// tolerance.
template <class V>
std::vector<char> douglas_peucker_keep(const std::vector<V>& pts, double tol) {
  const std::size_t n = pts.size();
  std::vector<char> keep(n, 0);
  if (n == 0) return keep;
  keep.front() = 1;
  keep.back() = 1;
  std::vector<std::pair<std::size_t, std::size_t>> stack;
  stack.emplace_back(0, n - 1);
  while (!stack.empty()) {
    const auto [first, last] = stack.back();
    stack.pop_back();
    if (last <= first + 1) continue;
    double worst = -1.0;
    std::size_t worst_i = first;
    for (std::size_t i = first + 1; i < last; ++i) {
      const double d = distance_to_segment(pts[i], pts[first], pts[last]);
      if (d > worst) {
        worst = d;
        worst_i = i;
      }
    }
    // !(worst <= tol) also splits on NaN, keeping such points rather than hiding them.
    if (!(worst <= tol)) {
      keep[worst_i] = 1;
      stack.emplace_back(worst_i, last);
      stack.emplace_back(first, worst_i);
    }
  }
  return keep;
}

template <class V>
std::vector<V> simplify_impl(const std::vector<V>& pts, double tol) {
  if (pts.size() <= 2) return pts;
  const std::vector<char> keep = douglas_peucker_keep(pts, tol);
  std::vector<V> out;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (keep[i]) out.push_back(pts[i]);
  }
  return out;
}

bool same_run(const Move& a, const Move& b) {
  return a.kind == b.kind && a.feed_mm_min == b.feed_mm_min && a.cutting == b.cutting;
}

}  // namespace

std::vector<Vec3> simplify_polyline(const std::vector<Vec3>& points, double tolerance_mm) {
  return simplify_impl(points, tolerance_mm);
}

std::vector<Vec2> simplify_polyline(const std::vector<Vec2>& points, double tolerance_mm) {
  return simplify_impl(points, tolerance_mm);
}

std::vector<Vec3> refine_steep_stretches(const std::vector<Vec3>& in, double tol,
                                         const std::function<double(Vec2)>& height) {
  if (in.size() < 2 || !(tol > 0.0)) return in;
  constexpr double kMinWidthMm = 2e-3;
  // Only stretches steeper than kSteep: a jump rises by millimetres over a sampling step. A
  // smooth arc at that slope (the ball rolling over a rim, radius r) is bent away from its
  // chord by at most w^2 (1 + kSteep^2) / (8 r) normal to it (3 um for a 0.1 mm step and
  // r = 4 mm); gentler stretches are the sampling's own business.
  constexpr double kSteep = 3.0;
  auto dir = [](const Vec3& u, const Vec3& v) {
    return std::atan2(v.z - u.z, std::hypot(v.x - u.x, v.y - u.y));
  };
  std::vector<Vec3> out;
  out.reserve(in.size());
  std::vector<std::pair<Vec3, Vec3>> stack;
  for (std::size_t k = 0; k + 1 < in.size(); ++k) {
    out.push_back(in[k]);
    const Vec3 &a0 = in[k], &b0 = in[k + 1];
    if (std::fabs(b0.z - a0.z) <= kSteep * std::hypot(b0.x - a0.x, b0.y - a0.y)) continue;
    const double th = dir(a0, b0);
    const double before = k > 0 ? std::fabs(th - dir(in[k - 1], a0)) : kPi;
    const double after = k + 2 < in.size() ? std::fabs(dir(b0, in[k + 2]) - th) : kPi;
    if (distance(a0, b0) * std::max(before, after) / 8.0 < 0.25 * tol) continue;
    // Depth first, right half pushed first, so points come out in order.
    stack.assign(1, {a0, b0});
    while (!stack.empty()) {
      const auto [a, b] = stack.back();
      stack.pop_back();
      const double w = std::hypot(b.x - a.x, b.y - a.y);
      if (w >= 2.0 * kMinWidthMm) {
        const Vec2 mxy{0.5 * (a.x + b.x), 0.5 * (a.y + b.y)};
        const double zm = height(mxy);
        const double off = std::fabs(zm - 0.5 * (a.z + b.z)) * w / std::hypot(w, b.z - a.z);
        if (off > 0.5 * tol) {
          const Vec3 m{mxy.x, mxy.y, zm};
          stack.push_back({m, b});
          stack.push_back({a, m});
          continue;
        }
      }
      if (!(b == b0)) out.push_back(b);
    }
  }
  out.push_back(in.back());
  return out;
}

std::vector<Vec2> chaikin_smooth(const std::vector<Vec2>& points, int iterations, double ratio) {
  // A ratio above 0.5 would cross the two new points over; 0.5 merges them into one.
  if (!(ratio > 0.0)) return points;
  ratio = std::min(ratio, 0.5);
  std::vector<Vec2> cur = points;
  for (int it = 0; it < iterations && cur.size() > 2; ++it) {
    std::vector<Vec2> next;
    next.reserve(2 * cur.size());
    next.push_back(cur.front());
    const std::size_t segments = cur.size() - 1;
    for (std::size_t i = 0; i < segments; ++i) {
      const Vec2 a = cur[i], b = cur[i + 1];
      // The first segment keeps its start (the path's end point) instead of the point
      // at `ratio`, and the last its end, so the ends stay put.
      if (i > 0) next.push_back(a + (b - a) * ratio);
      if (i + 1 < segments) next.push_back(a + (b - a) * (1.0 - ratio));
    }
    next.push_back(cur.back());
    // ratio 0.5 yields the same midpoint twice.
    next.erase(std::unique(next.begin(), next.end()), next.end());
    cur = std::move(next);
  }
  return cur;
}

Toolpath simplify(const Toolpath& path, double tolerance_mm) {
  Toolpath out = path;
  out.moves.clear();
  out.moves.reserve(path.moves.size());
  const auto& moves = path.moves;
  std::size_t i = 0;
  while (i < moves.size()) {
    if (moves[i].is_arc()) {
      out.moves.push_back(moves[i++]);
      continue;
    }
    std::size_t j = i + 1;
    while (j < moves.size() && !moves[j].is_arc() && same_run(moves[i], moves[j]))
      ++j;
    // The run's polyline starts where the previous move ended. The first move of the path
    // has no known start, so it is kept as is and the run starts at its end.
    std::size_t first = i;
    if (i == 0) out.moves.push_back(moves[first++]);
    if (first < j) {
      std::vector<Vec3> pts;
      pts.reserve(j - first + 1);
      pts.push_back(moves[first - 1].end);
      for (std::size_t k = first; k < j; ++k)
        pts.push_back(moves[k].end);
      const std::vector<char> keep = douglas_peucker_keep(pts, tolerance_mm);
      for (std::size_t k = first; k < j; ++k) {
        if (keep[k - first + 1]) out.moves.push_back(moves[k]);
      }
    }
    i = j;
  }
  return out;
}

}  // namespace swarf
