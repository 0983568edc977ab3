// Seed 003 sections 2.4.1 and 2.4.2 on one layer.
#include "voxel/regions.h"

#include <cstdlib>
#include <limits>

#include "voxel/machinable.h"

namespace swarf::voxel_detail {
namespace {

// Appends a point, merging it into the last feed line when it continues that line in the
// same direction with the same cutting flag (2.4.2: only the ends of a feed line are kept).
void push(CellPath& path, CellPoint p, bool cutting) {
  if (!path.pts.empty() && path.pts.back() == p) return;
  const std::size_t n = path.pts.size();
  if (n >= 2 && path.cutting.back() == static_cast<std::uint8_t>(cutting)) {
    const CellPoint a = path.pts[n - 2], b = path.pts[n - 1];
    const long cx =
        static_cast<long>(b.i - a.i) * (p.j - b.j) - static_cast<long>(b.j - a.j) * (p.i - b.i);
    const long dt =
        static_cast<long>(b.i - a.i) * (p.i - b.i) + static_cast<long>(b.j - a.j) * (p.j - b.j);
    if (cx == 0 && dt > 0) {
      path.pts.back() = p;
      return;
    }
  }
  if (!path.pts.empty()) path.cutting.push_back(static_cast<std::uint8_t>(cutting));
  path.pts.push_back(p);
}

}  // namespace

std::vector<Run> find_runs(const std::vector<std::uint8_t>& flags, int nx, int ny) {
  std::vector<Run> runs;
  for (int j = 0; j < ny; ++j) {
    const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(nx);
    for (int i = 0; i < nx; ++i) {
      // Cells to machine: the tool fits and there is stock to remove.
      auto machine = [&](int x) {
        return (flags[row + static_cast<std::size_t>(x)] & (kFree | kStock)) == (kFree | kStock);
      };
      if (!machine(i)) continue;
      Run r{j, i, i};
      while (r.b + 1 < nx && (flags[row + static_cast<std::size_t>(r.b)] & kLinkX) &&
             machine(r.b + 1)) {
        ++r.b;
      }
      runs.push_back(r);
      i = r.b;
    }
  }
  return runs;
}

std::vector<CellPath> trapped_area_regions(const std::vector<std::uint8_t>& flags, int nx, int ny) {
  const std::vector<Run> runs = find_runs(flags, nx, ny);
  std::vector<std::size_t> row_start(static_cast<std::size_t>(ny) + 1, 0);
  for (const Run& r : runs)
    ++row_start[static_cast<std::size_t>(r.j) + 1];
  for (std::size_t j = 1; j < row_start.size(); ++j)
    row_start[j] += row_start[j - 1];
  std::vector<std::uint8_t> visited(runs.size(), 0);
  std::vector<CellPath> regions;
  std::size_t first = 0;
  for (;;) {
    // Step 3: the lowermost (then leftmost) point of the remaining trapped area.
    while (first < runs.size() && visited[first])
      ++first;
    if (first == runs.size()) break;
    CellPath path;
    std::size_t cur = first;
    visited[cur] = 1;
    push(path, {runs[cur].a, runs[cur].j}, true);
    push(path, {runs[cur].b, runs[cur].j}, true);
    int end = runs[cur].b;
    for (;;) {
      // Step 1: the nearest machinable cell of the next row that a safe y-move reaches.
      const int j = runs[cur].j;
      if (j + 1 >= ny) break;  // the Y-extremity
      const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(nx);
      std::size_t best = runs.size();
      int best_x = 0, best_d = std::numeric_limits<int>::max();
      for (std::size_t s = row_start[static_cast<std::size_t>(j) + 1];
           s < row_start[static_cast<std::size_t>(j) + 2]; ++s) {
        if (visited[s]) continue;
        const int lo = std::max(runs[s].a, runs[cur].a), hi = std::min(runs[s].b, runs[cur].b);
        for (int x = lo; x <= hi; ++x) {
          if (!(flags[row + static_cast<std::size_t>(x)] & kLinkY)) continue;
          const int d = std::abs(x - end);
          if (d < best_d) {
            best_d = d;
            best = s;
            best_x = x;
          }
        }
      }
      if (best == runs.size()) break;  // step 2: a dead end
      // Back along the line just cut (no material), up one row, then to the nearer end of
      // the new line and along it to its far end.
      push(path, {best_x, j}, false);
      push(path, {best_x, j + 1}, true);
      const Run& s = runs[best];
      const bool left_nearer = std::abs(best_x - s.a) <= std::abs(best_x - s.b);
      const int near_end = left_nearer ? s.a : s.b, far_end = left_nearer ? s.b : s.a;
      push(path, {near_end, j + 1}, true);
      push(path, {far_end, j + 1}, true);
      end = far_end;
      cur = best;
      visited[cur] = 1;
    }
    regions.push_back(std::move(path));
  }
  return regions;
}

std::vector<CellPath> zigzag_runs(const std::vector<std::uint8_t>& flags, int nx, int ny) {
  const std::vector<Run> runs = find_runs(flags, nx, ny);
  std::vector<CellPath> out;
  std::size_t r = 0;
  while (r < runs.size()) {
    std::size_t s = r;
    while (s < runs.size() && runs[s].j == runs[r].j)
      ++s;
    const bool forward = runs[r].j % 2 == 0;
    for (std::size_t t = 0; t < s - r; ++t) {
      const Run& run = forward ? runs[r + t] : runs[s - 1 - t];
      CellPath p;
      push(p, {forward ? run.a : run.b, run.j}, true);
      push(p, {forward ? run.b : run.a, run.j}, true);
      out.push_back(std::move(p));
    }
    r = s;
  }
  return out;
}

}  // namespace swarf::voxel_detail
