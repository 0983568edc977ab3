// Links that stay down (seed 003 2.4.3: links between regions are air moves): the cell
// searches that route a link through cells already cut, and the per-layer route cache they
// share. Private to src/voxel; used by the layered toolpath builder in rough.cpp.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <map>
#include <vector>

#include "swarf/voxel/voxel.h"
#include "voxel/machinable.h"
#include "voxel/regions.h"

namespace swarf::voxel_detail {

// Search state shared by a builder and its dry-run copies (one thread).
struct LinkScratch {
  std::vector<int> dist;
  std::vector<std::uint32_t> stamp;
  std::uint32_t gen = 0;
  std::vector<std::size_t> queue;
  std::vector<std::size_t> parent;
  std::vector<std::vector<std::size_t>> buckets;
  // Routes of the layer being planned, shared by its dry runs and its emission. A route
  // depends only on its end cells, the layer and which cells are cut: the regions already
  // finished (a bit each), or the previous layer for a layer change. Key: from cell, to
  // cell, layer-change flag, then the finished regions' bits.
  std::map<std::vector<std::uint64_t>, std::vector<Vec2>> routes;
};

// Heights a layer's threshold is compared with by the link tests (base heights, and the
// cell reach for the paper's rule), sorted, distinct.
std::vector<double> compared_heights(const Reach& reach);

// Searches over one layer's cells for links that stay down; the toolpath builder derives
// from it. The cell predicates are template parameters so that each search inlines them.
class LinkSearch {
 public:
  LinkSearch(const VoxelModel& m, const Reach& reach, LinkScratch& scratch)
      : m_(m), reach_(reach), scratch_(&scratch) {}

  // Cells whose squares the segment passes over (sampled at a quarter cell).
  template <class F>
  bool all_cells_along(Vec2 p, Vec2 q, F&& ok) const {
    const double c = m_.cell_mm;
    const int steps = std::max(1, static_cast<int>(std::ceil(distance(p, q) / (0.25 * c))));
    for (int s = 0; s <= steps; ++s) {
      const Vec2 a = p + (q - p) * (static_cast<double>(s) / steps);
      const int i = static_cast<int>(std::floor((a.x - m_.origin.x) / c + 0.5));
      const int j = static_cast<int>(std::floor((a.y - m_.origin.y) / c + 0.5));
      if (i < 0 || j < 0 || i >= m_.nx || j >= m_.ny || !ok(m_.column(i, j))) return false;
    }
    return true;
  }

  // A straight link at layer k's height may stay down when it keeps the tool off the part
  // and passes only over cells that `ok` says hold no material any more.
  template <class F>
  bool link_clear(int k, Vec2 p, Vec2 q, F&& ok) const {
    return all_cells_along(p, q, ok) && straight_move_clear(m_, reach_, k, p, q);
  }

  // Cells on an axis-parallel (or diagonal) segment between two cell centres.
  template <class F>
  void for_cells(CellPoint a, CellPoint b, F&& f) const {
    const int di = (b.i > a.i) - (b.i < a.i), dj = (b.j > a.j) - (b.j < a.j);
    for (CellPoint c = a;; c.i += di, c.j += dj) {
      f(m_.column(c.i, c.j));
      if (c == b) break;
    }
  }

  std::size_t cell_at(Vec2 p) const {
    const int i = static_cast<int>(std::floor((p.x - m_.origin.x) / m_.cell_mm + 0.5));
    const int j = static_cast<int>(std::floor((p.y - m_.origin.y) / m_.cell_mm + 0.5));
    return m_.column(std::clamp(i, 0, m_.nx - 1), std::clamp(j, 0, m_.ny - 1));
  }

  // Breadth-first search from `start` over cells where ok(c) holds, stepping only along the
  // layer's safe x and y feeds; stops once every cell in `targets` is reached. Distances (in
  // steps) are left in the shared scratch field, read with steps_to(); -1 = not reached.
  // The field is reset by a generation stamp, not cleared: no allocation per search.
  template <class F>
  void bfs(const std::vector<std::uint8_t>& flags, std::size_t start, F&& ok,
           const std::vector<std::size_t>& targets) const {
    LinkScratch& sc = *scratch_;
    if (sc.dist.size() != flags.size()) {
      sc.dist.assign(flags.size(), 0);
      sc.stamp.assign(flags.size(), 0);
      sc.gen = 0;
    }
    ++sc.gen;
    sc.queue.clear();
    if (!ok(start)) return;
    const auto nx = static_cast<std::size_t>(m_.nx);
    auto set = [&](std::size_t c, int d) {
      sc.stamp[c] = sc.gen;
      sc.dist[c] = d;
      sc.queue.push_back(c);
    };
    set(start, 0);
    std::size_t next_check = 64;
    for (std::size_t h = 0; h < sc.queue.size(); ++h) {
      if (h >= next_check) {
        bool all = true;
        for (std::size_t t : targets)
          all = all && steps_to(t) >= 0;
        if (all) break;
        next_check = h * 2;
      }
      const std::size_t c = sc.queue[h];
      const std::size_t i = c % nx;
      const int dc = sc.dist[c];
      auto visit = [&](std::size_t d) {
        if (sc.stamp[d] != sc.gen && ok(d)) set(d, dc + 1);
      };
      if (flags[c] & kLinkX) visit(c + 1);
      if (i > 0 && (flags[c - 1] & kLinkX)) visit(c - 1);
      if (flags[c] & kLinkY) visit(c + nx);
      if (c >= nx && (flags[c - nx] & kLinkY)) visit(c - nx);
    }
  }
  int steps_to(std::size_t c) const {
    return scratch_->stamp[c] == scratch_->gen ? scratch_->dist[c] : -1;
  }

  // Shortest 4-connected path from `from` to `to` over cells where ok(c) holds, along the
  // layer's safe feeds: A* with the Manhattan distance (exact for unit steps, so the
  // search stays near the straight line instead of flooding the layer), bucket queue.
  template <class F>
  bool astar(const std::vector<std::uint8_t>& flags, std::size_t from, std::size_t to, F&& ok,
             std::vector<std::size_t>& cells) const {
    LinkScratch& sc = *scratch_;
    if (sc.dist.size() != flags.size()) {
      sc.dist.assign(flags.size(), 0);
      sc.stamp.assign(flags.size(), 0);
      sc.gen = 0;
    }
    sc.parent.resize(flags.size());
    ++sc.gen;
    const auto nx = static_cast<std::size_t>(m_.nx);
    const long ti = static_cast<long>(to % nx), tj = static_cast<long>(to / nx);
    auto h = [&](std::size_t c) {
      return static_cast<std::size_t>(std::labs(static_cast<long>(c % nx) - ti) +
                                      std::labs(static_cast<long>(c / nx) - tj));
    };
    for (auto& b : sc.buckets)
      b.clear();
    // hc: the heuristic of c, passed in (found from the popped cell's coordinates) so that
    // no cell index is divided twice.
    auto push = [&](std::size_t c, int g, std::size_t hc) {
      sc.stamp[c] = sc.gen;
      sc.dist[c] = g;
      const std::size_t f = static_cast<std::size_t>(g) + hc;
      if (f >= sc.buckets.size()) sc.buckets.resize(f + 1);
      sc.buckets[f].push_back(c);
    };
    sc.parent[from] = from;
    push(from, 0, h(from));
    for (std::size_t f = h(from); f < sc.buckets.size(); ++f) {
      // Last in, first out within a bucket: among equal f the deepest g first, which
      // breaks the many ties of the Manhattan metric towards the target.
      while (!sc.buckets[f].empty()) {
        const std::size_t c = sc.buckets[f].back();
        sc.buckets[f].pop_back();
        const long ci = static_cast<long>(c % nx), cj = static_cast<long>(c / nx);
        const std::size_t hx = static_cast<std::size_t>(std::labs(ci - ti));
        const std::size_t hy = static_cast<std::size_t>(std::labs(cj - tj));
        if (static_cast<std::size_t>(sc.dist[c]) + hx + hy != f) continue;  // stale entry
        if (c == to) {
          cells.clear();
          for (std::size_t x = to; x != from; x = sc.parent[x])
            cells.push_back(x);
          cells.push_back(from);
          std::reverse(cells.begin(), cells.end());
          return true;
        }
        const int g = sc.dist[c] + 1;
        auto visit = [&](std::size_t d, std::size_t hd) {
          if ((sc.stamp[d] != sc.gen || g < sc.dist[d]) && ok(d)) {
            sc.parent[d] = c;
            push(d, g, hd);
          }
        };
        const std::size_t hx_plus = static_cast<std::size_t>(std::labs(ci + 1 - ti));
        const std::size_t hx_minus = static_cast<std::size_t>(std::labs(ci - 1 - ti));
        const std::size_t hy_plus = static_cast<std::size_t>(std::labs(cj + 1 - tj));
        const std::size_t hy_minus = static_cast<std::size_t>(std::labs(cj - 1 - tj));
        if (flags[c] & kLinkX) visit(c + 1, hx_plus + hy);
        if (ci > 0 && (flags[c - 1] & kLinkX)) visit(c - 1, hx_minus + hy);
        if (flags[c] & kLinkY) visit(c + nx, hx + hy_plus);
        if (c >= nx && (flags[c - nx] & kLinkY)) visit(c - nx, hx + hy_minus);
      }
    }
    return false;
  }

  // A link that stays down on the way from p to q through cells where ok(c) holds: the
  // shortest cell path, then pulled straight wherever a straight move is clear. Empty when
  // there is none. Returns the points after p, ending at q.
  template <class F>
  std::vector<Vec2> route(int k, const std::vector<std::uint8_t>& flags, Vec2 p, Vec2 q,
                          F&& ok) const {
    const std::size_t from = cell_at(p), to = cell_at(q);
    // The target itself is where the next cut starts: it may still hold material.
    auto passable = [&](std::size_t c) { return c == to || c == from || ok(c); };
    std::vector<std::size_t> cells;
    if (!astar(flags, from, to, passable, cells)) return {};
    const auto nx = static_cast<std::size_t>(m_.nx);
    auto centre = [&](std::size_t c) {
      return m_.centre(static_cast<int>(c % nx), static_cast<int>(c / nx));
    };
    // Pull the path straight: from each anchor, the farthest cell a clear straight move
    // reaches, found by galloping then bisection (O(log n) tests instead of O(n)).
    std::vector<Vec2> out;
    std::size_t a = 0;
    const std::size_t last = cells.size() - 1;
    auto clear_to = [&](std::size_t b) {
      return link_clear(k, centre(cells[a]), centre(cells[b]), passable);
    };
    while (a < last) {
      std::size_t good = a + 1, step = 1;
      while (good < last) {
        const std::size_t probe = std::min(last, good + step);
        if (!clear_to(probe)) {
          std::size_t lo = good, hi = probe;  // clear at lo, not at hi
          while (hi - lo > 1) {
            const std::size_t mid = lo + (hi - lo) / 2;
            (clear_to(mid) ? lo : hi) = mid;
          }
          good = lo;
          break;
        }
        good = probe;
        step *= 2;
      }
      out.push_back(centre(cells[good]));
      a = good;
    }
    return out;
  }

 protected:
  const VoxelModel& m_;
  const Reach& reach_;
  LinkScratch* scratch_;
};

}  // namespace swarf::voxel_detail
