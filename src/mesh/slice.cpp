// Slicing a triangle mesh by parallel planes (seed 001 Sec. 2: the STL model is sliced in the
// xy, yz and zx planes into 2D polygon sets).
//
// Robustness comes from topology, not from tolerances: a vertex exactly on a plane counts as
// above it (symbolic perturbation), so every triangle is either uncut or cut across exactly two
// of its edges, and the cut points are identified by their mesh edge. On a closed mesh every
// cut edge is left by exactly one segment and entered by exactly one, so the loops close
// exactly, whatever the level hits (vertices, edges, whole faces). Open meshes leave open
// chains, which are joined by distance or closed.
#include "swarf/mesh/slice.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "polygon/polygon_detail.h"
#include "swarf/core/parallel.h"

namespace swarf {

Vec2 to_plane(Vec3 p, Axis axis) {
  switch (axis) {
    case Axis::kX:
      return {p.y, p.z};
    case Axis::kY:
      return {p.z, p.x};
    case Axis::kZ:
      return {p.x, p.y};
  }
  return {p.x, p.y};
}

Vec3 from_plane(Vec2 uv, double level, Axis axis) {
  switch (axis) {
    case Axis::kX:
      return {level, uv.x, uv.y};
    case Axis::kY:
      return {uv.y, level, uv.x};
    case Axis::kZ:
      return {uv.x, uv.y, level};
  }
  return {uv.x, uv.y, level};
}

std::vector<double> slice_levels(double from, double to, double pitch) {
  if (!std::isfinite(from) || !std::isfinite(to) || !std::isfinite(pitch) || pitch <= 0.0 ||
      to < from)
    return {};
  const double span = to - from;
  // The relative slack keeps a span that is a whole number of pitches (0.3 / 0.1 in binary is
  // 2.9999999999999996) from losing its last level.
  const double steps = std::floor(span / pitch * (1.0 + 1e-12) + 1e-9);
  if (steps > 1e8) return {};  // a pitch so fine the caller surely made a mistake
  const auto n = static_cast<std::size_t>(steps) + 1;
  const double margin = std::max(0.0, 0.5 * (span - static_cast<double>(n - 1) * pitch));
  std::vector<double> levels(n);
  for (std::size_t i = 0; i < n; ++i)
    levels[i] = std::min(to, from + margin + static_cast<double>(i) * pitch);
  return levels;
}

namespace {

// The mesh prepared once for all levels: undirected edge ids per triangle corner, the extent
// of each triangle along the axis, and buckets of triangles along the axis so that a level
// visits only triangles near it.
class Slicer {
 public:
  Slicer(const Mesh& mesh, Axis axis) : mesh_(mesh), axis_(static_cast<int>(axis)), plane_(axis) {
    build_edges();
    build_buckets();
  }

  PolygonSet slice(double level, const SliceOptions& options) const;

 private:
  struct Segment {
    std::uint32_t from;  ///< edge id where the segment starts
    std::uint32_t to;    ///< edge id where it ends
  };
  /// A triangle in a bucket with its corner coordinates along the axis, copied so that the
  /// scan over a bucket reads memory in order instead of chasing vertex indices.
  struct Entry {
    double c[3];
    std::uint32_t tri;
  };

  void build_edges();
  void build_buckets();
  Vec2 edge_point(std::uint32_t edge, double level) const;

  const Mesh& mesh_;
  int axis_;
  Axis plane_;
  std::vector<std::array<std::uint32_t, 3>> tri_edges_;  ///< edge id of corner k -> k+1
  std::vector<std::array<std::uint32_t, 2>> edge_ends_;  ///< vertex indices, lower first
  double lo_ = 0.0, hi_ = 0.0, width_ = 1.0;             ///< axis range of the mesh, bucket width
  std::vector<std::uint32_t> bucket_start_;
  std::vector<Entry> bucket_entries_;
};

void Slicer::build_edges() {
  const std::size_t n = mesh_.size();
  std::vector<std::uint64_t> keys;
  keys.reserve(3 * n);
  for (const auto& t : mesh_.triangles)
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = t[k], b = t[(k + 1) % 3];
      keys.push_back(std::min(a, b) << 32 | std::max(a, b));
    }
  std::vector<std::uint64_t> unique = keys;
  std::sort(unique.begin(), unique.end());
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  edge_ends_.resize(unique.size());
  for (std::size_t e = 0; e < unique.size(); ++e)
    edge_ends_[e] = {static_cast<std::uint32_t>(unique[e] >> 32),
                     static_cast<std::uint32_t>(unique[e] & 0xffffffffu)};
  tri_edges_.resize(n);
  for (std::size_t t = 0; t < n; ++t)
    for (int k = 0; k < 3; ++k)
      tri_edges_[t][k] = static_cast<std::uint32_t>(
          std::lower_bound(unique.begin(), unique.end(), keys[3 * t + k]) - unique.begin());
}

void Slicer::build_buckets() {
  const std::size_t n = mesh_.size();
  std::vector<double> tri_min(n), tri_max(n);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, extent_sum = 0.0;
  for (std::size_t t = 0; t < n; ++t) {
    const double a = mesh_.corner(t, 0)[axis_], b = mesh_.corner(t, 1)[axis_],
                 c = mesh_.corner(t, 2)[axis_];
    tri_min[t] = std::min({a, b, c});
    tri_max[t] = std::max({a, b, c});
    lo = std::min(lo, tri_min[t]);
    hi = std::max(hi, tri_max[t]);
    extent_sum += tri_max[t] - tri_min[t];
  }
  if (n == 0 || !(hi > lo)) {  // empty or flat mesh: no level cuts it
    bucket_start_ = {0, 0};
    lo_ = 0.0;
    width_ = 1.0;
    return;
  }
  lo_ = lo;
  hi_ = hi;
  // Buckets about as wide as a typical triangle is tall: a level then visits roughly twice
  // the triangles it cuts, and each triangle sits in about two buckets. Widen when tall
  // triangles would make the table large.
  const double range = hi - lo;
  width_ = std::max({extent_sum / static_cast<double>(n), range / 1e6, range * 1e-12});
  std::size_t buckets = 0, entries = 0;
  for (;;) {
    buckets = static_cast<std::size_t>(range / width_) + 1;
    entries = 0;
    for (std::size_t t = 0; t < n; ++t)
      entries += static_cast<std::size_t>((tri_max[t] - lo) / width_) -
                 static_cast<std::size_t>((tri_min[t] - lo) / width_) + 1;
    if (entries <= 8 * n + buckets || buckets <= 1) break;
    width_ *= 2.0;
  }
  bucket_start_.assign(buckets + 1, 0);
  for (std::size_t t = 0; t < n; ++t) {
    const auto b0 = static_cast<std::size_t>((tri_min[t] - lo) / width_);
    const auto b1 = static_cast<std::size_t>((tri_max[t] - lo) / width_);
    for (std::size_t b = b0; b <= b1; ++b)
      ++bucket_start_[b + 1];
  }
  for (std::size_t b = 0; b < buckets; ++b)
    bucket_start_[b + 1] += bucket_start_[b];
  bucket_entries_.resize(entries);
  std::vector<std::uint32_t> fill(bucket_start_.begin(), bucket_start_.end() - 1);
  for (std::size_t t = 0; t < n; ++t) {  // ascending triangle order within each bucket
    const auto b0 = static_cast<std::size_t>((tri_min[t] - lo) / width_);
    const auto b1 = static_cast<std::size_t>((tri_max[t] - lo) / width_);
    const Entry e{{mesh_.corner(t, 0)[axis_], mesh_.corner(t, 1)[axis_], mesh_.corner(t, 2)[axis_]},
                  static_cast<std::uint32_t>(t)};
    for (std::size_t b = b0; b <= b1; ++b)
      bucket_entries_[fill[b]++] = e;
  }
}

Vec2 Slicer::edge_point(std::uint32_t edge, double level) const {
  // Always interpolated from the lower vertex index, so that both triangles of an edge (and
  // every thread) compute the very same point.
  const Vec3& a = mesh_.vertices[edge_ends_[edge][0]];
  const Vec3& b = mesh_.vertices[edge_ends_[edge][1]];
  const double t = (level - a[axis_]) / (b[axis_] - a[axis_]);
  if (t <= 0.0) return to_plane(a, plane_);
  if (t >= 1.0) return to_plane(b, plane_);
  return to_plane(a + (b - a) * t, plane_);
}

PolygonSet Slicer::slice(double level, const SliceOptions& options) const {
  // A triangle is cut when min < level <= max, so nothing is cut outside (lo, hi]; checking
  // that first also keeps the bucket index below from overflowing.
  if (!std::isfinite(level) || bucket_start_.size() < 2 || level <= lo_ || level > hi_) return {};
  const auto bucket = static_cast<std::size_t>((level - lo_) / width_);
  if (bucket + 1 >= bucket_start_.size()) return {};

  // 1. One directed segment per cut triangle, from edge to edge.
  std::vector<Segment> segs;
  for (std::uint32_t i = bucket_start_[bucket]; i < bucket_start_[bucket + 1]; ++i) {
    const Entry& e = bucket_entries_[i];
    bool above[3];
    int count = 0;
    for (int k = 0; k < 3; ++k)
      count += (above[k] = e.c[k] >= level) ? 1 : 0;
    if (count == 0 || count == 3) continue;
    const std::uint32_t t = e.tri;
    const bool lonely_above = count == 1;
    int i0 = 0;
    while (above[i0] != lonely_above)
      ++i0;
    // The cut leaves corner i0's side through edge (i0, i0+1) and enters through (i0-1, i0).
    // Oriented so that the outward normal n of a counter-clockwise (seen from outside)
    // triangle lies to the right: direction = axis x n, so outer loops run counter-clockwise.
    const std::uint32_t out_edge = tri_edges_[t][i0], in_edge = tri_edges_[t][(i0 + 2) % 3];
    Segment s = lonely_above ? Segment{out_edge, in_edge} : Segment{in_edge, out_edge};
    if (s.from != s.to) segs.push_back(s);  // a triangle with a repeated vertex cuts nothing
  }
  if (segs.empty()) return {};

  // 2. Chain by edge id. Sorted by (from, to) so that the walk is deterministic.
  std::sort(segs.begin(), segs.end(), [](const Segment& a, const Segment& b) {
    return a.from != b.from ? a.from < b.from : a.to < b.to;
  });
  std::vector<char> used(segs.size(), 0);
  std::vector<std::uint32_t> entered;  // sorted 'to' edges: a segment whose start nobody
  entered.reserve(segs.size());        // enters begins an open chain
  for (const Segment& s : segs)
    entered.push_back(s.to);
  std::sort(entered.begin(), entered.end());
  auto next_unused = [&](std::uint32_t edge) -> std::size_t {
    auto it = std::lower_bound(segs.begin(), segs.end(), edge,
                               [](const Segment& s, std::uint32_t e) { return s.from < e; });
    for (; it != segs.end() && it->from == edge; ++it) {
      const auto j = static_cast<std::size_t>(it - segs.begin());
      if (!used[j]) return j;
    }
    return segs.size();
  };

  struct Chain {
    std::vector<Vec2> points;
    bool closed = false;
  };
  std::vector<Chain> chains;
  auto walk = [&](std::size_t start) {
    Chain c;
    std::size_t cur = start;
    for (;;) {
      used[cur] = 1;
      c.points.push_back(edge_point(segs[cur].from, level));
      const std::uint32_t to = segs[cur].to;
      if (to == segs[start].from) {
        c.closed = true;
        break;
      }
      const std::size_t nxt = next_unused(to);
      if (nxt == segs.size()) {
        c.points.push_back(edge_point(to, level));
        break;
      }
      cur = nxt;
    }
    chains.push_back(std::move(c));
  };
  // Open chains first, from their true starts, then the loops.
  for (std::size_t i = 0; i < segs.size(); ++i)
    if (!used[i] && !std::binary_search(entered.begin(), entered.end(), segs[i].from)) walk(i);
  for (std::size_t i = 0; i < segs.size(); ++i)
    if (!used[i]) walk(i);

  // 3. Open chains (open or broken meshes): append the nearest chain whose start lies within
  // the gap tolerance of the end; whatever stays open is closed by its chord.
  PolygonSet raw;
  std::vector<std::size_t> open;
  for (std::size_t i = 0; i < chains.size(); ++i) {
    if (chains[i].closed)
      raw.rings.push_back(std::move(chains[i].points));
    else
      open.push_back(i);
  }
  const double gap = std::max(0.0, options.gap_tolerance_mm);
  std::vector<char> taken(chains.size(), 0);
  for (std::size_t oi = 0; oi < open.size(); ++oi) {
    if (taken[open[oi]]) continue;
    taken[open[oi]] = 1;
    std::vector<Vec2> ring = std::move(chains[open[oi]].points);
    for (;;) {
      if (distance(ring.back(), ring.front()) <= gap) break;
      std::size_t best = chains.size();
      double best_d = gap;
      for (std::size_t oj : open)
        if (!taken[oj]) {
          const double d = distance(ring.back(), chains[oj].points.front());
          if (d <= best_d && (best == chains.size() || d < best_d)) {
            best = oj;
            best_d = d;
          }
        }
      if (best == chains.size()) break;
      taken[best] = 1;
      ring.insert(ring.end(), chains[best].points.begin(), chains[best].points.end());
    }
    raw.rings.push_back(std::move(ring));
  }
  // Sections of a clean closed mesh are valid already; the fast path checks that exactly and
  // only runs the Clipper union when they are not.
  return detail::normalized_nonzero_fast(raw);
}

}  // namespace

std::vector<PolygonSet> slice_mesh(const Mesh& mesh, Axis axis, const std::vector<double>& levels,
                                   const SliceOptions& options, const Context& ctx) {
  std::vector<PolygonSet> out(levels.size());
  if (mesh.empty() || levels.empty()) return out;
  ctx.report("slice", 0.0);
  const Slicer slicer(mesh, axis);
  parallel_for(levels.size(), ctx.threads, [&](std::size_t i) {
    if (ctx.cancelled()) return;  // the caller checks ctx after a cancelled run
    out[i] = slicer.slice(levels[i], options);
  });
  ctx.report("slice", 1.0);
  return out;
}

}  // namespace swarf
