// The cells of a uniform grid that a straight segment passes through: how the spatial
// indexes over edges (the tri-slice level envelope, the mesh-vertex contacts, the pocket's
// walls) list each edge in the cells it comes near, and only those.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "swarf/core/vec.h"

namespace swarf {

/// nx x ny square cells of side `cell` from `origin`; cell (i, j) covers
/// [origin + (i, j) cell, origin + (i + 1, j + 1) cell), index j nx + i (row-major).
struct CellGrid {
  Vec2 origin;
  double cell = 1.0;
  int nx = 0, ny = 0;
};

/// Calls fn(cell index) for every cell of g that the segment a-b passes through, row by row:
/// in each row the x range of the segment's part in the row's band, widened by 1e-9 of a
/// cell so that rounding never drops a cell (an index relies on every cell an edge passes
/// through listing it). Not the segment's bounding box: a long diagonal edge would be listed
/// in a square of cells it never comes near, and every query there would test it. Cells
/// beyond the grid are clamped to its border.
template <class Fn>
void for_cells_on_segment(const CellGrid& g, Vec2 a, Vec2 b, Fn&& fn) {
  const double eps = 1e-9 * g.cell;
  const double ylo = std::min(a.y, b.y), yhi = std::max(a.y, b.y);
  const int j0 =
      std::clamp(static_cast<int>(std::floor((ylo - eps - g.origin.y) / g.cell)), 0, g.ny - 1);
  const int j1 =
      std::clamp(static_cast<int>(std::floor((yhi + eps - g.origin.y) / g.cell)), 0, g.ny - 1);
  for (int j = j0; j <= j1; ++j) {
    double xlo = std::min(a.x, b.x), xhi = std::max(a.x, b.x);
    if (a.y != b.y) {
      const double y0 = std::max(ylo, g.origin.y + j * g.cell);
      const double y1 = std::min(yhi, g.origin.y + (j + 1) * g.cell);
      const double t0 = std::clamp((y0 - a.y) / (b.y - a.y), 0.0, 1.0);
      const double t1 = std::clamp((y1 - a.y) / (b.y - a.y), 0.0, 1.0);
      const double x0 = a.x + t0 * (b.x - a.x), x1 = a.x + t1 * (b.x - a.x);
      xlo = std::max(xlo, std::min(x0, x1));
      xhi = std::min(xhi, std::max(x0, x1));
    }
    const int i0 =
        std::clamp(static_cast<int>(std::floor((xlo - eps - g.origin.x) / g.cell)), 0, g.nx - 1);
    const int i1 =
        std::clamp(static_cast<int>(std::floor((xhi + eps - g.origin.x) / g.cell)), 0, g.nx - 1);
    for (int i = i0; i <= i1; ++i)
      fn(static_cast<std::size_t>(j) * static_cast<std::size_t>(g.nx) +
         static_cast<std::size_t>(i));
  }
}

}  // namespace swarf
