#include "pocket/wall_index.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pocket/geometry.h"
#include "swarf/core/grid_walk.h"

namespace swarf::pocket {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Below this many edges the plain loops are as quick as any index.
constexpr std::size_t kMinIndexedEdges = 64;
constexpr int kMaxCellsPerSide = 1024;

}  // namespace

WallIndex::WallIndex(const PolygonSet& region, bool index) : region_(region) {
  Box2 box;
  for (std::uint32_t r = 0; r < region_.rings.size(); ++r) {
    const Ring& ring = region_.rings[r];
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      edges_.push_back({ring[i], ring[(i + 1) % n]});
      ray_edges_.push_back({ring[i], ring[(i + n - 1) % n]});
      box.add(ring[i]);
    }
  }
  if (!index || edges_.size() < kMinIndexedEdges || box.empty()) return;
  // About one cell per edge over the box; the edges lie on the walls, so the cells they
  // occupy hold a few each.
  const Vec2 size = box.size();
  cell_ = std::sqrt(std::max(size.x * size.y, 1e-12) / static_cast<double>(edges_.size()));
  cell_ = std::max({cell_, size.x / kMaxCellsPerSide, size.y / kMaxCellsPerSide, 1e-9});
  origin_ = box.min;
  nx_ = static_cast<int>(std::floor(size.x / cell_)) + 1;
  ny_ = static_cast<int>(std::floor(size.y / cell_)) + 1;
  const std::size_t ncell = static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_);
  // The cells each edge passes through (grid_walk.h), not its whole box.
  const CellGrid grid{origin_, cell_, nx_, ny_};
  auto cells_of = [&](Vec2 a, Vec2 b, auto&& fn) { for_cells_on_segment(grid, a, b, fn); };
  start_.assign(ncell + 1, 0);
  for (const Edge& e : edges_)
    cells_of(e.a, e.b, [&](std::size_t c) { ++start_[c + 1]; });
  for (std::size_t c = 0; c < ncell; ++c)
    start_[c + 1] += start_[c];
  ids_.resize(start_.back());
  {
    std::vector<std::uint32_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t k = 0; k < edges_.size(); ++k)
      cells_of(edges_[k].a, edges_[k].b, [&](std::size_t c) { ids_[fill[c]++] = k; });
  }
  // Rows for the inside test: every edge whose y range meets the row (same floor as a query
  // point's row, so a point's row always lists the edges straddling its y).
  auto row_of = [&](double y) {
    return std::clamp(static_cast<int>(std::floor((y - origin_.y) / cell_)), 0, ny_ - 1);
  };
  row_start_.assign(static_cast<std::size_t>(ny_) + 1, 0);
  for (const Edge& e : ray_edges_)
    for (int j = row_of(std::min(e.a.y, e.b.y)); j <= row_of(std::max(e.a.y, e.b.y)); ++j)
      ++row_start_[static_cast<std::size_t>(j) + 1];
  for (int j = 0; j < ny_; ++j)
    row_start_[static_cast<std::size_t>(j) + 1] += row_start_[static_cast<std::size_t>(j)];
  row_ids_.resize(row_start_.back());
  std::vector<std::uint32_t> fill(row_start_.begin(), row_start_.end() - 1);
  for (std::uint32_t k = 0; k < ray_edges_.size(); ++k) {
    const Edge& e = ray_edges_[k];
    for (int j = row_of(std::min(e.a.y, e.b.y)); j <= row_of(std::max(e.a.y, e.b.y)); ++j)
      row_ids_[fill[static_cast<std::size_t>(j)]++] = k;
  }
}

// The searches grow a square round the query (one cell, then doubling) until the best answer
// found lies within it: every edge that could beat it meets the square, so it has been
// seen, and the answer is the brute force's. The square covering the whole grid ends the
// search too. Each round visits only the cells the last one did not, and skips a cell whose
// box is farther than the best answer so far: an edge's nearest point to the query lies in
// a cell the edge is listed in, no farther than the edge itself, so an edge that could beat
// (or tie with) the answer is still seen (a finely drawn wall lists hundreds of edges in the
// last square: a 10,000-edge outline spent 70 % of its time here).
template <class Visit, class Done, class Farther>
void WallIndex::grow(Vec2 lo, Vec2 hi, Visit&& visit, Done&& done, Farther&& farther) const {
  auto cell_of = [&](double v, double o, int n) {
    return std::clamp(static_cast<int>(std::floor((v - o) / cell_)), 0, n - 1);
  };
  const double gx1 = origin_.x + nx_ * cell_, gy1 = origin_.y + ny_ * cell_;
  int pi0 = 0, pi1 = -1, pj0 = 0, pj1 = -1;  // the cells already visited (none yet)
  struct RingCell {
    double gap_sq;  // from the query's box to the cell's
    std::size_t cell;
  };
  thread_local std::vector<RingCell> ring;
  for (double r = cell_;; r *= 2.0) {
    const Box2 b{lo - Vec2{r, r}, hi + Vec2{r, r}};
    const bool meets =
        !(b.max.x < origin_.x || b.max.y < origin_.y || b.min.x > gx1 || b.min.y > gy1);
    if (meets) {
      const int i0 = cell_of(b.min.x, origin_.x, nx_), i1 = cell_of(b.max.x, origin_.x, nx_);
      const int j0 = cell_of(b.min.y, origin_.y, ny_), j1 = cell_of(b.max.y, origin_.y, ny_);
      // The new cells holding edges, nearest first, so that the best answer shrinks early
      // and prunes the rest.
      ring.clear();
      for (int j = j0; j <= j1; ++j) {
        for (int i = i0; i <= i1; ++i) {
          if (i >= pi0 && i <= pi1 && j >= pj0 && j <= pj1) {
            i = pi1;  // skip the visited block of this row
            continue;
          }
          const std::size_t c = static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) +
                                static_cast<std::size_t>(i);
          if (start_[c] == start_[c + 1]) continue;
          const Vec2 c0{origin_.x + i * cell_, origin_.y + j * cell_};
          ring.push_back({box_gap_sq(lo, hi, c0, c0 + Vec2{cell_, cell_}), c});
        }
      }
      std::sort(ring.begin(), ring.end(),
                [](const RingCell& x, const RingCell& y) { return x.gap_sq < y.gap_sq; });
      // The best answer only shrinks and the cells come nearest first: once one is farther,
      // so are the rest.
      for (const RingCell& rc : ring) {
        if (farther(rc.gap_sq)) break;
        for (std::uint32_t k = start_[rc.cell]; k < start_[rc.cell + 1]; ++k)
          visit(ids_[k]);
      }
      pi0 = i0;
      pi1 = i1;
      pj0 = j0;
      pj1 = j1;
    }
    if (done(r) ||
        (b.min.x <= origin_.x && b.min.y <= origin_.y && b.max.x >= gx1 && b.max.y >= gy1))
      return;
  }
}

double WallIndex::distance(Vec2 p) const {
  if (!indexed()) return distance_to_rings(region_, p);
  double d2 = kInf;
  grow(
      p, p,
      [&](std::uint32_t k) {
        const Edge& e = edges_[k];
        if (box_gap_sq(p, p, e.a, e.b) >= d2) return;
        d2 = std::min(d2, norm_sq(p - nearest_on_segment(p, e.a, e.b)));
      },
      [&](double r) { return d2 <= r * r; }, [&](double gap_sq) { return gap_sq >= d2; });
  return std::sqrt(d2);
}

Vec2 WallIndex::nearest(Vec2 p) const {
  if (!indexed()) return nearest_on_rings(region_, p);
  double best = kInf;
  std::uint32_t best_k = 0;
  bool found = false;
  grow(
      p, p,
      [&](std::uint32_t k) {
        const Edge& e = edges_[k];
        // Farther than the best by its box alone: it can neither beat it nor tie with it.
        if (box_gap_sq(p, p, e.a, e.b) > best) return;
        const double d2 = norm_sq(p - nearest_on_segment(p, e.a, e.b));
        // The loop over all edges keeps the first of equals: the lowest index.
        if (d2 < best || (d2 == best && k < best_k)) {
          best = d2;
          best_k = k;
          found = true;
        }
      },
      [&](double r) { return best <= r * r; }, [&](double gap_sq) { return gap_sq > best; });
  if (!found) return p;
  return nearest_on_segment(p, edges_[best_k].a, edges_[best_k].b);
}

double WallIndex::segment_distance(Vec2 a, Vec2 b) const {
  if (!indexed()) return segment_distance_to_rings(region_, a, b);
  const Vec2 lo{std::min(a.x, b.x), std::min(a.y, b.y)}, hi{std::max(a.x, b.x), std::max(a.y, b.y)};
  double d = kInf;
  grow(
      lo, hi,
      [&](std::uint32_t k) {
        const Vec2 c = edges_[k].a, e = edges_[k].b;
        if (box_gap_sq(lo, hi, c, e) >= d * d) return;  // also once d is 0
        d = std::min(d, segment_segment_distance(a, b, c, e));
      },
      [&](double r) { return d <= r; }, [&](double gap_sq) { return gap_sq >= d * d; });
  return d;
}

bool WallIndex::inside(Vec2 p) const {
  if (!indexed()) return point_in_region(region_, p);
  if (region_.rings.empty()) return false;
  if (p.y < origin_.y || p.y > origin_.y + ny_ * cell_) return false;  // no edge straddles p.y
  const int j = std::clamp(static_cast<int>(std::floor((p.y - origin_.y) / cell_)), 0, ny_ - 1);
  // Parity of the crossings to the right of p over all rings, as point_in_region counts.
  bool odd = false;
  for (std::uint32_t q = row_start_[static_cast<std::size_t>(j)];
       q < row_start_[static_cast<std::size_t>(j) + 1]; ++q) {
    const std::uint32_t k = row_ids_[q];
    const Vec2 a = ray_edges_[k].a, b = ray_edges_[k].b;
    if ((a.y > p.y) != (b.y > p.y)) {
      const double x = a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y);
      odd = odd != (p.x < x);
    }
  }
  return odd;
}

void keep_off_walls(const WallIndex& walls, double reach, double clearance, Vec2 a, Vec2 b,
                    std::vector<Vec2>& via, int depth) {
  if (depth > 16) return;
  const double need = std::min({reach, walls.distance(a), walls.distance(b)}) - 1e-7;
  if (walls.segment_distance(a, b) >= need) return;
  const Vec2 mid = (a + b) * 0.5;
  const Vec2 w = walls.nearest(mid);
  const double d = distance(mid, w);
  if (d < 1e-9 || !walls.inside(mid)) return;  // not a corner: leave it
  const Vec2 q = w + (mid - w) * ((reach + clearance) / d);
  if (!walls.inside(q) || walls.distance(q) < reach) return;
  keep_off_walls(walls, reach, clearance, a, q, via, depth + 1);
  via.push_back(q);
  keep_off_walls(walls, reach, clearance, q, b, via, depth + 1);
}

}  // namespace swarf::pocket
