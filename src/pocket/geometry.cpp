#include "pocket/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace swarf::pocket {

double ring_area(const Ring& ring) {
  double a = 0.0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i)
    a += cross(ring[i], ring[(i + 1) % n]);
  return 0.5 * a;
}

bool point_in_ring(const Ring& ring, Vec2 p) {
  bool inside = false;
  for (std::size_t i = 0, n = ring.size(), j = n - 1; i < n; j = i++) {
    const Vec2 a = ring[i], b = ring[j];
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      if (p.x < x) inside = !inside;
    }
  }
  return inside;
}

bool point_in_region(const PolygonSet& region, Vec2 p) {
  bool inside = false;
  for (const Ring& r : region.rings)
    inside = inside != point_in_ring(r, p);
  return inside;
}

Vec2 nearest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double l2 = norm_sq(ab);
  const double t = l2 > 0.0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
  return a + ab * t;
}

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  return distance(p, nearest_on_segment(p, a, b));
}

double box_gap_sq(Vec2 lo, Vec2 hi, Vec2 c, Vec2 e) {
  const double gx = std::max({std::min(c.x, e.x) - hi.x, 0.0, lo.x - std::max(c.x, e.x)});
  const double gy = std::max({std::min(c.y, e.y) - hi.y, 0.0, lo.y - std::max(c.y, e.y)});
  return gx * gx + gy * gy;
}

double segment_segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 e) {
  // Proper or touching crossing: distance 0.
  const double d1 = cross(b - a, c - a), d2 = cross(b - a, e - a);
  const double d3 = cross(e - c, a - c), d4 = cross(e - c, b - c);
  if (((d1 <= 0 && d2 >= 0) || (d1 >= 0 && d2 <= 0)) &&
      ((d3 <= 0 && d4 >= 0) || (d3 >= 0 && d4 <= 0)) && (d1 != 0 || d2 != 0))
    return 0.0;
  return std::min({point_segment_distance(a, c, e), point_segment_distance(b, c, e),
                   point_segment_distance(c, a, b), point_segment_distance(e, a, b)});
}

double point_line_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len = norm(d);
  return len < 1e-12 ? distance(p, a) : std::abs(cross(d, p - a)) / len;
}

double distance_to_rings(const PolygonSet& region, Vec2 p) {
  // Squared distances, one root at the end, and edges whose box lies farther than the best
  // so far skipped: the exact-geometry checks of the output call this for every path point
  // (a hypot per edge was 8 % of the benchmark L's time).
  double d2 = std::numeric_limits<double>::infinity();
  for (const Ring& r : region.rings)
    for (std::size_t i = 0, n = r.size(); i < n; ++i) {
      const Vec2 a = r[i], b = r[(i + 1) % n];
      if (box_gap_sq(p, p, a, b) >= d2) continue;
      d2 = std::min(d2, norm_sq(p - nearest_on_segment(p, a, b)));
    }
  return std::sqrt(d2);
}

double segment_distance_to_rings(const PolygonSet& region, Vec2 a, Vec2 b) {
  double d = std::numeric_limits<double>::infinity();
  const Vec2 lo{std::min(a.x, b.x), std::min(a.y, b.y)}, hi{std::max(a.x, b.x), std::max(a.y, b.y)};
  for (const Ring& r : region.rings)
    for (std::size_t i = 0, n = r.size(); i < n; ++i) {
      const Vec2 c = r[i], e = r[(i + 1) % n];
      // Boxes further apart than the best so far cannot do better.
      if (box_gap_sq(lo, hi, c, e) >= d * d) continue;
      d = std::min(d, segment_segment_distance(a, b, c, e));
      if (d == 0.0) return 0.0;
    }
  return d;
}

Vec2 nearest_on_rings(const PolygonSet& region, Vec2 p) {
  double best = std::numeric_limits<double>::infinity();
  Vec2 q = p;
  for (const Ring& r : region.rings)
    for (std::size_t i = 0, n = r.size(); i < n; ++i) {
      const Vec2 c = nearest_on_segment(p, r[i], r[(i + 1) % n]);
      const double d2 = norm_sq(p - c);
      if (d2 < best) {
        best = d2;
        q = c;
      }
    }
  return q;
}

namespace {

int orient(Vec2 a, Vec2 b, Vec2 c) {
  const double v = cross(b - a, c - a);
  return v > 0.0 ? 1 : (v < 0.0 ? -1 : 0);
}
bool on_segment(Vec2 a, Vec2 b, Vec2 p) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}
bool segments_touch(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const int o1 = orient(a, b, c), o2 = orient(a, b, d), o3 = orient(c, d, a), o4 = orient(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  if (o1 == 0 && on_segment(a, b, c)) return true;
  if (o2 == 0 && on_segment(a, b, d)) return true;
  if (o3 == 0 && on_segment(c, d, a)) return true;
  if (o4 == 0 && on_segment(c, d, b)) return true;
  return false;
}
Vec2 crossing_point(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double den = cross(b - a, d - c);
  if (std::abs(den) < 1e-300) return a;
  const double t = cross(c - a, d - c) / den;
  return a + (b - a) * std::clamp(t, 0.0, 1.0);
}

struct Edge {
  double xmin, xmax;
  std::size_t ring, index;
};

}  // namespace

namespace {

// Calls visit(crossing) for each pair of non-adjacent edges that touch, in the sweep's
// order (edges by xmin, then ring and index), until it returns true.
template <typename Visit>
void for_each_crossing(const std::vector<Ring>& rings, Visit&& visit) {
  std::vector<Edge> edges;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    for (std::size_t i = 0, n = rings[r].size(); i < n; ++i) {
      const Vec2 a = rings[r][i], b = rings[r][(i + 1) % n];
      edges.push_back({std::min(a.x, b.x), std::max(a.x, b.x), r, i});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& a, const Edge& b) {
    return a.xmin != b.xmin ? a.xmin < b.xmin
                            : (a.ring != b.ring ? a.ring < b.ring : a.index < b.index);
  });
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    const Ring& re = rings[e.ring];
    const Vec2 a = re[e.index], b = re[(e.index + 1) % re.size()];
    for (std::size_t j = i + 1; j < edges.size() && edges[j].xmin <= e.xmax; ++j) {
      const Edge& f = edges[j];
      const Ring& rf = rings[f.ring];
      if (e.ring == f.ring) {
        const std::size_t n = re.size();
        if ((e.index + 1) % n == f.index || (f.index + 1) % n == e.index) continue;  // adjacent
      }
      const Vec2 c = rf[f.index], d = rf[(f.index + 1) % rf.size()];
      if (std::max(std::min(a.y, b.y), std::min(c.y, d.y)) >
          std::min(std::max(a.y, b.y), std::max(c.y, d.y)))
        continue;
      if (segments_touch(a, b, c, d)) {
        Crossing x{e.ring, e.index, f.ring, f.index, crossing_point(a, b, c, d)};
        if (x.ring_a > x.ring_b || (x.ring_a == x.ring_b && x.edge_a > x.edge_b)) {
          std::swap(x.ring_a, x.ring_b);
          std::swap(x.edge_a, x.edge_b);
        }
        if (visit(x)) return;
      }
    }
  }
}

}  // namespace

RingContacts find_ring_contacts(const std::vector<Ring>& rings) {
  RingContacts out;
  for_each_crossing(rings, [&](const Crossing& x) {
    if (x.ring_a == x.ring_b) {
      out.self_crossing = x;
      return true;
    }
    const std::pair<std::size_t, std::size_t> pair{x.ring_a, x.ring_b};
    if (std::find(out.pairs.begin(), out.pairs.end(), pair) == out.pairs.end())
      out.pairs.push_back(pair);
    return false;
  });
  std::sort(out.pairs.begin(), out.pairs.end());
  return out;
}

Ring cleaned_ring(const Ring& ring, double eps) {
  Ring out;
  for (const Vec2& p : ring)
    if (out.empty() || distance(out.back(), p) > eps) out.push_back(p);
  while (out.size() > 1 && distance(out.front(), out.back()) <= eps)
    out.pop_back();
  return out;
}

void append_arc(std::vector<Vec2>& out, Vec2 c, double r, double a0, double a1, double tol) {
  const double sweep = a1 - a0;
  // Chord error of a chord subtending angle t is r (1 - cos(t/2)) <= tol.
  const double tol_r = std::clamp(tol / std::max(r, 1e-12), 1e-9, 1.0);
  const double max_step = 2.0 * std::acos(1.0 - tol_r);
  const int n = std::clamp(static_cast<int>(std::ceil(std::abs(sweep) / max_step)), 1, 100000);
  for (int i = 1; i <= n; ++i) {
    const double a = a0 + sweep * i / n;
    out.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
}

}  // namespace swarf::pocket
