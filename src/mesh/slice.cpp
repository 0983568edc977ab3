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
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <utility>

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

// Undirected edge ids per triangle corner: the same for every axis, so built once per call.
struct MeshEdges {
  void build(const Mesh& mesh);
  std::vector<std::array<std::uint32_t, 3>> tri_edges;  ///< edge id of corner k -> k+1
  std::vector<std::array<std::uint32_t, 2>> edge_ends;  ///< vertex indices, lower first
};

void MeshEdges::build(const Mesh& mesh) {
  // One sort of (undirected edge key, corner slot): equal keys are adjacent, so edge ids are
  // handed out in key order without searching for each corner.
  const std::size_t n = mesh.size();
  struct Key {
    std::uint64_t key;
    std::uint32_t slot;
  };
  std::vector<Key> keys;
  keys.reserve(3 * n);
  for (std::size_t t = 0; t < n; ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t a = tri[k], b = tri[(k + 1) % 3];
      keys.push_back(
          {std::min(a, b) << 32 | std::max(a, b), static_cast<std::uint32_t>(3 * t + k)});
    }
  }
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    return a.key != b.key ? a.key < b.key : a.slot < b.slot;
  });
  tri_edges.resize(n);
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (i == 0 || keys[i].key != keys[i - 1].key)
      edge_ends.push_back({static_cast<std::uint32_t>(keys[i].key >> 32),
                           static_cast<std::uint32_t>(keys[i].key & 0xffffffffu)});
    tri_edges[keys[i].slot / 3][keys[i].slot % 3] =
        static_cast<std::uint32_t>(edge_ends.size() - 1);
  }
}

// The mesh prepared once for all levels of one axis: each triangle's corners along the axis,
// and for every level the list of triangles that it cuts (min < level <= max), so that a
// level visits exactly the triangles it cuts.
class Slicer {
 public:
  Slicer(const Mesh& mesh, const MeshEdges& edges, Axis axis, const std::vector<double>& levels)
      : mesh_(mesh),
        tri_edges_(edges.tri_edges),
        edge_ends_(edges.edge_ends),
        axis_(static_cast<int>(axis)),
        plane_(axis) {
    build_level_lists(levels);
  }

  PolygonSet slice(std::size_t level_index, double level, const SliceOptions& options) const;

 private:
  struct Segment {
    std::uint32_t from;  ///< edge id where the segment starts
    std::uint32_t to;    ///< edge id where it ends
  };

  void build_level_lists(const std::vector<double>& levels);
  Vec2 edge_point(std::uint32_t edge, double level) const;

  const Mesh& mesh_;
  const std::vector<std::array<std::uint32_t, 3>>& tri_edges_;
  const std::vector<std::array<std::uint32_t, 2>>& edge_ends_;
  int axis_;
  Axis plane_;
  std::vector<std::array<double, 3>> tri_c_;  ///< corner coordinates along the axis
  std::vector<std::uint32_t> level_start_;    ///< CSR: level i -> its triangles
  std::vector<std::uint32_t> level_tris_;     ///< ascending within each level
};

void Slicer::build_level_lists(const std::vector<double>& levels) {
  const std::size_t n = mesh_.size();
  tri_c_.reserve(n);
  for (std::size_t t = 0; t < n; ++t)
    tri_c_.push_back(
        {mesh_.corner(t, 0)[axis_], mesh_.corner(t, 1)[axis_], mesh_.corner(t, 2)[axis_]});
  // Finite levels sorted (with their indices), so that the levels a triangle cuts,
  // min < level <= max, are one run found by two binary searches.
  std::vector<std::pair<double, std::uint32_t>> sorted;
  sorted.reserve(levels.size());
  for (std::size_t i = 0; i < levels.size(); ++i)
    if (std::isfinite(levels[i])) sorted.push_back({levels[i], static_cast<std::uint32_t>(i)});
  std::sort(sorted.begin(), sorted.end());
  auto run = [&](std::size_t t, std::size_t& r0, std::size_t& r1) {
    const auto& c = tri_c_[t];
    const double lo = std::min({c[0], c[1], c[2]}), hi = std::max({c[0], c[1], c[2]});
    const auto first_above = [&](double v) {
      return static_cast<std::size_t>(
          std::upper_bound(
              sorted.begin(), sorted.end(), v,
              [](double x, const std::pair<double, std::uint32_t>& l) { return x < l.first; }) -
          sorted.begin());
    };
    r0 = first_above(lo);
    r1 = lo < hi ? first_above(hi) : r0;
  };
  // Each triangle's run found once (two binary searches), kept for the fill pass.
  std::vector<std::array<std::uint32_t, 2>> runs(n);
  level_start_.assign(levels.size() + 1, 0);
  for (std::size_t t = 0; t < n; ++t) {
    std::size_t r0 = 0, r1 = 0;
    run(t, r0, r1);
    runs[t] = {static_cast<std::uint32_t>(r0), static_cast<std::uint32_t>(r1)};
    for (std::size_t r = r0; r < r1; ++r)
      ++level_start_[sorted[r].second + 1];
  }
  for (std::size_t i = 0; i < levels.size(); ++i)
    level_start_[i + 1] += level_start_[i];
  level_tris_.resize(level_start_.back());
  std::vector<std::uint32_t> fill(level_start_.begin(), level_start_.end() - 1);
  for (std::size_t t = 0; t < n; ++t)  // ascending triangle order within each level
    for (std::uint32_t r = runs[t][0]; r < runs[t][1]; ++r)
      level_tris_[fill[sorted[r].second]++] = static_cast<std::uint32_t>(t);
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

// Per-thread tables indexed by edge id for chaining: the first sorted segment leaving an
// edge, and whether some segment enters it. Every entry is reset after use, so a table can
// serve any mesh (it only grows); scratch only, the result never depends on it.
struct ChainScratch {
  static constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<std::uint32_t> first_from;
  std::vector<char> entered;
  void reserve(std::size_t edges) {
    if (first_from.size() < edges) {
      first_from.resize(edges, kNone);
      entered.resize(edges, 0);
    }
  }
};

PolygonSet Slicer::slice(std::size_t level_index, double level, const SliceOptions& options) const {
  if (!std::isfinite(level) || level_index + 1 >= level_start_.size()) return {};
  const std::uint32_t b0 = level_start_[level_index], b1 = level_start_[level_index + 1];
  if (b0 == b1) return {};

  // 1. One directed segment per cut triangle, from edge to edge.
  std::vector<Segment> segs;
  segs.reserve(b1 - b0);
  for (std::uint32_t i = b0; i < b1; ++i) {
    const std::uint32_t t = level_tris_[i];
    const auto& c = tri_c_[t];
    bool above[3];
    int count = 0;
    for (int k = 0; k < 3; ++k)
      count += (above[k] = c[k] >= level) ? 1 : 0;
    if (count == 0 || count == 3) continue;  // cannot happen for min < level <= max
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
  // Compared as one 64-bit key: the same order, without the branch on equal starts.
  std::sort(segs.begin(), segs.end(), [](const Segment& a, const Segment& b) {
    return (std::uint64_t{a.from} << 32 | a.to) < (std::uint64_t{b.from} << 32 | b.to);
  });
  thread_local ChainScratch scratch;
  scratch.reserve(edge_ends_.size());
  std::uint32_t* first_from = scratch.first_from.data();
  char* entered = scratch.entered.data();
  for (std::size_t j = segs.size(); j-- > 0;) {
    first_from[segs[j].from] = static_cast<std::uint32_t>(j);
    entered[segs[j].to] = 1;
  }
  std::vector<char> used(segs.size(), 0);
  auto next_unused = [&](std::uint32_t edge) -> std::size_t {
    std::size_t j = first_from[edge];
    if (j == ChainScratch::kNone) return segs.size();
    for (; j < segs.size() && segs[j].from == edge; ++j)
      if (!used[j]) return j;
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
    if (!used[i] && !entered[segs[i].from]) walk(i);
  for (std::size_t i = 0; i < segs.size(); ++i)
    if (!used[i]) walk(i);
  for (const Segment& s : segs) {  // leave the tables clean for the next level
    first_from[s.from] = ChainScratch::kNone;
    entered[s.to] = 0;
  }
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
  std::array<std::vector<double>, 3> all;
  all[static_cast<std::size_t>(axis)] = levels;
  auto out = slice_mesh_axes(mesh, all, options, ctx);
  return std::move(out[static_cast<std::size_t>(axis)]);
}

std::array<std::vector<PolygonSet>, 3> slice_mesh_axes(
    const Mesh& mesh, const std::array<std::vector<double>, 3>& levels, const SliceOptions& options,
    const Context& ctx) {
  std::array<std::vector<PolygonSet>, 3> out;
  std::size_t total = 0;
  for (std::size_t a = 0; a < 3; ++a) {
    out[a].resize(levels[a].size());
    total += levels[a].size();
  }
  if (mesh.empty() || total == 0) return out;
  ctx.report("slice", 0.0);
  // The edge table and the three axes' level lists are independent (a Slicer only keeps
  // references to the table until it slices): four tasks, the edge table (the longest) first.
  MeshEdges edges;
  std::vector<std::unique_ptr<Slicer>> slicers(3);
  parallel_for(4, ctx.threads, [&](std::size_t k) {
    if (k == 0) {
      edges.build(mesh);
      return;
    }
    const std::size_t a = k - 1;
    if (!levels[a].empty())
      slicers[a] = std::make_unique<Slicer>(mesh, edges, static_cast<Axis>(a), levels[a]);
  });
  // One loop over the levels of all axes: no serial step between the families.
  parallel_for(total, ctx.threads, [&](std::size_t i) {
    if (ctx.cancelled()) return;  // the caller checks ctx after a cancelled run
    std::size_t a = 0;
    while (i >= levels[a].size()) {
      i -= levels[a].size();
      ++a;
    }
    out[a][i] = slicers[a]->slice(i, levels[a][i], options);
  });
  ctx.report("slice", 1.0);
  return out;
}

}  // namespace swarf
