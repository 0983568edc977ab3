// The pocket's walls (outer ring and islands) bucketed on a uniform grid, for the exact-
// geometry queries the adaptive pocket makes along its whole output: distance to the walls,
// nearest wall point, a segment's distance to the walls, inside or not. Each answers exactly
// as its brute-force counterpart in geometry.h does (the same arithmetic on the same edges,
// the same tie-breaking), only it visits the edges near the query instead of all of them: a
// plate with a dozen round bosses (580 edges) spent a third of its time in those loops.
// Private to src/pocket.
#pragma once

#include <cstdint>
#include <vector>

#include "swarf/core/vec.h"
#include "swarf/polygon/polygon.h"

namespace swarf::pocket {

/// How far the pocket toolpaths keep the tool's edge off the walls (beyond the wall stock):
/// passes snapped to a wall, moves round an island's corner, straight plunges, and the
/// contour-parallel rings round corners.
constexpr double kWallClearanceMm = 0.002;

class WallIndex {
 public:
  WallIndex() = default;
  /// `index` false: always the plain loops (what the index is checked against).
  explicit WallIndex(const PolygonSet& region, bool index = true);

  const PolygonSet& region() const { return region_; }
  /// distance_to_rings(region(), p).
  double distance(Vec2 p) const;
  /// nearest_on_rings(region(), p).
  Vec2 nearest(Vec2 p) const;
  /// segment_distance_to_rings(region(), a, b).
  double segment_distance(Vec2 a, Vec2 b) const;
  /// point_in_region(region(), p).
  bool inside(Vec2 p) const;
  /// Whether the grid is used (pockets with few edges are answered by the plain loops).
  bool indexed() const { return cell_ > 0.0; }

 private:
  struct Edge {
    Vec2 a, b;  ///< ring[i], ring[i + 1]: the order of the brute-force loops
  };
  // visit(edge) for the edges of the cells of [lo - r, hi + r], r one cell and doubling,
  // until done(r) or the square covers the grid; each cell once, and none whose box is
  // farther(squared gap from the query's box to the cell's) than the best answer so far.
  template <class Visit, class Done, class Farther>
  void grow(Vec2 lo, Vec2 hi, Visit&& visit, Done&& done, Farther&& farther) const;

  PolygonSet region_;
  std::vector<Edge> edges_;  ///< every ring's edges, rings in order
  double cell_ = 0.0;        ///< 0: not indexed
  Vec2 origin_;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> start_;  ///< CSR, per cell (row-major): edges whose box meets it
  std::vector<std::uint32_t> ids_;
  /// Per row of cells, the edges as point_in_ring walks them (ring[i], ring[i - 1]) whose y
  /// range meets the row.
  std::vector<std::uint32_t> row_start_;
  std::vector<std::uint32_t> row_ids_;
  std::vector<Edge> ray_edges_;  ///< (ring[i], ring[i - 1]) per edge, same index as edges_
};

/// Points to go through between a and b (in order, ends excluded) so that no straight piece
/// comes nearer to the walls than `reach`, or than a or b already are: the middle of a piece
/// that would is moved off the nearest wall to reach + clearance, and each half is checked
/// again (at most 16 levels deep). A straight move round the convex corner of an island cuts
/// in by its sagitta; this keeps a tool of radius `reach` out of the walls exactly.
void keep_off_walls(const WallIndex& walls, double reach, double clearance, Vec2 a, Vec2 b,
                    std::vector<Vec2>& via, int depth = 0);

}  // namespace swarf::pocket
