// Private: seed 003 section 2.3 pre-processing. Offsetting and projection reduce to
// heights: after projection (2.3.2) a column is blocked at layer k exactly when the part
// anywhere above the layer's tip (less the allowance) lies within reach, so the whole
// model is a per-cell "highest part within reach" map compared with each layer's height.
#pragma once

#include <cstdint>
#include <vector>

#include "swarf/voxel/rough.h"
#include "swarf/voxel/voxel.h"

namespace swarf::voxel_detail {

inline constexpr std::uint8_t kFree = 1;   ///< the tool centre may stand here
inline constexpr std::uint8_t kLinkX = 2;  ///< the feed to cell (i + 1, j) is safe
inline constexpr std::uint8_t kLinkY = 4;  ///< the feed to cell (i, j + 1) is safe
inline constexpr std::uint8_t kStock = 8;  ///< the cell holds stock to remove

struct Reach {
  /// Highest part point that the tool (grown by the allowance) can touch: standing at the
  /// cell centre, moving to the +x neighbour, moving to the +y neighbour. -inf = none.
  std::vector<double> centre, link_x, link_y;
  /// The base heights the reach was grown from (exact tops of the top squares, or the
  /// centre-ray tops of the paper's rule), used to test arbitrary straight links: a grid
  /// of base_nx x base_ny squares of base_square_mm, square (0, 0) centred at base_origin.
  std::vector<double> base;
  int base_nx = 0, base_ny = 0;
  double base_square_mm = 0.0;
  Vec2 base_origin;
  double radius_mm = 0.0;  ///< D/2 + allowance
  double allowance_mm = 0.0;
  OffsetRule rule = OffsetRule::kDisk;
};

Reach compute_reach(const VoxelModel& model, double tool_radius_mm, double allowance_mm,
                    OffsetRule rule, int threads);

/// Heights at or above this block the tip at layer k (floor allowance included).
double layer_threshold(const VoxelModel& model, const Reach& reach, int k);

/// Flags (kFree, kLinkX, kLinkY, kStock) of every cell at layer k; empty when no cell
/// holding stock is free. `stock` marks the cells whose square meets the stock (empty =
/// all).
std::vector<std::uint8_t> layer_flags(const VoxelModel& model, const Reach& reach, int k,
                                      const std::vector<std::uint8_t>& stock);

/// Exact test of a straight move at layer k between two points (mm): does the stadium of
/// radius reach.radius_mm around it stay clear of every cell square whose base height
/// blocks the layer? (The paper's square rule tests only the end cells' flags.)
bool straight_move_clear(const VoxelModel& model, const Reach& reach, int k, Vec2 p, Vec2 q);

}  // namespace swarf::voxel_detail
