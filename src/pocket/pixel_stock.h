// The pixel stock of seed 000 section 3, on the CPU: a bit-packed bitmap of uncut pocket
// material and one of forbidden pixels (walls and islands grown by the wall stock and a
// resolution margin). The engagement of a move is the number of material pixels the tool
// disk removes between two positions (seed 000 Fig. 2 middle); only the crescent between
// the two disks is scanned, row by row with popcounts, never the whole image; 8 x 8 pixel
// blocks that hold nothing are skipped (block_occupancy).
#pragma once

#include <algorithm>
#include <cmath>
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

/// Calls fn(i, j) for the pixels of the grid whose centres lie within r of c.
template <class Fn>
void for_disk(const Grid& grid, Vec2 c, double r, Fn&& fn) {
  const Vec2 q = grid.to_px(c);
  const double rp = r / grid.h;
  for (int j = std::max(0, static_cast<int>(std::floor(q.y - rp)));
       j <= std::min(grid.height - 1, static_cast<int>(std::ceil(q.y + rp))); ++j) {
    for (int i = std::max(0, static_cast<int>(std::floor(q.x - rp)));
         i <= std::min(grid.width - 1, static_cast<int>(std::ceil(q.x + rp))); ++i) {
      if (norm_sq(Vec2{i - q.x, j - q.y}) <= rp * rp) fn(i, j);
    }
  }
}

/// for_disk by rows: calls fn(j, i0, i1) for each row span [i0, i1] of the pixels whose
/// centres lie within r of c (for work done a row span at a time, as BitImage::clear).
template <class Fn>
void for_disk_rows(const Grid& grid, Vec2 c, double r, Fn&& fn) {
  const Vec2 q = grid.to_px(c);
  const double rp = r / grid.h;
  const int j0 = std::max(0, static_cast<int>(std::ceil(q.y - rp)));
  const int j1 = std::min(grid.height - 1, static_cast<int>(std::floor(q.y + rp)));
  for (int j = j0; j <= j1; ++j) {
    const double half = std::sqrt(std::max(0.0, rp * rp - (j - q.y) * (j - q.y)));
    const int i0 = std::max(0, static_cast<int>(std::ceil(q.x - half)));
    const int i1 = std::min(grid.width - 1, static_cast<int>(std::floor(q.x + half)));
    if (i0 <= i1) fn(j, i0, i1);
  }
}

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
  /// Calls fn(i) for each set bit i in columns [x0, x1] of row j, in increasing i.
  template <class Fn>
  void for_each_set(int j, int x0, int x1, Fn&& fn) const {
    const std::uint64_t* r = row(j);
    for (int w = x0 >> 6; w <= (x1 >> 6); ++w) {
      std::uint64_t m = r[w];
      if (w == (x0 >> 6)) m &= ~std::uint64_t{0} << static_cast<unsigned>(x0 & 63);
      if (w == (x1 >> 6)) m &= ~std::uint64_t{0} >> static_cast<unsigned>(63 - (x1 & 63));
      for (; m != 0; m &= m - 1)
        fn(w * 64 + __builtin_ctzll(m));
    }
  }
  /// Number of set bits in columns [x0, x1] of row j (x0 <= x1, both inside). Inline:
  /// it is the inner loop of every engagement probe. kHw: use the POPCNT instruction
  /// (only inside functions compiled for it, see pixel_stock.cpp).
  template <bool kHw = false>
  [[gnu::always_inline]] int count(int j, int x0, int x1) const {
    const std::uint64_t* r = row(j);
    const int w0 = x0 >> 6, w1 = x1 >> 6;
    const std::uint64_t lo = ~std::uint64_t{0} << static_cast<unsigned>(x0 & 63);
    const std::uint64_t hi = ~std::uint64_t{0} >> static_cast<unsigned>(63 - (x1 & 63));
    if (w0 == w1) return popcount<kHw>(r[w0] & lo & hi);
    int n = popcount<kHw>(r[w0] & lo);
    for (int w = w0 + 1; w < w1; ++w)
      n += popcount<kHw>(r[w]);
    return n + popcount<kHw>(r[w1] & hi);
  }
  /// Portable SWAR popcount by default: without -mpopcnt, std::popcount becomes a libgcc
  /// call that cost a third of the run time; the SWAR form stays inline on every target.
  template <bool kHw = false>
  [[gnu::always_inline]] static int popcount(std::uint64_t x) {
    if constexpr (kHw) {
      return __builtin_popcountll(x);
    } else {
      x = x - ((x >> 1) & 0x5555555555555555ull);
      x = (x & 0x3333333333333333ull) + ((x >> 2) & 0x3333333333333333ull);
      x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0full;
      return static_cast<int>((x * 0x0101010101010101ull) >> 56);
    }
  }
  /// Clears columns [x0, x1] of row j; returns how many bits were set.
  template <bool kHw = false>
  [[gnu::always_inline]] int clear(int j, int x0, int x1) {
    std::uint64_t* r = row(j);
    const int w0 = x0 >> 6, w1 = x1 >> 6;
    int n = 0;
    for (int w = w0; w <= w1; ++w) {
      std::uint64_t m = ~std::uint64_t{0};
      if (w == w0) m &= ~std::uint64_t{0} << static_cast<unsigned>(x0 & 63);
      if (w == w1) m &= ~std::uint64_t{0} >> static_cast<unsigned>(63 - (x1 & 63));
      n += popcount<kHw>(r[w] & m);
      r[w] &= ~m;
    }
    return n;
  }
  std::size_t count_all() const;
  /// Set bits that are not set in `mask` (same size).
  std::size_t count_all_except(const BitImage& mask) const;
  /// The lowest / highest set column in [x0, x1] of row j, or -1 when there is none.
  int first_set(int j, int x0, int x1) const;
  int last_set(int j, int x0, int x1) const;
  /// Words per row, and word w of row j (columns 64 w to 64 w + 63).
  int words_per_row() const { return words_; }
  std::uint64_t word(int j, int w) const { return row(j)[static_cast<std::size_t>(w)]; }
  /// Replaces columns 8 k to 8 k + 7 of row j by the bits of `byte`.
  void set_byte(int j, int k, unsigned byte);
  /// Replaces word w of row j (bits past the width are dropped: they stay clear).
  void set_word(int j, int w, std::uint64_t v) {
    if (w == words_ - 1 && (width_ & 63) != 0) v &= ~std::uint64_t{0} >> (64 - (width_ & 63));
    row(j)[static_cast<std::size_t>(w)] = v;
  }
  /// Sets columns [x0, x1] of row j (x0 <= x1, both inside).
  void set_span(int j, int x0, int x1) {
    std::uint64_t* r = row(j);
    const int w0 = x0 >> 6, w1 = x1 >> 6;
    const std::uint64_t lo = ~std::uint64_t{0} << static_cast<unsigned>(x0 & 63);
    const std::uint64_t hi = ~std::uint64_t{0} >> static_cast<unsigned>(63 - (x1 & 63));
    if (w0 == w1) {
      r[w0] |= lo & hi;
      return;
    }
    r[w0] |= lo;
    for (int w = w0 + 1; w < w1; ++w)
      r[w] = ~std::uint64_t{0};
    r[w1] |= hi;
  }

 private:
  [[gnu::always_inline]] const std::uint64_t* row(int j) const {
    return bits_.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(words_);
  }
  [[gnu::always_inline]] std::uint64_t* row(int j) {
    return bits_.data() + static_cast<std::size_t>(j) * static_cast<std::size_t>(words_);
  }
  int width_ = 0, height_ = 0, words_ = 0;
  std::vector<std::uint64_t> bits_;
};

/// Pixel centres inside the region (even-odd over all rings), by exact scanline crossings.
BitImage rasterize(const PolygonSet& region, const Grid& grid);

/// Which 8 x 8 pixel blocks of `img` hold a set pixel: block (k, b) covers columns 8 k to
/// 8 k + 7 and rows 8 b to 8 b + 7. Lets a disk scan skip the rows and columns round the
/// tool that hold nothing (most of the disk: the material is a thin crescent at the front).
constexpr int kBlockShift = 3;
BitImage block_occupancy(const BitImage& img);
/// Recomputes the blocks of band b (rows 8 b to 8 b + 7) over word columns w0 to w1 of img.
void update_block_occupancy(BitImage& blocks, const BitImage& img, int b, int w0, int w1);

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
  /// Counting may stop once the count passes `enough` (the result is then some value
  /// above it): callers that only need to know "more than enough" save the rest.
  int probe(Vec2 from, Vec2 to, int enough = kNoLimit) const;
  static constexpr int kNoLimit = 0x7fffffff;
  /// probe(from, to) for a `from` whose disk holds no material and no forbidden pixel
  /// (every position the tool has been moved to): then the crescent's count is the whole
  /// disk's, one row interval each instead of the difference of two. Same result.
  int probe_disk(Vec2 to, int enough = kNoLimit) const;
  /// Removes the material of disk(to) minus disk(from); returns the pixels removed.
  int cut(Vec2 from, Vec2 to, CutVisitor visit = nullptr, void* user = nullptr);
  /// cut() that writes `tag` into cells[j * width + i] for each pixel (i, j) it removes:
  /// the re-simulation's cut map, without a call through a pointer per pixel.
  int cut_tagging(Vec2 from, Vec2 to, std::uint32_t* cells, int width, std::uint32_t tag);
  /// Lets tests run the portable code on a CPU that has POPCNT and SSE4.1 (results must
  /// not depend on it). Not thread-safe against running stocks; default true.
  static void allow_cpu_features(bool allow);
  /// Whole-disk versions for places the tool has not come from (entry, links, checks).
  bool gouges(Vec2 centre) const {
    // Decided by the clearance of the nearest pixel when it is more than a pixel from R
    // (inline: a resume search asks this millions of times).
    double c = 0.0;
    if (clearance_px(centre, c)) {
      if (c - 0.71 > radius_px_ + 1.0) return false;
      if (c + 0.71 < radius_px_ - 1.0) return true;
    }
    return gouges_scan(centre);
  }
  /// Material pixels in the disk; may stop counting once past `enough` (then returns
  /// some value above it), e.g. 0 to ask "is there any?".
  int material_in_disk(Vec2 centre, double radius_mm, int enough = kNoLimit) const;
  int stamp(Vec2 centre, CutVisitor visit = nullptr, void* user = nullptr);
  /// Puts back a pixel a cut removed (the raw path dropped the move that cut it).
  void restore(int i, int j) {
    material_.set(i, j, true);
    material_blocks_.set(i >> kBlockShift, j >> kBlockShift, true);
  }

 private:
  // Calls fn(j, x0, x1) for the row pieces of disk(to) \ disk(from) that may hold a set
  // pixel of the image whose block occupancy is `blocks` (pieces clipped to its occupied
  // blocks, empty bands skipped).
  template <class RowFn>
  bool crescent_rows(Vec2 from, Vec2 to, const BitImage& blocks, RowFn&& fn) const;
  // The work of probe, cut, gouges and material_in_disk, written once; kHw instances run
  // inside functions compiled for POPCNT and SSE4.1 (floor and ceil as single
  // instructions), chosen at run time when the CPU has them: about 1.8x faster, same
  // results bit for bit (integer counts; floor and ceil are exact either way).
  template <bool kHw>
  int probe_t(Vec2 from, Vec2 to, int enough) const;
  // visit(j, x0, x1) sees each row piece before it is cleared.
  template <bool kHw, class RowVisit>
  int cut_t(Vec2 from, Vec2 to, RowVisit&& visit);
  bool gouges_scan(Vec2 centre) const;  // the disk scan behind gouges()
  // The clearance map's value (px) at the pixel nearest to p, when there is a map and p's
  // pixel is in the image. The nearest forbidden pixel lies within c +- 0.71 of p.
  bool clearance_px(Vec2 p, double& c) const {
    if (clearance_sq_ == nullptr) return false;
    const Vec2 q = grid_.to_px(p);
    const double fx = q.x + 0.5, fy = q.y + 0.5;
    if (!(fx >= 0.0 && fy >= 0.0 && fx < grid_.width && fy < grid_.height)) return false;
    const int i = static_cast<int>(fx), j = static_cast<int>(fy);  // floor: both >= 0
    c = std::sqrt(static_cast<double>((*clearance_sq_)[grid_.index(i, j)]));
    return true;
  }
  template <bool kHw>
  bool gouges_t(Vec2 centre) const;
  template <bool kHw>
  int material_in_disk_t(Vec2 centre, double radius_mm, int enough) const;
  int probe_hw(Vec2 from, Vec2 to, int enough) const;
  int cut_hw(Vec2 from, Vec2 to, CutVisitor visit, void* user);
  int cut_tagging_hw(Vec2 from, Vec2 to, std::uint32_t* cells, int width, std::uint32_t tag);
  bool gouges_hw(Vec2 centre) const;
  int material_in_disk_hw(Vec2 centre, double radius_mm, int enough) const;
  Grid grid_;
  BitImage material_;
  BitImage forbidden_;
  BitImage material_blocks_;   // block_occupancy(material_), kept up to date by cut
  BitImage forbidden_blocks_;  // block_occupancy(forbidden_)
  double radius_px_;
  const std::vector<float>* clearance_sq_ = nullptr;
  // Half widths of the disk's rows for centres at y = Y + f / kSub: half_[f * rows_ + o]
  // for row Y + o - reach_ (negative: the row misses the disk). Saves a sqrt per row.
  static constexpr int kSub = 64;
  int reach_ = 0, rows_ = 0;
  std::vector<double> half_;
  std::vector<int> first_row_, last_row_;  // per f: the disk's first and last row
};

}  // namespace swarf::pocket
