// Private: seed 003 sections 2.4.1 (Trapped Area segmentation) and 2.4.2 (clustering of
// CL points into straight feed lines), on one layer's cell flags.
#pragma once

#include <cstdint>
#include <vector>

namespace swarf::voxel_detail {

struct CellPoint {
  int i = 0, j = 0;
  bool operator==(const CellPoint&) const = default;
};

/// A region's path through cell centres: straight feed lines only (clustered: interior
/// points of a straight line are dropped). cutting[s] says whether segment s (from pts[s] to
/// pts[s + 1]) enters uncut material; false for moves back over cells already cut.
struct CellPath {
  std::vector<CellPoint> pts;
  std::vector<std::uint8_t> cutting;
};

/// A maximal row interval [a, b] of free cells holding stock, joined by safe x-moves.
struct Run {
  int j = 0, a = 0, b = 0;
};

/// Runs of every row, rows upwards, runs left to right.
std::vector<Run> find_runs(const std::vector<std::uint8_t>& flags, int nx, int ny);

/// Seed 003 section 2.4.1: Trapped Area regions. A region starts at the lowest, leftmost
/// unvisited run, follows it, and steps to the next row's unvisited run that a safe y-move
/// reaches closest to where the line ended, zig-zagging until no such run is left (the
/// Y-extremity or a dead end). Every run belongs to exactly one region.
std::vector<CellPath> trapped_area_regions(const std::vector<std::uint8_t>& flags, int nx, int ny);

/// The baseline: every run on its own, rows upwards, alternate rows traversed in opposite
/// directions (the plain zig-zag of a CAM system without segmentation).
std::vector<CellPath> zigzag_runs(const std::vector<std::uint8_t>& flags, int nx, int ny);

}  // namespace swarf::voxel_detail
