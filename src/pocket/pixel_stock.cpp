#include "pocket/pixel_stock.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <type_traits>

namespace swarf::pocket {

Grid Grid::covering(const Box2& box, double h, double margin) {
  Grid g;
  g.h = h;
  g.origin = box.min - Vec2{margin, margin};
  const Vec2 size = box.size() + Vec2{2 * margin, 2 * margin};
  g.width = static_cast<int>(std::ceil(size.x / h)) + 1;
  g.height = static_cast<int>(std::ceil(size.y / h)) + 1;
  return g;
}

BitImage::BitImage(int width, int height)
    : width_(width),
      height_(height),
      words_((width + 63) / 64),
      bits_(static_cast<std::size_t>(words_) * static_cast<std::size_t>(height), 0u) {}

void BitImage::set(int i, int j, bool v) {
  std::uint64_t& w = row(j)[static_cast<std::size_t>(i) >> 6];
  const std::uint64_t m = std::uint64_t{1} << (static_cast<unsigned>(i) & 63u);
  w = v ? (w | m) : (w & ~m);
}

namespace {

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define SWARF_POCKET_DISPATCH 1
#define SWARF_TARGET_HW __attribute__((target("popcnt,sse4.1")))
std::atomic<bool> g_allow_hw{true};
bool cpu_has_hw() {
  static const bool has = __builtin_cpu_supports("popcnt") && __builtin_cpu_supports("sse4.1");
  return has && g_allow_hw.load(std::memory_order_relaxed);
}
#else
#define SWARF_TARGET_HW
#endif
// Row callbacks must be inlined into the kHw functions to be compiled for their target.
#define SWARF_INLINE __attribute__((always_inline))

}  // namespace

std::size_t BitImage::count_all() const {
  std::size_t n = 0;
  for (std::uint64_t w : bits_)
    n += static_cast<std::size_t>(popcount<>(w));
  return n;
}

std::size_t BitImage::count_all_except(const BitImage& mask) const {
  std::size_t n = 0;
  for (std::size_t k = 0; k < bits_.size(); ++k)
    n += static_cast<std::size_t>(popcount<>(bits_[k] & ~mask.bits_[k]));
  return n;
}

int BitImage::first_set(int j, int x0, int x1) const {
  const std::uint64_t* r = row(j);
  const int w0 = x0 >> 6, w1 = x1 >> 6;
  for (int w = w0; w <= w1; ++w) {
    std::uint64_t m = r[w];
    if (w == w0) m &= ~std::uint64_t{0} << static_cast<unsigned>(x0 & 63);
    if (w == w1) m &= ~std::uint64_t{0} >> static_cast<unsigned>(63 - (x1 & 63));
    if (m != 0) return w * 64 + __builtin_ctzll(m);
  }
  return -1;
}

int BitImage::last_set(int j, int x0, int x1) const {
  const std::uint64_t* r = row(j);
  const int w0 = x0 >> 6, w1 = x1 >> 6;
  for (int w = w1; w >= w0; --w) {
    std::uint64_t m = r[w];
    if (w == w0) m &= ~std::uint64_t{0} << static_cast<unsigned>(x0 & 63);
    if (w == w1) m &= ~std::uint64_t{0} >> static_cast<unsigned>(63 - (x1 & 63));
    if (m != 0) return w * 64 + 63 - __builtin_clzll(m);
  }
  return -1;
}

void BitImage::set_byte(int j, int k, unsigned byte) {
  std::uint64_t& w = row(j)[static_cast<std::size_t>(k) >> 3];
  const unsigned shift = (static_cast<unsigned>(k) & 7u) * 8u;
  w = (w & ~(std::uint64_t{0xff} << shift)) | (static_cast<std::uint64_t>(byte & 0xffu) << shift);
}

void update_block_occupancy(BitImage& blocks, const BitImage& img, int b, int w0, int w1) {
  const int j0 = b << kBlockShift, j1 = std::min(img.height() - 1, j0 + (1 << kBlockShift) - 1);
  for (int w = w0; w <= w1; ++w) {
    std::uint64_t any = 0;
    for (int j = j0; j <= j1; ++j)
      any |= img.word(j, w);
    // One bit per byte (each byte is one block's columns), gathered into the top byte by
    // a multiply whose partial products never collide.
    any |= any >> 4;
    any |= any >> 2;
    any |= any >> 1;
    any &= 0x0101010101010101ull;
    blocks.set_byte(b, w, static_cast<unsigned>((any * 0x0102040810204080ull) >> 56));
  }
}

BitImage block_occupancy(const BitImage& img) {
  static_assert(kBlockShift == 3, "a block's columns are one byte of a row word");
  BitImage blocks(img.words_per_row() * 8, (img.height() + 7) >> kBlockShift);
  for (int b = 0; b < blocks.height(); ++b)
    update_block_occupancy(blocks, img, b, 0, img.words_per_row() - 1);
  return blocks;
}

BitImage rasterize(const PolygonSet& region, const Grid& grid) {
  BitImage img(grid.width, grid.height);
  std::vector<double> xs;
  for (int j = 0; j < grid.height; ++j) {
    const double y = grid.origin.y + j * grid.h;
    xs.clear();
    for (const Ring& r : region.rings)
      for (std::size_t k = 0, n = r.size(); k < n; ++k) {
        const Vec2 a = r[k], b = r[(k + 1) % n];
        if ((a.y > y) != (b.y > y)) xs.push_back(a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y));
      }
    std::sort(xs.begin(), xs.end());
    for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
      const int i0 = std::max(0, static_cast<int>(std::ceil((xs[k] - grid.origin.x) / grid.h)));
      const int i1 = std::min(grid.width - 1,
                              static_cast<int>(std::floor((xs[k + 1] - grid.origin.x) / grid.h)));
      for (int i = i0; i <= i1; ++i)
        img.set(i, j, true);
    }
  }
  return img;
}

PixelStock::PixelStock(Grid grid, BitImage material, BitImage forbidden, double tool_radius_mm,
                       const std::vector<float>* clearance_sq)
    : grid_(grid),
      material_(std::move(material)),
      forbidden_(std::move(forbidden)),
      material_blocks_(block_occupancy(material_)),
      forbidden_blocks_(block_occupancy(forbidden_)),
      radius_px_(tool_radius_mm / grid.h),
      clearance_sq_(clearance_sq) {
  reach_ = static_cast<int>(std::ceil(radius_px_)) + 1;
  rows_ = 2 * reach_ + 2;
  half_.assign(static_cast<std::size_t>(kSub) * rows_, -1.0);
  for (int f = 0; f < kSub; ++f)
    for (int o = 0; o < rows_; ++o) {
      const double dy = (o - reach_) - static_cast<double>(f) / kSub;
      const double q = radius_px_ * radius_px_ - dy * dy;
      half_[static_cast<std::size_t>(f) * rows_ + o] = q >= 0.0 ? std::sqrt(q) : -1.0;
    }
  // The rows a disk has are consecutive: from the first to the last with a half width.
  first_row_.assign(kSub, rows_);
  last_row_.assign(kSub, -1);
  for (int f = 0; f < kSub; ++f)
    for (int o = 0; o < rows_; ++o)
      if (half_[static_cast<std::size_t>(f) * rows_ + o] >= 0.0) {
        first_row_[static_cast<std::size_t>(f)] =
            std::min(first_row_[static_cast<std::size_t>(f)], o);
        last_row_[static_cast<std::size_t>(f)] = o;
      }
}

// Calls fn(j, x0, x1) for each row piece of disk(to) \ disk(from) (pixel centres, radius
// radius_px_) that meets an occupied block of `blocks`, clipped to the occupied blocks'
// columns of its band. Returns false when the disk leaves the image (counts as a gouge:
// the image border is far outside the pocket).
template <class RowFn>
[[gnu::always_inline]] inline bool PixelStock::crescent_rows(Vec2 from, Vec2 to,
                                                             const BitImage& blocks,
                                                             RowFn&& fn) const {
  // Centres' y snapped to 1/kSub pixel so that row half widths come from the table.
  const Vec2 a = grid_.to_px(from), b = grid_.to_px(to);
  const double r = radius_px_;
  if (b.y - r < 0 || b.y + r > grid_.height - 1 || b.x - r < 0 || b.x + r > grid_.width - 1)
    return false;
  const double by_floor = std::floor(b.y);
  const int bY = static_cast<int>(by_floor);
  const int bf = std::min(kSub - 1, static_cast<int>((b.y - by_floor) * kSub));
  const double* hb = half_.data() + static_cast<std::size_t>(bf) * rows_;
  const double ay_floor = std::floor(a.y);
  const bool a_near = std::abs(a.y - b.y) < 2.0 * r + 2.0;
  const int aY = a_near ? static_cast<int>(ay_floor) : 0;
  const int af = a_near ? std::min(kSub - 1, static_cast<int>((a.y - ay_floor) * kSub)) : 0;
  const double* ha = half_.data() + static_cast<std::size_t>(af) * rows_;
  // The band (8 rows) of the current row, and the columns of its occupied blocks that
  // disk(to) can reach: the first and last occupied block under the band's widest row.
  // Written once for a crescent and once for a whole disk (from far away: the probes of
  // the move chooser, the gouge tests, stamps), which needs no work for disk(from).
  auto rows = [&](auto crescent) SWARF_INLINE {
    int band = -1, cx0 = 0, cx1 = -1;
    const int o_last = last_row_[static_cast<std::size_t>(bf)];
    for (int o = first_row_[static_cast<std::size_t>(bf)]; o <= o_last; ++o) {
      const double half = hb[o];
      const int j = bY + o - reach_;
      if ((j >> kBlockShift) != band) {
        band = j >> kBlockShift;
        const int o_end = std::min(rows_ - 1, o + ((1 << kBlockShift) - 1 - (j & 7)));
        // The band's widest row is the one nearest the centre, which lies between rows
        // reach_ and reach_ + 1 (row o has dy = o - reach_ - bf / kSub).
        const double widest =
            std::max(hb[std::clamp(reach_, o, o_end)], hb[std::clamp(reach_ + 1, o, o_end)]);
        const int w0 = static_cast<int>(std::ceil(b.x - widest)),
                  w1 = static_cast<int>(std::floor(b.x + widest));
        const int k0 = w0 > w1 ? -1 : blocks.first_set(band, w0 >> kBlockShift, w1 >> kBlockShift);
        if (k0 < 0) {  // nothing in this band's reach: skip its rows
          o = o_end;
          continue;
        }
        cx0 = std::max(w0, k0 << kBlockShift);
        cx1 = std::min(w1, (blocks.last_set(band, k0, w1 >> kBlockShift) << kBlockShift) +
                               (1 << kBlockShift) - 1);
      }
      const int x0 = std::max(cx0, static_cast<int>(std::ceil(b.x - half))),
                x1 = std::min(cx1, static_cast<int>(std::floor(b.x + half)));
      if (x0 > x1) continue;
      if constexpr (!decltype(crescent)::value) {
        if (!fn(j, x0, x1)) return;
      } else {
        const int oa = j - aY + reach_;
        const double hA = (oa >= 0 && oa < rows_) ? ha[oa] : -1.0;
        const int a0 = static_cast<int>(std::ceil(a.x - hA)),
                  a1 = static_cast<int>(std::floor(a.x + hA));
        if (hA < 0.0 || a0 > a1) {
          if (!fn(j, x0, x1)) return;
          continue;
        }
        if (x0 <= std::min(x1, a0 - 1) && !fn(j, x0, std::min(x1, a0 - 1))) return;
        if (std::max(x0, a1 + 1) <= x1 && !fn(j, std::max(x0, a1 + 1), x1)) return;
      }
    }
  };
  if (a_near)
    rows(std::true_type{});
  else
    rows(std::false_type{});
  return true;
}

template <bool kHw>
[[gnu::always_inline]] inline int PixelStock::probe_t(Vec2 from, Vec2 to, int enough) const {
  int n = 0;
  bool gouge = false;
  // Far from every forbidden pixel (nearest pixel's clearance minus the distance to it
  // exceeds the radius by a pixel): only material needs counting.
  double c = 0.0;
  if (clearance_px(to, c)) {
    // The nearest forbidden pixel lies within c +- 0.71 of `to`; 0.05 covers the 1/kSub
    // snapping of the row widths. Inside R: disk(to) holds it, disk(from) is free, so the
    // crescent does: a gouge, without scanning (boundary moves and the scans probe many
    // such moves).
    if (c + 0.71 < radius_px_ - 0.05) return kGouge;
    if (c - 0.71 > radius_px_ + 1.0) {
      // No gouge is possible here, so the count may stop early.
      crescent_rows(from, to, material_blocks_, [&](int jj, int x0, int x1) SWARF_INLINE {
        n += material_.count<kHw>(jj, x0, x1);
        return n <= enough;
      });
      return n;
    }
  }
  const bool inside =
      crescent_rows(from, to, forbidden_blocks_, [&](int j, int x0, int x1) SWARF_INLINE {
        gouge = forbidden_.count<kHw>(j, x0, x1) > 0;
        return !gouge;
      });
  if (!inside || gouge) return kGouge;
  crescent_rows(from, to, material_blocks_, [&](int j, int x0, int x1) SWARF_INLINE {
    n += material_.count<kHw>(j, x0, x1);
    return true;
  });
  return n;
}

template <bool kHw, class RowVisit>
[[gnu::always_inline]] inline int PixelStock::cut_t(Vec2 from, Vec2 to, RowVisit&& visit) {
  int n = 0;
  // The blocks of each band the cut cleared pixels in are recomputed once the cut has left
  // that band (rows come in increasing order): word columns w0 to w1 of band `band`.
  int band = -1, w0 = 0, w1 = -1;
  auto flush = [&] {
    if (w0 <= w1) update_block_occupancy(material_blocks_, material_, band, w0, w1);
  };
  crescent_rows(from, to, material_blocks_, [&](int j, int x0, int x1) SWARF_INLINE {
    visit(j, x0, x1);
    const int cleared = material_.clear<kHw>(j, x0, x1);
    if (cleared == 0) return true;
    n += cleared;
    if ((j >> kBlockShift) != band) {
      flush();
      band = j >> kBlockShift;
      w0 = x0 >> 6;
      w1 = x1 >> 6;
    } else {
      w0 = std::min(w0, x0 >> 6);
      w1 = std::max(w1, x1 >> 6);
    }
    return true;
  });
  flush();
  return n;
}

namespace {
// A point far enough away that its disk misses every row: turns the crescent into a disk.
Vec2 far_away(Vec2 c, double r_mm) {
  return c + Vec2{0.0, 1e6 + 4.0 * r_mm};
}
}  // namespace

template <bool kHw>
[[gnu::always_inline]] inline bool PixelStock::gouges_t(Vec2 centre) const {
  bool gouge = false;
  const bool inside = crescent_rows(far_away(centre, tool_radius_mm()), centre, forbidden_blocks_,
                                    [&](int j, int x0, int x1) SWARF_INLINE {
                                      gouge = forbidden_.count<kHw>(j, x0, x1) > 0;
                                      return !gouge;
                                    });
  return gouge || !inside;
}

template <bool kHw>
[[gnu::always_inline]] inline int PixelStock::material_in_disk_t(Vec2 centre, double radius_mm,
                                                                 int enough) const {
  const Vec2 c = grid_.to_px(centre);
  const double r = radius_mm / grid_.h;
  int n = 0;
  const int j0 = std::max(0, static_cast<int>(std::ceil(c.y - r)));
  const int j1 = std::min(grid_.height - 1, static_cast<int>(std::floor(c.y + r)));
  // Columns the disk can reach, clipped per band (8 rows) to its occupied blocks.
  const int dx0 = std::max(0, static_cast<int>(std::ceil(c.x - r)));
  const int dx1 = std::min(grid_.width - 1, static_cast<int>(std::floor(c.x + r)));
  if (dx0 > dx1) return 0;
  int band = -1, cx0 = 0, cx1 = -1;
  for (int j = j0; j <= j1; ++j) {
    if ((j >> kBlockShift) != band) {
      band = j >> kBlockShift;
      const int k0 = material_blocks_.first_set(band, dx0 >> kBlockShift, dx1 >> kBlockShift);
      if (k0 < 0) {  // nothing in this band's reach: skip its rows
        j = (band << kBlockShift) + (1 << kBlockShift) - 1;
        continue;
      }
      cx0 = std::max(dx0, k0 << kBlockShift);
      cx1 = std::min(dx1, (material_blocks_.last_set(band, k0, dx1 >> kBlockShift) << kBlockShift) +
                              (1 << kBlockShift) - 1);
    }
    const double dy = j - c.y;
    const double half = std::sqrt(std::max(0.0, r * r - dy * dy));
    const int x0 = std::max(cx0, static_cast<int>(std::ceil(c.x - half)));
    const int x1 = std::min(cx1, static_cast<int>(std::floor(c.x + half)));
    if (x0 <= x1) n += material_.count<kHw>(j, x0, x1);
    if (n > enough) break;
  }
  return n;
}

SWARF_TARGET_HW int PixelStock::probe_hw(Vec2 from, Vec2 to, int enough) const {
  return probe_t<true>(from, to, enough);
}
namespace {
// The row visitors of cut and cut_tagging: through the caller's pointer per pixel, or a tag
// written into a map.
struct CallPerPixel {
  const BitImage& material;
  CutVisitor visit;
  void* user;
  SWARF_INLINE void operator()(int j, int x0, int x1) const {
    if (visit != nullptr) material.for_each_set(j, x0, x1, [&](int i) { visit(user, i, j); });
  }
};
struct Tag {
  const BitImage& material;
  std::uint32_t* cells;
  int width;
  std::uint32_t tag;
  SWARF_INLINE void operator()(int j, int x0, int x1) const {
    std::uint32_t* row = cells + static_cast<std::size_t>(j) * static_cast<std::size_t>(width);
    material.for_each_set(j, x0, x1, [&](int i) { row[i] = tag; });
  }
};
}  // namespace

SWARF_TARGET_HW int PixelStock::cut_hw(Vec2 from, Vec2 to, CutVisitor visit, void* user) {
  return cut_t<true>(from, to, CallPerPixel{material_, visit, user});
}
SWARF_TARGET_HW int PixelStock::cut_tagging_hw(Vec2 from, Vec2 to, std::uint32_t* cells, int width,
                                               std::uint32_t tag) {
  return cut_t<true>(from, to, Tag{material_, cells, width, tag});
}
SWARF_TARGET_HW bool PixelStock::gouges_hw(Vec2 centre) const {
  return gouges_t<true>(centre);
}
SWARF_TARGET_HW int PixelStock::material_in_disk_hw(Vec2 centre, double radius_mm,
                                                    int enough) const {
  return material_in_disk_t<true>(centre, radius_mm, enough);
}

int PixelStock::probe(Vec2 from, Vec2 to, int enough) const {
#ifdef SWARF_POCKET_DISPATCH
  if (cpu_has_hw()) return probe_hw(from, to, enough);
#endif
  return probe_t<false>(from, to, enough);
}
void PixelStock::allow_cpu_features(bool allow) {
#ifdef SWARF_POCKET_DISPATCH
  g_allow_hw.store(allow, std::memory_order_relaxed);
#else
  (void)allow;
#endif
}

int PixelStock::probe_disk(Vec2 to, int enough) const {
  return probe(far_away(to, tool_radius_mm()), to, enough);
}
int PixelStock::cut(Vec2 from, Vec2 to, CutVisitor visit, void* user) {
#ifdef SWARF_POCKET_DISPATCH
  if (cpu_has_hw()) return cut_hw(from, to, visit, user);
#endif
  return cut_t<false>(from, to, CallPerPixel{material_, visit, user});
}
int PixelStock::cut_tagging(Vec2 from, Vec2 to, std::uint32_t* cells, int width,
                            std::uint32_t tag) {
#ifdef SWARF_POCKET_DISPATCH
  if (cpu_has_hw()) return cut_tagging_hw(from, to, cells, width, tag);
#endif
  return cut_t<false>(from, to, Tag{material_, cells, width, tag});
}
bool PixelStock::gouges_scan(Vec2 centre) const {
#ifdef SWARF_POCKET_DISPATCH
  if (cpu_has_hw()) return gouges_hw(centre);
#endif
  return gouges_t<false>(centre);
}
int PixelStock::material_in_disk(Vec2 centre, double radius_mm, int enough) const {
#ifdef SWARF_POCKET_DISPATCH
  if (cpu_has_hw()) return material_in_disk_hw(centre, radius_mm, enough);
#endif
  return material_in_disk_t<false>(centre, radius_mm, enough);
}

int PixelStock::stamp(Vec2 centre, CutVisitor visit, void* user) {
  return cut(far_away(centre, tool_radius_mm()), centre, visit, user);
}

}  // namespace swarf::pocket
