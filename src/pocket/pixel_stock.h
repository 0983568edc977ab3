// The pixel stock of seed 000 section 3, on the CPU: a bit-packed bitmap of uncut pocket
// material and one of forbidden pixels (walls and islands grown by the wall stock and a
// resolution margin). The engagement of a move is the number of material pixels the tool
// disk removes between two positions (seed 000 Fig. 2 middle); only the crescent between
// the two disks is scanned, row by row with popcounts, never the whole disk or image.
#pragma once

#include <cstdint>
#include <vector>

#include "swarf/core/vec.h"
#include "swarf/polygon/polygon.h"

namespace swarf::pocket {

/// Pixel (i, j) has its centre at origin + h (i, j).
struct Grid {
  Vec2 origin;
  double h = 0.1;
  int width = 0;
  int height = 0;

  Vec2 to_px(Vec2 world) const { return (world - origin) / h; }
  Vec2 to_world(double i, double j) const { return origin + Vec2{i, j} * h; }
  std::size_t index(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(i);
  }
  /// A grid with pixel size h covering box grown by margin on every side.
  static Grid covering(const Box2& box, double h, double margin);
};

class BitImage {
 public:
  BitImage() = default;
  BitImage(int width, int height);
  int width() const { return width_; }
  int height() const { return height_; }
  bool get(int i, int j) const {
    return (row(j)[static_cast<std::size_t>(i) >> 6] >> (static_cast<unsigned>(i) & 63u)) & 1u;
  }
  void set(int i, int j, bool v);
  /// Number of set bits in columns [x0, x1] of row j (x0 <= x1, both inside).
  int count(int j, int x0, int x1) const;
  /// Clears columns [x0, x1] of row j; returns how many bits were set.
  int clear(int j, int x0, int x1);
  std::size_t count_all() const;

 private:
  const std::uint64_t* row(int j) const {
    return bits_.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(words_);
  }
  std::uint64_t* row(int j) {
    return bits_.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(words_);
  }
  int width_ = 0, height_ = 0, words_ = 0;
  std::vector<std::uint64_t> bits_;
};

/// Pixel centres inside the region (even-odd over all rings), by exact scanline crossings.
BitImage rasterize(const PolygonSet& region, const Grid& grid);

/// Called for every pixel a cut removes (for the report picture).
using CutVisitor = void (*)(void* user, int i, int j);

class PixelStock {
 public:
  static constexpr int kGouge = -1;

  /// `clearance_sq` (optional, kept by reference): squared distance in px^2 from each pixel
  /// to the nearest forbidden one; lets probes far from walls skip the gouge scan.
  PixelStock(Grid grid, BitImage material, BitImage forbidden, double tool_radius_mm,
             const std::vector<float>* clearance_sq = nullptr);

  const Grid& grid() const { return grid_; }
  double tool_radius_mm() const { return radius_px_ * grid_.h; }
  const BitImage& material() const { return material_; }
  const BitImage& forbidden() const { return forbidden_; }

  /// Material pixels in disk(to) minus disk(from), or kGouge when that crescent holds a
  /// forbidden pixel. Assumes disk(from) is already free of material and of forbidden
  /// pixels (true at every position the tool has been moved to). Changes nothing.
  int probe(Vec2 from, Vec2 to) const;
  /// Removes the material of disk(to) minus disk(from); returns the pixels removed.
  int cut(Vec2 from, Vec2 to, CutVisitor visit = nullptr, void* user = nullptr);
  /// Whole-disk versions for places the tool has not come from (entry, links, checks).
  bool gouges(Vec2 centre) const;
  int material_in_disk(Vec2 centre, double radius_mm) const;
  int stamp(Vec2 centre, CutVisitor visit = nullptr, void* user = nullptr);
  /// Gives up on one material pixel (the move chooser found no way to reach it).
  void drop_pixel(int i, int j) { material_.set(i, j, false); }

 private:
  template <class RowFn>
  bool crescent_rows(Vec2 from, Vec2 to, RowFn&& fn) const;
  Grid grid_;
  BitImage material_;
  BitImage forbidden_;
  double radius_px_;
  const std::vector<float>* clearance_sq_ = nullptr;
  // Half widths of the disk's rows for centres at y = Y + f / kSub: half_[f * rows_ + o]
  // for row Y + o - reach_ (negative: the row misses the disk). Saves a sqrt per row.
  static constexpr int kSub = 64;
  int reach_ = 0, rows_ = 0;
  std::vector<double> half_;
};

}  // namespace swarf::pocket
