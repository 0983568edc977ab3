// The one wrapper around Clipper 6 (STYLE.md 2): every boolean operation and offset in
// Swarf goes through here. Coordinates are scaled to integers on a 1e-5 mm grid, Clipper's
// arc tolerance is given in those scaled units, and every result is cleaned and oriented
// (outers CCW, holes CW) before it leaves this file.
#include "swarf/polygon/polygon.h"

#include "polygon/polygon_detail.h"

#include <polyclipping/clipper.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace swarf {
namespace {

namespace cl = ClipperLib;

// Grid units per mm. Written out (not 1 / 1e-5, which is not exactly 1e5 in binary) so that
// grid points convert back to the nearest double of their decimal value.
constexpr double kScale = 1e5;
static_assert(kScale * kPolygonResolutionMm == 1.0);
// The cleaning (detail::clean_path, Clipper's CleanPolygons rule) drops vertices closer than
// this to a neighbour or to the line through its neighbours, in grid units: 1.5 units =
// 1.5e-5 mm, far below any machining tolerance but enough to remove the slivers and spikes
// that integer rounding leaves after offsets.
constexpr double kCleanDistance = 1.5;
// Coordinates beyond this are refused by Clipper (its hiRange is about 4.6e18 units);
// keep a wide safety margin. 1e12 mm is far outside any machine.
constexpr double kMaxAbsMm = 1e12;

// std::llround of the scaled value (halves away from zero) without the call into libm: below
// 2^52 the difference from the truncation is the exact fraction, above it every double is an
// integer (|v| <= 1e17 after the clamp, within int64).
cl::cInt to_grid(double v) {
  const double s = std::clamp(v, -kMaxAbsMm, kMaxAbsMm) * kScale;
  const auto i = static_cast<cl::cInt>(s);
  const double f = s - static_cast<double>(i);
  // Branch free: the fraction is as likely above a half as below.
  return i + static_cast<cl::cInt>(f >= 0.5) - static_cast<cl::cInt>(f <= -0.5);
}

}  // namespace

namespace detail {

// Removes, per ring, vertices within `distance` grid units of the vertex before them,
// vertex pairs that fold back (the neighbours of a vertex within `distance` of each other)
// and vertices within `distance` of the line through their neighbours (of the three, the one
// lying between the other two along the longer axis is measured, so a spike is caught
// whichever way it points), stepping back to re-examine the previous vertex after each
// removal until a whole round removes nothing. That is the rule of Clipper's CleanPolygons,
// done here on index arrays without its per-ring linked list and out-of-line calls per
// vertex (Clipper's was a quarter of the slicing time; this takes about a fifth fewer
// instructions, the rule's tests and division per vertex being most of the cost). The
// result, starting vertex included, is the same, which PolygonClean.SameAsClippersCleanPolygon
// checks on random and degenerate rings.
void clean_path(ClipperLib::Path& path, double distance) {
  const std::size_t n = path.size();
  if (n == 0) return;
  thread_local std::vector<std::uint32_t> next, prev;
  thread_local std::vector<char> kept;
  next.resize(n);
  prev.resize(n);
  kept.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    next[i] = static_cast<std::uint32_t>((i + 1) % n);
    prev[(i + 1) % n] = static_cast<std::uint32_t>(i);
  }
  const double d2 = distance * distance;
  const cl::IntPoint* const pt = path.data();
  auto close = [&](const cl::IntPoint& a, const cl::IntPoint& b) {
    const double dx = static_cast<double>(a.X - b.X), dy = static_cast<double>(a.Y - b.Y);
    return dx * dx + dy * dy <= d2;
  };
  // Squared distance of p from the line through a and b (NaN when a == b: never near).
  auto line_dist2 = [](const cl::IntPoint& p, const cl::IntPoint& a, const cl::IntPoint& b) {
    const double ka = static_cast<double>(a.Y - b.Y), kb = static_cast<double>(b.X - a.X);
    const double c0 = ka * static_cast<double>(a.X) + kb * static_cast<double>(a.Y);
    const double c = ka * static_cast<double>(p.X) + kb * static_cast<double>(p.Y) - c0;
    return (c * c) / (ka * ka + kb * kb);
  };
  auto near_line = [&](const cl::IntPoint& p1, const cl::IntPoint& p2, const cl::IntPoint& p3) {
    const bool along_x = std::abs(p1.X - p2.X) > std::abs(p1.Y - p2.Y);
    const cl::cInt u1 = along_x ? p1.X : p1.Y, u2 = along_x ? p2.X : p2.Y,
                   u3 = along_x ? p3.X : p3.Y;
    if ((u1 > u2) == (u1 < u3)) return line_dist2(p1, p2, p3) < d2;
    if ((u2 > u1) == (u2 < u3)) return line_dist2(p2, p1, p3) < d2;
    return line_dist2(p3, p1, p2) < d2;
  };
  std::size_t size = n;
  auto exclude = [&](std::uint32_t i) {
    const std::uint32_t r = prev[i];
    next[r] = next[i];
    prev[next[i]] = r;
    kept[r] = 0;
    return r;
  };
  std::uint32_t cur = 0;
  while (!kept[cur] && next[cur] != prev[cur]) {
    // In this order: a near-duplicate of the previous vertex, a fold-back (the neighbours
    // close to each other: both go), a vertex near the line through its neighbours.
    const bool duplicate = close(pt[cur], pt[prev[cur]]);
    if (!duplicate && close(pt[prev[cur]], pt[next[cur]])) {
      exclude(next[cur]);
      cur = exclude(cur);
      size -= 2;
    } else if (duplicate || near_line(pt[prev[cur]], pt[cur], pt[next[cur]])) {
      cur = exclude(cur);
      size -= 1;
    } else {
      kept[cur] = 1;
      cur = next[cur];
    }
  }
  if (size < 3) size = 0;
  thread_local cl::Path out;
  out.resize(size);
  for (std::size_t i = 0; i < size; ++i, cur = next[cur])
    out[i] = pt[cur];
  path.swap(out);
}

}  // namespace detail

namespace {

void clean_paths(cl::Paths& paths, double distance) {
  for (cl::Path& p : paths)
    detail::clean_path(p, distance);
}

cl::Path to_path(const std::vector<Vec2>& ring) {
  cl::Path path;
  path.reserve(ring.size());
  for (const Vec2& p : ring) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;  // a NaN point has no place
    const cl::IntPoint q(to_grid(p.x), to_grid(p.y));
    if (!path.empty() && path.back() == q) continue;
    path.push_back(q);
  }
  return path;
}

cl::Paths to_paths(const PolygonSet& set) {
  cl::Paths paths;
  paths.reserve(set.rings.size());
  for (const Ring& r : set.rings) {
    cl::Path p = to_path(r);
    if (p.size() >= 3) paths.push_back(std::move(p));
  }
  return paths;
}

Ring to_ring(const cl::Path& path) {
  Ring ring;
  ring.reserve(path.size());
  // Division (not multiplication by 1e-5) so that grid points map to the nearest double.
  for (const cl::IntPoint& q : path)
    ring.push_back({static_cast<double>(q.X) / kScale, static_cast<double>(q.Y) / kScale});
  return ring;
}

cl::PolyFillType to_clipper(FillRule rule) {
  switch (rule) {
    case FillRule::kEvenOdd:
      return cl::pftEvenOdd;
    case FillRule::kNonZero:
      return cl::pftNonZero;
    case FillRule::kPositive:
      return cl::pftPositive;
  }
  return cl::pftNonZero;
}

// Cleans Clipper output and converts it. Clipper already returns outers with positive and
// holes with negative orientation; cleaning never flips a ring, but it can collapse one, so
// rings left with fewer than three points or zero area are dropped.
PolygonSet from_paths(cl::Paths paths) {
  clean_paths(paths, kCleanDistance);
  PolygonSet out;
  out.rings.reserve(paths.size());
  for (const cl::Path& p : paths) {
    if (p.size() < 3 || cl::Area(p) == 0.0) continue;
    out.rings.push_back(to_ring(p));
  }
  return out;
}

// Adds the outer rings of `node`'s children, each followed by its holes, to `parts`;
// islands inside holes become parts of their own.
void collect_parts(const cl::PolyNode& node, std::vector<PolygonSet>& parts) {
  for (const cl::PolyNode* outer : node.Childs) {
    cl::Paths paths{outer->Contour};
    for (const cl::PolyNode* hole : outer->Childs)
      paths.push_back(hole->Contour);
    PolygonSet part = from_paths(std::move(paths));
    // A part whose outer ring collapsed while cleaning is dropped with its holes.
    if (!part.empty() && signed_area(part.rings.front()) > 0.0) parts.push_back(std::move(part));
    for (const cl::PolyNode* hole : outer->Childs)
      collect_parts(*hole, parts);
  }
}

PolygonSet boolean(cl::ClipType type, const cl::Paths& subject, const cl::Paths& clip) {
  cl::Clipper c;
  c.AddPaths(subject, cl::ptSubject, true);
  c.AddPaths(clip, cl::ptClip, true);
  cl::Paths solution;
  c.Execute(type, solution, cl::pftNonZero, cl::pftNonZero);
  return from_paths(std::move(solution));
}

double arc_tolerance_grid(const OffsetOptions& options) {
  // Clipper's own default (0.25) is in grid units, i.e. 2.5e-6 mm here: far too fine and
  // slow. Convert the tolerance in mm, never below one grid step.
  const double tol = std::isfinite(options.arc_tolerance_mm) ? options.arc_tolerance_mm : 0.0;
  return std::max(tol * kScale, 1.0);
}

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len_sq = norm_sq(ab);
  double t = len_sq > 0.0 ? dot(p - a, ab) / len_sq : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return distance(p, a + ab * t);
}

// --- validity check for the fast normalization ---------------------------------------------

// Exact orientation sign of (b - a) x (c - a); coordinates are limited to +-2^29 grid units
// by the caller, so the products fit in 64 bits.
int orient(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c) {
  const cl::cInt v = (b.X - a.X) * (c.Y - a.Y) - (b.Y - a.Y) * (c.X - a.X);
  return (v > 0) - (v < 0);
}
bool on_segment(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& p) {
  return std::min(a.X, b.X) <= p.X && p.X <= std::max(a.X, b.X) && std::min(a.Y, b.Y) <= p.Y &&
         p.Y <= std::max(a.Y, b.Y);
}
// True when the closed segments ab and cd share any point.
bool segments_touch(const cl::IntPoint& a, const cl::IntPoint& b, const cl::IntPoint& c,
                    const cl::IntPoint& d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 != o2 && o3 != o4 && o1 * o2 <= 0 && o3 * o4 <= 0) {
    if (o1 != 0 || o2 != 0) return true;
  }
  return (o1 == 0 && on_segment(a, b, c)) || (o2 == 0 && on_segment(a, b, d)) ||
         (o3 == 0 && on_segment(c, d, a)) || (o4 == 0 && on_segment(c, d, b));
}

// True when every ring is simple and no two rings touch: every pair of edges whose y ranges
// overlap is tested exactly; edges adjacent in a ring may only share their common vertex.
bool simple_and_disjoint(const cl::Paths& paths) {
  struct Edge {
    cl::cInt ymin, ymax, xmin, xmax;
    std::uint32_t ring, index;
  };
  std::vector<Edge> edges;
  for (std::size_t r = 0; r < paths.size(); ++r) {
    const cl::Path& p = paths[r];
    for (std::size_t i = 0; i < p.size(); ++i) {
      const cl::IntPoint &a = p[i], &b = p[(i + 1) % p.size()];
      edges.push_back({std::min(a.Y, b.Y), std::max(a.Y, b.Y), std::min(a.X, b.X),
                       std::max(a.X, b.X), static_cast<std::uint32_t>(r),
                       static_cast<std::uint32_t>(i)});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return a.ymin != b.ymin ? a.ymin < b.ymin : a.xmin < b.xmin;
  });
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    const cl::Path& pe = paths[e.ring];
    const cl::IntPoint &a = pe[e.index], &b = pe[(e.index + 1) % pe.size()];
    for (std::size_t j = i + 1; j < edges.size() && edges[j].ymin <= e.ymax; ++j) {
      const Edge& f = edges[j];
      if (f.xmin > e.xmax || f.xmax < e.xmin) continue;
      const cl::Path& pf = paths[f.ring];
      const cl::IntPoint &c = pf[f.index], &d = pf[(f.index + 1) % pf.size()];
      if (e.ring == f.ring) {
        const std::size_t n = pe.size();
        const bool f_follows = (e.index + 1) % n == f.index,
                   e_follows = (f.index + 1) % n == e.index;
        if (f_follows || e_follows) {
          // Adjacent: they share one vertex; they must not fold back over each other.
          const cl::IntPoint& o = f_follows ? a : c;  // start of the first edge
          const cl::IntPoint& m = f_follows ? b : a;  // shared vertex
          const cl::IntPoint& q = f_follows ? d : b;  // end of the second edge
          if (n < 3 ||
              (orient(o, m, q) == 0 && (m.X - o.X) * (q.X - m.X) + (m.Y - o.Y) * (q.Y - m.Y) < 0))
            return false;
          if (f_follows && e_follows) return false;  // a two-point ring
          continue;
        }
      }
      if (segments_touch(a, b, c, d)) return false;
    }
  }
  return true;
}

// Winding number of ring `path` around p (p not on it).
int winding(const cl::Path& path, const cl::IntPoint& p) {
  int w = 0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    const cl::IntPoint &a = path[i], &b = path[(i + 1) % path.size()];
    if (a.Y <= p.Y) {
      if (b.Y > p.Y && orient(a, b, p) > 0) ++w;
    } else if (b.Y <= p.Y && orient(a, b, p) < 0) {
      --w;
    }
  }
  return w;
}

// For simple, disjoint rings: true when each counter-clockwise ring has winding 0 from the
// other rings and each clockwise ring winding 1, so that under the non-zero rule every ring
// separates filled (winding 1) from empty (winding 0) and the set is already normalized.
bool oriented_as_normalized(const cl::Paths& paths) {
  std::vector<cl::IntRect> boxes(paths.size());
  for (std::size_t r = 0; r < paths.size(); ++r) {
    cl::IntRect b{paths[r][0].X, paths[r][0].Y, paths[r][0].X, paths[r][0].Y};
    for (const cl::IntPoint& q : paths[r]) {
      b.left = std::min(b.left, q.X);
      b.right = std::max(b.right, q.X);
      b.top = std::min(b.top, q.Y);
      b.bottom = std::max(b.bottom, q.Y);
    }
    boxes[r] = b;
  }
  for (std::size_t r = 0; r < paths.size(); ++r) {
    const cl::IntPoint p = paths[r][0];
    int w = 0;
    for (std::size_t s = 0; s < paths.size(); ++s) {
      if (s == r) continue;
      const cl::IntRect& b = boxes[s];
      if (p.X < b.left || p.X > b.right || p.Y < b.top || p.Y > b.bottom) continue;
      w += winding(paths[s], p);
    }
    if (w != (cl::Area(paths[r]) > 0 ? 0 : 1)) return false;
  }
  return true;
}

}  // namespace

namespace detail {

PolygonSet normalized_nonzero_fast(const PolygonSet& set) {
  constexpr cl::cInt kLimit = cl::cInt{1} << 29;  // keeps orient() within 64 bits
  cl::Paths paths = to_paths(set);
  clean_paths(paths, kCleanDistance);
  // A ring that collapsed (or a figure eight of zero total area) needs the union.
  bool plain = true;
  for (const cl::Path& p : paths) {
    plain &= p.size() >= 3 && cl::Area(p) != 0.0;
    for (const cl::IntPoint& q : p)
      plain &= q.X > -kLimit && q.X < kLimit && q.Y > -kLimit && q.Y < kLimit;
  }
  if (plain && simple_and_disjoint(paths) && oriented_as_normalized(paths)) {
    PolygonSet out;
    out.rings.reserve(paths.size());
    for (const cl::Path& p : paths)
      out.rings.push_back(to_ring(p));
    return out;
  }
  return normalized(set, FillRule::kNonZero);
}

}  // namespace detail

PolygonSet normalized(const PolygonSet& set, FillRule rule) {
  cl::Clipper c;
  c.AddPaths(to_paths(set), cl::ptSubject, true);
  cl::Paths solution;
  c.Execute(cl::ctUnion, solution, to_clipper(rule), to_clipper(rule));
  return from_paths(std::move(solution));
}

PolygonSet simplified(const PolygonSet& set, double tolerance_mm) {
  if (!(tolerance_mm > 0.0)) return set;
  const double tol2 = tolerance_mm * tolerance_mm;
  PolygonSet out;
  out.rings.reserve(set.rings.size());
  std::vector<char> keep;
  std::vector<std::pair<std::size_t, std::size_t>> stack;
  for (const Ring& ring : set.rings) {
    const std::size_t n = ring.size();
    if (n < 6) {
      out.rings.push_back(ring);
      continue;
    }
    // Closed ring: split at vertex 0 and the vertex farthest from it, then Douglas-Peucker on
    // both chains (iteratively; index n stands for vertex 0 again).
    std::size_t far = 0;
    double far_d = -1.0;
    for (std::size_t k = 1; k < n; ++k) {
      const double d = norm_sq(ring[k] - ring[0]);
      if (d > far_d) {
        far_d = d;
        far = k;
      }
    }
    keep.assign(n, 0);
    keep[0] = keep[far] = 1;
    stack.assign({{0, far}, {far, n}});
    while (!stack.empty()) {
      const auto [a, b] = stack.back();
      stack.pop_back();
      if (b <= a + 1) continue;
      const Vec2 pa = ring[a], e = ring[b % n] - pa;
      const double len2 = norm_sq(e);
      double worst = -1.0;
      std::size_t at = a;
      for (std::size_t k = a + 1; k < b; ++k) {
        const Vec2 q = ring[k] - pa;
        const double t = len2 > 0.0 ? std::clamp(dot(q, e) / len2, 0.0, 1.0) : 0.0;
        const double d = norm_sq(q - e * t);
        if (d > worst) {
          worst = d;
          at = k;
        }
      }
      if (worst <= tol2) continue;
      keep[at] = 1;
      stack.push_back({a, at});
      stack.push_back({at, b});
    }
    Ring r;
    for (std::size_t k = 0; k < n; ++k)
      if (keep[k]) r.push_back(ring[k]);
    out.rings.push_back(r.size() >= 3 ? std::move(r) : ring);
  }
  return normalized(out);
}

PolygonSet unite(const PolygonSet& a, const PolygonSet& b) {
  return boolean(cl::ctUnion, to_paths(a), to_paths(b));
}

PolygonSet unite(std::span<const PolygonSet> sets) {
  // Many sets: halves united first, then the two. One union of everything is quadratic when
  // the sets lie on top of each other (the offsets of neighbouring slices in Eq. (1), nearly
  // coincident): every scanbeam then holds every set's edges, all crossing each other
  // (Clipper's intersection list took 96 % of the torus part's waterlines, 11.6 s at 0.05 mm).
  // Halving keeps each union to two overlapping inputs; on disjoint sets it costs about the
  // same as one pass.
  constexpr std::size_t kOnePass = 4;
  if (sets.size() > kOnePass) {
    const std::size_t half = sets.size() / 2;
    return unite(unite(sets.first(half)), unite(sets.subspan(half)));
  }
  // All rings as subjects of one union: normalized inputs wind +1 inside and 0 outside, so
  // under the non-zero rule the union is exactly where any set winds non-zero.
  cl::Paths all;
  for (const PolygonSet& s : sets) {
    cl::Paths p = to_paths(s);
    all.insert(all.end(), std::make_move_iterator(p.begin()), std::make_move_iterator(p.end()));
  }
  return boolean(cl::ctUnion, all, {});
}

PolygonSet subtract(const PolygonSet& a, const PolygonSet& b) {
  if (a.empty()) return {};
  return boolean(cl::ctDifference, to_paths(a), to_paths(b));
}

PolygonSet intersect(const PolygonSet& a, const PolygonSet& b) {
  if (a.empty() || b.empty()) return {};
  return boolean(cl::ctIntersection, to_paths(a), to_paths(b));
}

PolygonSet intersect(std::span<const PolygonSet> sets) {
  if (sets.empty()) return {};
  PolygonSet acc = normalized(sets.front());
  for (std::size_t i = 1; i < sets.size() && !acc.empty(); ++i)
    acc = intersect(acc, sets[i]);
  return acc;
}

PolygonSet offset(const PolygonSet& set, double delta_mm, const OffsetOptions& options) {
  if (!std::isfinite(delta_mm) || delta_mm == 0.0) return normalized(set);
  cl::ClipperOffset co(2.0, arc_tolerance_grid(options));
  co.AddPaths(to_paths(set), cl::jtRound, cl::etClosedPolygon);
  cl::Paths solution;
  co.Execute(solution, delta_mm * kScale);
  return from_paths(std::move(solution));
}

PolygonSet inflate_polylines(std::span<const Polyline2> lines, double radius_mm,
                             const OffsetOptions& options) {
  if (!std::isfinite(radius_mm) || radius_mm <= 0.0) return {};
  cl::ClipperOffset co(2.0, arc_tolerance_grid(options));
  for (const Polyline2& line : lines) {
    const cl::Path p = to_path(line);
    if (!p.empty()) co.AddPath(p, cl::jtRound, cl::etOpenRound);
  }
  cl::Paths solution;
  co.Execute(solution, radius_mm * kScale);
  return from_paths(std::move(solution));
}

double signed_area(const Ring& ring) {
  if (ring.size() < 3) return 0.0;
  // Shoelace relative to the first point: no cancellation far from the origin.
  const Vec2 o = ring.front();
  double twice = 0.0;
  for (std::size_t i = 1; i + 1 < ring.size(); ++i)
    twice += cross(ring[i] - o, ring[i + 1] - o);
  return 0.5 * twice;
}

double area(const PolygonSet& set) {
  double a = 0.0;
  for (const Ring& r : set.rings)
    a += signed_area(r);
  return a;
}

Box2 bounds(const PolygonSet& set) {
  Box2 b;
  for (const Ring& r : set.rings)
    for (const Vec2& p : r)
      b.add(p);
  return b;
}

double perimeter(const PolygonSet& set) {
  double len = 0.0;
  for (const Ring& r : set.rings)
    for (std::size_t i = 0; i < r.size(); ++i)
      len += distance(r[i], r[(i + 1) % r.size()]);
  return len;
}

bool contains(const PolygonSet& set, Vec2 p) {
  // Boundary first (points on an edge count as inside), then the non-zero winding number,
  // which for a normalized set is 1 inside and 0 outside or in a hole.
  constexpr double kOnBoundaryMm = 1e-9;
  int winding = 0;
  for (const Ring& r : set.rings) {
    const std::size_t n = r.size();
    if (n < 2) continue;
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 a = r[i], b = r[(i + 1) % n];
      if (point_segment_distance(p, a, b) <= kOnBoundaryMm) return true;
      if (a.y <= p.y) {
        if (b.y > p.y && cross(b - a, p - a) > 0.0) ++winding;
      } else if (b.y <= p.y && cross(b - a, p - a) < 0.0) {
        --winding;
      }
    }
  }
  return winding != 0;
}

double distance_to_boundary(const PolygonSet& set, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  for (const Ring& r : set.rings) {
    const std::size_t n = r.size();
    for (std::size_t i = 0; i < n; ++i)
      best = std::min(best, point_segment_distance(p, r[i], r[(i + 1) % n]));
  }
  return best;
}

std::vector<PolygonSet> connected_parts(const PolygonSet& set) {
  cl::Clipper c;
  c.AddPaths(to_paths(set), cl::ptSubject, true);
  cl::PolyTree tree;
  c.Execute(cl::ctUnion, tree, cl::pftNonZero, cl::pftNonZero);
  std::vector<PolygonSet> parts;
  collect_parts(tree, parts);
  return parts;
}

}  // namespace swarf
