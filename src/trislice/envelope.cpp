// Eq. (1) evaluated on a scan line without polygon unions: see envelope.h for the argument.
#include "swarf/trislice/envelope.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>

#include "swarf/core/grid_walk.h"
#include "swarf/core/parallel.h"

namespace swarf {
#ifdef SWARF_ENV_COUNT
std::atomic<long> g_blocks{0}, g_bins{0}, g_segs{0};
#endif
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

SliceEnvelope SliceEnvelope::build(const SliceFamily& family, double bin_mm, int stride) {
  SliceEnvelope e;
  e.axis_ = family.axis;
  e.first_ = family.first_level;
  e.pitch_ = family.pitch_mm;
  // The slices read, by reference (a strided envelope for roughing used to copy them).
  std::vector<const PolygonSet*> slices;
  if (stride > 1) {
    // Keep the slices on the coarser lattice (level index divisible by stride), so coarse
    // and fine envelopes of one model share their slices.
    e.pitch_ = family.pitch_mm * stride;
    e.first_ = SliceFamily{}.first_level;
    const long base = std::lround(family.first_level / family.pitch_mm);
    for (std::size_t j = 0; j < family.size(); ++j) {
      const long k = base + static_cast<long>(j);
      if (((k % stride) + stride) % stride != 0) continue;
      if (slices.empty()) e.first_ = family.level(j);
      slices.push_back(&family.slices[j]);
    }
  } else {
    for (const PolygonSet& set : family.slices)
      slices.push_back(&set);
  }
  e.n_ = slices.size();
  e.bin_ = bin_mm > 0.0 ? bin_mm : 1.0;
  // Upward-facing edges of every slice, as (s, z) segments. Rings are normalized (outers
  // counter-clockwise, holes clockwise in the plane's (u, v)), so the outward normal of an
  // edge (du, dv) is (dv, -du) and its z component says whether the edge faces up. An edge
  // facing down can never be the first contact of a disc coming from above (the disc would
  // have to cross the solid to reach it). The edges are walked three times (extent, count,
  // fill) rather than gathered in a temporary array: that array (or one per slice) cost more
  // in fresh pages than the walks cost.
  auto up_edges = [&](auto&& fn) {  // fn(slice, segment with s0 <= s1, normal not set)
    for (std::size_t j = 0; j < e.n_; ++j) {
      for (const Ring& ring : slices[j]->rings) {
        for (std::size_t k = 0; k < ring.size(); ++k) {
          const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
          const double du = b.x - a.x, dv = b.y - a.y;
          double nz = 0.0;
          Seg s{};
          if (family.axis == Axis::kX) {  // (u, v) = (y, z)
            nz = -du;
            s = {a.x, a.y, b.x, b.y, 0.0, 0.0};
          } else {  // kY: (u, v) = (z, x)
            nz = dv;
            s = {a.y, a.x, b.y, b.x, 0.0, 0.0};
          }
          // nz < -1e-12 |(du, dv)|, squared: hypot is slow and this runs for every edge.
          if (nz < 0.0 && nz * nz > 1e-24 * (du * du + dv * dv)) continue;
          if (s.s0 > s.s1) s = {s.s1, s.z1, s.s0, s.z0, 0, 0};
          fn(j, s);
        }
      }
    }
  };
  double smin = kInf, smax = -kInf;
  e.nseg_ = 0;
  up_edges([&](std::size_t, const Seg& s) {
    smin = std::min(smin, s.s0);
    smax = std::max(smax, s.s1);
    ++e.nseg_;
  });
  if (smin > smax) {
    smin = 0.0;
    smax = 0.0;
  }
  e.smin_ = smin;
  e.nb_ = static_cast<int>(std::floor((smax - smin) / e.bin_)) + 1;
  const std::size_t nb = static_cast<std::size_t>(e.nb_);
  // Cells are stored bin-major (cell of slice j, bin b = b * n + j): a query walks one bin
  // over consecutive slices, and the secondary family's scan lines slide along the slices
  // of fixed bins, so their cells, upper lines and segments lie in one run of memory.
  const auto cell_of = [n = e.n_](std::size_t j, std::size_t b) { return b * n + j; };
  e.start_.assign(e.n_ * nb + 1, 0);
  std::vector<double> binmax(e.n_ * nb, -kInf);
  auto bin_of = [&](double s) {
    return std::clamp(static_cast<int>(std::floor((s - e.smin_) / e.bin_)), 0, e.nb_ - 1);
  };
  // Count, then fill (CSR). A segment is copied into every bin it spans, so a query reads
  // the segments of a bin, and of consecutive bins of a slice, from one run of memory.
  up_edges([&](std::size_t j, const Seg& s) {
    for (int b = bin_of(s.s0), b1 = bin_of(s.s1); b <= b1; ++b)
      ++e.start_[cell_of(j, static_cast<std::size_t>(b)) + 1];
  });
  for (std::size_t c = 0; c < e.n_ * nb; ++c)
    e.start_[c + 1] += e.start_[c];
  e.seg_.resize(e.start_.back());
  e.slice_of_.resize(e.start_.back());
  std::vector<std::uint32_t> fill(e.start_.begin(), e.start_.end() - 1);
  up_edges([&](std::size_t j, Seg s) {
    // Upward unit normal (ns, nz) = (-dz, ds) / len, and the slope for the interior test.
    const double ds_ = s.s1 - s.s0, dz_ = s.z1 - s.z0, len = std::hypot(ds_, dz_);
    if (ds_ > 1e-12 && len > 0.0) {
      s.ns = -dz_ / len;
      s.nz = ds_ / len;
    }  // else vertical (nz stays 0): only its end points can be touched
    for (int b = bin_of(s.s0), b1 = bin_of(s.s1); b <= b1; ++b) {
      const std::size_t c = cell_of(j, static_cast<std::size_t>(b));
      e.seg_[fill[c]] = s;
      e.slice_of_[fill[c]++] = static_cast<std::uint32_t>(j);
      binmax[c] = std::max({binmax[c], s.z0, s.z1});
    }
  });
  // Upper lines per (slice, bin): the slope of the highest edges across the bin, raised until
  // every edge end inside the bin (clipped to it) lies under the line. Edges are straight, so
  // their ends bound them.
  e.line_.assign(e.n_ * nb, Line{-kInf, 0.0, 0.0, -kInf});
  for (std::size_t c = 0; c < e.n_ * nb; ++c) {
    if (e.start_[c] == e.start_[c + 1]) continue;
    const double lo = e.smin_ + e.bin_ * static_cast<double>(c / e.n_), hi = lo + e.bin_;
    const double mid = lo + 0.5 * e.bin_;
    double zl = -kInf, zh = -kInf;
    auto clip = [&](const Seg& g, double at) { return g.z0 - (at - g.s0) * g.ns / g.nz; };
    for (std::uint32_t k = e.start_[c]; k < e.start_[c + 1]; ++k) {
      const Seg& g = e.seg_[k];
      if (g.nz > 0.0 && g.s0 <= lo && g.s1 >= lo) zl = std::max(zl, clip(g, lo));
      if (g.nz > 0.0 && g.s0 <= hi && g.s1 >= hi) zh = std::max(zh, clip(g, hi));
    }
    const double b = zl > -kInf && zh > -kInf ? (zh - zl) / e.bin_ : 0.0;
    double a = -kInf;
    for (std::uint32_t k = e.start_[c]; k < e.start_[c + 1]; ++k) {
      const Seg& g = e.seg_[k];
      const double s0 = std::max(g.s0, lo), s1 = std::min(g.s1, hi);
      const double z0 = g.nz > 0.0 && g.s0 < lo ? clip(g, lo) : g.z0;
      const double z1 = g.nz > 0.0 && g.s1 > hi ? clip(g, hi) : g.z1;
      a = std::max({a, z0 - b * (s0 - mid), z1 - b * (s1 - mid)});
    }
    e.line_[c] = {a, b, b / std::sqrt(1.0 + b * b), binmax[c]};
  }
  // Coarse bins (kCoarse fine bins) per block of kBlock slices and per super-block of
  // kBlock^2 slices: a query rejects far slices wholesale with few checks.
  e.nbc_ = (e.nb_ + kCoarse - 1) / kCoarse;
  const std::size_t nbc = static_cast<std::size_t>(e.nbc_);
  const std::size_t nblock = (e.n_ + kBlock - 1) / kBlock;
  const std::size_t nsuper = (nblock + kBlock - 1) / kBlock;
  std::vector<double> blockmax(nblock * nbc, -kInf);
  e.supermax_.assign(nsuper * nbc, -kInf);
  for (std::size_t j = 0; j < e.n_; ++j)
    for (std::size_t b = 0; b < nb; ++b) {
      const double v = binmax[cell_of(j, b)];
      double& m = blockmax[(j / kBlock) * nbc + b / kCoarse];
      m = std::max(m, v);
      double& sm = e.supermax_[(j / kBlock / kBlock) * nbc + b / kCoarse];
      sm = std::max(sm, v);
    }
  // Block lines per (block, bin): one slope for the block (that of its highest line ends),
  // raised over every slice's line: a_j + b_j t <= a + b t + |b_j - b| w / 2 on the bin.
  e.blockline_.assign(nblock * nb, Line{-kInf, 0.0, 0.0, -kInf});
  for (std::size_t blk = 0; blk < nblock; ++blk)
    for (std::size_t b = 0; b < nb; ++b) {
      double zl = -kInf, zh = -kInf;
      const std::size_t j1 = std::min(e.n_, (blk + 1) * kBlock);
      for (std::size_t j = blk * kBlock; j < j1; ++j) {
        const Line& L = e.line_[cell_of(j, b)];
        zl = std::max(zl, L.a - 0.5 * e.bin_ * L.b);
        zh = std::max(zh, L.a + 0.5 * e.bin_ * L.b);
      }
      e.blockline_[blk * nb + b].top = blockmax[blk * nbc + b / kCoarse];
      if (!(zl > -kInf)) continue;
      const double slope = (zh - zl) / e.bin_;
      double a = -kInf;
      for (std::size_t j = blk * kBlock; j < j1; ++j) {
        const Line& L = e.line_[cell_of(j, b)];
        if (L.a > -kInf) a = std::max(a, L.a + std::fabs(L.b - slope) * 0.5 * e.bin_);
      }
      e.blockline_[blk * nb + b] = {a, slope, slope / std::sqrt(1.0 + slope * slope),
                                    blockmax[blk * nbc + b / kCoarse]};
    }
  return e;
}

double SliceEnvelope::drop_on(const Seg& g, double s, double rho, double rho2) {
  double c = -kInf;
  const double d0 = s - g.s0, d1 = s - g.s1;
  if (std::fabs(d0) <= rho) c = g.z0 + std::sqrt(rho2 - d0 * d0);
  if (std::fabs(d1) <= rho) c = std::max(c, g.z1 + std::sqrt(rho2 - d1 * d1));
  if (g.nz > 0.0) {
    const double qs = s - rho * g.ns;
    if (qs >= g.s0 && qs <= g.s1) c = std::max(c, g.z0 - (qs - g.s0) * g.ns / g.nz + rho * g.nz);
  }
  return c;
}

double SliceEnvelope::hint_height(Vec2 p, double r, std::uint32_t hint) const {
  if (hint >= seg_.size()) return -kInf;
  const double q = axis_ == Axis::kX ? p.x : p.y, s = axis_ == Axis::kX ? p.y : p.x;
  const double dq = q - (first_ + static_cast<double>(slice_of_[hint]) * pitch_);
  const double rho2 = r * r - dq * dq;
  return rho2 >= 0.0 ? drop_on(seg_[hint], s, std::sqrt(rho2), rho2) : -kInf;
}

std::size_t SliceEnvelope::memory_bytes() const {
  return seg_.size() * (sizeof(Seg) + sizeof(std::uint32_t)) +
         start_.size() * sizeof(std::uint32_t) + supermax_.size() * sizeof(double) +
         (line_.size() + blockline_.size()) * sizeof(Line);
}

double SliceEnvelope::centre_height(Vec2 p, double r, double best, std::uint32_t* hint) const {
  if (n_ == 0 || !(r > 0.0)) return best;
  const double q = axis_ == Axis::kX ? p.x : p.y;  // across the slices
  const double s = axis_ == Axis::kX ? p.y : p.x;  // along them
  const long n = static_cast<long>(n_);
  const long jlo = std::max(0L, static_cast<long>(std::ceil((q - r - first_) / pitch_ - 1e-9)));
  const long jhi = std::min(n - 1, static_cast<long>(std::floor((q + r - first_) / pitch_ + 1e-9)));
  if (jlo > jhi) return best;
  const long jc = std::clamp(std::lround((q - first_) / pitch_), jlo, jhi);
  const long B = static_cast<long>(kBlock);
  const std::size_t nb = static_cast<std::size_t>(nb_);
  const std::size_t nbc = static_cast<std::size_t>(nbc_);
  const double smax = smin_ + bin_ * nb_;
  auto level = [&](long j) { return first_ + static_cast<double>(j) * pitch_; };
  std::uint32_t best_id = kNoHint;
  // A disc of radius rho dropped at s onto segment id: end points, then the interior (contact
  // where the upward normal points at the centre).
  auto drop = [&](std::uint32_t id, double rho, double rho2) {
    const double c = drop_on(seg_[id], s, rho, rho2);
    if (c > best) {
      best = c;
      best_id = id;
    }
  };
  // Scan-line coherence: the segment that held the previous point up usually holds this one
  // up too (or nearly); starting from its height lets the bounds below prune from the start.
  if (hint != nullptr && *hint < seg_.size()) {
    const double dq = q - level(static_cast<long>(slice_of_[*hint]));
    const double rho2 = r * r - dq * dq;
    if (rho2 >= 0.0) drop(*hint, std::sqrt(rho2), rho2);
  }
  // The bins the ball can reach at all, with what every bound test needs of them (relative
  // to s: tlo, thi the bin's ends, dx2 the squared distance to it, off s from the bin's
  // centre where the upper lines are anchored). Worked out once per query, not per block and
  // slice. kCoarse == 1: the blocks' bins are the fine bins.
  static_assert(kCoarse == 1);
  if (s + r < smin_ || s - r > smax) return best;
  const int qb0 = std::clamp(static_cast<int>(std::floor((s - r - smin_) / bin_)), 0, nb_ - 1);
  const int qb1 = std::clamp(static_cast<int>(std::floor((s + r - smin_) / bin_)), 0, nb_ - 1);
  const int nq = qb1 - qb0 + 1;
  struct BinAt {
    double tlo, thi, dx2, off;
  };
  thread_local std::vector<BinAt> at_buf;
  thread_local std::vector<int> pass_buf, ord_buf;
  if (at_buf.size() < static_cast<std::size_t>(nq)) {
    at_buf.resize(static_cast<std::size_t>(nq));
    pass_buf.resize(static_cast<std::size_t>(nq));
    ord_buf.resize(static_cast<std::size_t>(nq));
  }
  BinAt* const at = at_buf.data();
  int* const pass = pass_buf.data();
  for (int m = 0; m < nq; ++m) {
    const double lo = smin_ + bin_ * (qb0 + m);
    const double tlo = lo - s, thi = tlo + bin_, dx = std::max({tlo, 0.0, -thi});
    at[m] = {tlo, thi, dx * dx, s - (lo + 0.5 * bin_)};
  }
  // The bins nearest to s first (dx2 falls towards s and rises past it, so a merge from the
  // bin holding s): a block's bins within its reach are then a prefix of this order, and the
  // scan over them stops at the first bin out of reach instead of testing every bin.
  int* const ord = ord_buf.data();
  {
    int lo = std::clamp(static_cast<int>(std::floor((s - smin_) / bin_)) - qb0, 0, nq - 1);
    int hi = lo + 1;
    for (int o = 0; o < nq; ++o)
      ord[o] = hi >= nq || (lo >= 0 && at[lo].dx2 <= at[hi].dx2) ? lo-- : hi++;
  }
  // Slices [j0, j1] and the squared reach of the disc on the nearest of them.
  auto reach2 = [&](long j0, long j1) {
    const double l0 = level(j0), l1 = level(j1);
    const double dmin = (q >= l0 && q <= l1) ? 0.0 : std::min(std::fabs(q - l0), std::fabs(q - l1));
    return std::max(0.0, r * r - dmin * dmin);
  };
  auto visit_block = [&](long blk) {
    long j0 = std::max(jlo, blk * B), j1 = std::min(jhi, blk * B + B - 1);
    if (j0 > j1) return;
    const double rm2 = reach2(j0, j1), rm = std::sqrt(rm2);
    // Bins of this block that can still beat the best centre (its highest z per bin, then
    // its upper line per bin, with the reach of its nearest slice); only those are opened.
    // thr: the least squared radius a slice needs to beat best over any of them.
    int npass = 0;
    double thr = kInf;
    const std::size_t brow = static_cast<std::size_t>(blk) * nb + static_cast<std::size_t>(qb0);
    for (int o = 0; o < nq; ++o) {
      const int m = ord[o];
      const BinAt& a = at[m];
      const double room = rm2 - a.dx2;
      if (room < 0.0) break;  // and so are the bins after it in this order
      const Line& L = blockline_[brow + static_cast<std::size_t>(m)];
      const double need = best - L.top;
      if (need >= 0.0 && room <= need * need) continue;
      const double a0 = std::max(a.tlo, -rm), a1 = std::min(a.thi, rm);
      if (a0 > a1) continue;
      const double tp = std::clamp(L.k * rm, a0, a1);
      const double need_line = best - (L.a + L.b * (tp + a.off));
      if (need_line >= 0.0 && rm2 - tp * tp <= need_line * need_line) continue;
      pass[npass++] = m;
      thr = std::min(thr, a.dx2 + (need > 0.0 ? need * need : 0.0));
    }
    if (npass == 0) return;
    // A slice beats best over bin m only if rho^2 >= dx2 + (best - block max)^2, so only the
    // slices within sqrt(r^2 - thr) of q can (best only grows while the block is visited, so
    // the range stays a superset). The slices of a block far from q mostly fall outside.
    const double span2 = r * r - thr;
    if (span2 < 0.0) return;
    const double span = std::sqrt(span2);
    j0 = std::max(j0, static_cast<long>(std::ceil((q - span - first_) / pitch_ - 1e-9)));
    j1 = std::min(j1, static_cast<long>(std::floor((q + span - first_) / pitch_ + 1e-9)));
    if (j0 > j1) return;
    // Squared disc radius per slice (seed 001 Eq. (1), with (i - j) ds -> y - y_j); the root
    // only once a cell of the slice passes its box test. Bins outer, slices inner: a block
    // passes one to three bins, so the inner loop runs long and its exit is predictable.
    double rho2s[kBlock], rhos[kBlock];
    for (long j = j0; j <= j1; ++j) {
      const double dq = q - level(j);
      rho2s[j - j0] = r * r - dq * dq;
      rhos[j - j0] = -1.0;
    }
    for (int pm = 0; pm < npass; ++pm) {
      const int m = pass[pm];
      const BinAt& a = at[m];
      for (long j = j0; j <= j1; ++j) {
        const double rho2 = rho2s[j - j0];
        const std::size_t cell =
            static_cast<std::size_t>(qb0 + m) * n_ + static_cast<std::size_t>(j);
        // The bin's box (as can_beat), then its upper line (as line_can_beat).
        const double room = rho2 - a.dx2;
        if (room < 0.0) continue;  // also rho2 < 0: the slice is out of reach
        const Line& L = line_[cell];
        const double need_box = best - L.top;
        if (need_box >= 0.0 && room <= need_box * need_box) continue;
        double& rho = rhos[j - j0];
        if (rho < 0.0) rho = std::sqrt(rho2);
        const double a0 = std::max(a.tlo, -rho), a1 = std::min(a.thi, rho);
        if (a0 > a1) continue;
        const double tp = std::clamp(L.k * rho, a0, a1);
        const double need_line = best - (L.a + L.b * (tp + a.off));
        if (need_line >= 0.0 && rho2 - tp * tp <= need_line * need_line) continue;
        for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
          // The segment's box first: no point of it rises above top, nor lies nearer than dx
          // along the line, so the disc cannot sit higher than top + sqrt(rho2 - dx^2).
          const Seg& g = seg_[k];
          const double need = best - std::max(g.z0, g.z1);
          if (need >= 0.0) {
            const double dx = std::max({g.s0 - s, 0.0, s - g.s1});
            if (rho2 - dx * dx <= need * need) continue;
          }
          // Then the segment's line: a disc centred at height best whose signed distance
          // from the line is at least rho sits on or above the tangent position, the highest
          // the disc can rest on any point of the segment (end points included). Three
          // products instead of drop_on's roots and division; the margin of 1e-9 mm keeps
          // the test on the safe side of rounding, so the answer does not change.
          if (g.nz > 0.0 && (best - g.z0) * g.nz + (s - g.s0) * g.ns >= rho + 1e-9) continue;
          drop(k, rho, rho2);
        }
      }
    }
  };
  const long SB = B * B;
  auto visit_super = [&](long sup) {
    const long j0 = std::max(jlo, sup * SB), j1 = std::min(jhi, sup * SB + SB - 1);
    if (j0 > j1) return;
    const double rm2 = reach2(j0, j1);
    bool any = false;
    const std::size_t srow = static_cast<std::size_t>(sup) * nbc + static_cast<std::size_t>(qb0);
    for (int o = 0; o < nq && !any; ++o) {
      const int m = ord[o];
      const double room = rm2 - at[m].dx2;
      if (room < 0.0) break;
      const double need = best - supermax_[srow + static_cast<std::size_t>(m)];
      any = room >= 0.0 && (need < 0.0 || room > need * need);
    }
    if (!any) return;
    // Blocks of this super-block, nearest to q first.
    const long b_lo = j0 / B, b_hi = j1 / B;
    const long b_c = std::clamp(jc / B, b_lo, b_hi);
    visit_block(b_c);
    for (long k = 1; b_c - k >= b_lo || b_c + k <= b_hi; ++k) {
      if (b_c - k >= b_lo) visit_block(b_c - k);
      if (b_c + k <= b_hi) visit_block(b_c + k);
    }
  };
  const long sc = jc / SB, slo = jlo / SB, shi = jhi / SB;
  visit_super(sc);
  for (long k = 1; sc - k >= slo || sc + k <= shi; ++k) {
    if (sc - k >= slo) visit_super(sc - k);
    if (sc + k <= shi) visit_super(sc + k);
  }
  if (hint != nullptr && best_id != kNoHint) *hint = best_id;
  return best;
}

LevelEnvelope LevelEnvelope::build(const SliceFamily& fam, double cell_mm, int stride) {
  LevelEnvelope e;
  e.cell_ = cell_mm > 0.0 ? cell_mm : 1.0;
  const long base = fam.pitch_mm > 0.0 ? std::lround(fam.first_level / fam.pitch_mm) : 0;
  // The levels read (every stride-th on the coarser lattice), in ascending order.
  std::vector<std::size_t> kept;
  for (std::size_t j = 0; j < fam.size(); ++j) {
    const long k = base + static_cast<long>(j);
    if (stride > 1 && ((k % stride) + stride) % stride != 0) continue;
    kept.push_back(j);
  }
  // Ring edges (start a, end b) of the kept levels, highest level first, each ring in its
  // order: fn(a, b, z). Walked three times (extent, count, fill) instead of gathered in a
  // temporary list and sorted per cell: levels rise strictly with the index, so this order
  // is the order by level (descending) and then by position in the model that the sort gave.
  //
  // An edge that the level above also has (the same end points, in either direction) is left
  // out: at every distance from p its copy above holds the centre higher by the level
  // difference, so it can never decide a query. These are the rings of vertical walls, the
  // same edges on every level: on a plate's sides a query near the wall walked down a ball
  // radius of levels (80 at 0.05 mm with a ø8 ball) before the levels' bound stopped it.
  std::vector<char> dominated;
  {
    using Key = std::array<double, 4>;
    auto key = [](Vec2 a, Vec2 b) {
      return a.x < b.x || (a.x == b.x && a.y <= b.y) ? Key{a.x, a.y, b.x, b.y}
                                                     : Key{b.x, b.y, a.x, a.y};
    };
    std::vector<Key> above, here;
    for (std::size_t m = kept.size(); m-- > 0;) {
      here.clear();
      for (const Ring& ring : fam.slices[kept[m]].rings)
        for (std::size_t q = 0; q < ring.size(); ++q) {
          const Key k = key(ring[q], ring[(q + 1) % ring.size()]);
          dominated.push_back(std::binary_search(above.begin(), above.end(), k) ? 1 : 0);
          here.push_back(k);
        }
      std::sort(here.begin(), here.end());
      std::swap(above, here);
    }
  }
  auto edges = [&](auto&& fn) {
    std::size_t idx = 0;
    for (std::size_t m = kept.size(); m-- > 0;) {
      const std::size_t j = kept[m];
      const double z = fam.level(j);
      for (const Ring& ring : fam.slices[j].rings)
        for (std::size_t q = 0; q < ring.size(); ++q)
          if (!dominated[idx++]) fn(ring[q], ring[(q + 1) % ring.size()], z);
    }
  };
  Box2 box;
  e.nseg_ = 0;
  edges([&](Vec2 a, Vec2, double) {
    box.add(a);
    ++e.nseg_;
  });
  if (e.nseg_ == 0) return e;
  e.origin_ = box.min;
  e.nx_ = static_cast<int>(std::floor(box.size().x / e.cell_)) + 1;
  e.ny_ = static_cast<int>(std::floor(box.size().y / e.cell_)) + 1;
  const std::size_t ncell = static_cast<std::size_t>(e.nx_) * static_cast<std::size_t>(e.ny_);
  // The cells an edge crosses (grid_walk.h), not its bounding box: a long diagonal edge (the
  // side of a large chamfered or drafted part) would be listed in thousands of cells it
  // never comes near, on every level, and every query there would test it.
  const CellGrid grid{e.origin_, e.cell_, e.nx_, e.ny_};
  auto cells = [&](Vec2 a, Vec2 b, auto&& fn) { for_cells_on_segment(grid, a, b, fn); };
  e.start_.assign(ncell + 1, 0);
  edges([&](Vec2 a, Vec2 b, double) { cells(a, b, [&](std::size_t c) { ++e.start_[c + 1]; }); });
  for (std::size_t c = 0; c < ncell; ++c)
    e.start_[c + 1] += e.start_[c];
  // The segments in that order per cell, so a query reads a cell from one run of memory.
  // Direction stored as end - start: the same doubles the queries computed per edge before.
  e.seg_.resize(e.start_.back());
  std::vector<std::uint32_t> fill(e.start_.begin(), e.start_.end() - 1);
  edges([&](Vec2 a, Vec2 b, double z) {
    const Seg g{a.x, a.y, b.x - a.x, b.y - a.y, z};
    cells(a, b, [&](std::size_t c) { e.seg_[fill[c]++] = g; });
  });
  // The highest level of each cell in a small array of its own: most cells a query walks
  // are ruled out by it without touching their segments.
  e.cellmax_.assign(ncell, -kInf);
  for (std::size_t c = 0; c < ncell; ++c)
    if (e.start_[c] < e.start_[c + 1]) e.cellmax_[c] = e.seg_[e.start_[c]].z;
  // And per square of kSuper x kSuper cells, so a query rules out most of the area around a
  // flat stretch with a few tests.
  e.nsx_ = (e.nx_ + kSuper - 1) / kSuper;
  e.nsy_ = (e.ny_ + kSuper - 1) / kSuper;
  e.supermax_.assign(static_cast<std::size_t>(e.nsx_) * static_cast<std::size_t>(e.nsy_), -kInf);
  for (int j = 0; j < e.ny_; ++j)
    for (int i = 0; i < e.nx_; ++i) {
      double& m =
          e.supermax_[static_cast<std::size_t>(j / kSuper) * static_cast<std::size_t>(e.nsx_) +
                      static_cast<std::size_t>(i / kSuper)];
      m = std::max(m, e.cellmax_[static_cast<std::size_t>(j) * static_cast<std::size_t>(e.nx_) +
                                 static_cast<std::size_t>(i)]);
    }
  return e;
}

std::size_t LevelEnvelope::memory_bytes() const {
  return seg_.size() * sizeof(Seg) + start_.size() * sizeof(std::uint32_t) +
         (cellmax_.size() + supermax_.size()) * sizeof(double);
}

double LevelEnvelope::drop_on(const Seg& g, Vec2 p, double r2) {
  const double ex = g.ex, ey = g.ey;
  const double len2 = ex * ex + ey * ey;
  double t = len2 > 0.0 ? ((p.x - g.x0) * ex + (p.y - g.y0) * ey) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double qx = g.x0 + t * ex - p.x, qy = g.y0 + t * ey - p.y;
  const double d2 = qx * qx + qy * qy;
  return d2 > r2 ? -kInf : g.z + std::sqrt(r2 - d2);
}

double LevelEnvelope::hint_height(Vec2 p, double r, std::uint32_t hint) const {
  return hint < seg_.size() ? drop_on(seg_[hint], p, r * r) : -kInf;
}

double LevelEnvelope::centre_height(Vec2 p, double r, double best, std::uint32_t* hint) const {
  if (seg_.empty() || !(r > 0.0)) return best;
  std::uint32_t best_k = SliceEnvelope::kNoHint;
  const double r2 = r * r;
  const int i0 = std::max(0, static_cast<int>(std::floor((p.x - r - origin_.x) / cell_)));
  const int i1 = std::min(nx_ - 1, static_cast<int>(std::floor((p.x + r - origin_.x) / cell_)));
  const int j0 = std::max(0, static_cast<int>(std::floor((p.y - r - origin_.y) / cell_)));
  const int j1 = std::min(ny_ - 1, static_cast<int>(std::floor((p.y + r - origin_.y) / cell_)));
  const double sc = cell_ * kSuper;
  for (int sj = j0 / kSuper; sj <= j1 / kSuper; ++sj) {
    const double sy0 = origin_.y + sj * sc;
    const double sdy = std::max({sy0 - p.y, 0.0, p.y - sy0 - sc});
    for (int si = i0 / kSuper; si <= i1 / kSuper; ++si) {
      const double sx0 = origin_.x + si * sc;
      const double sdx = std::max({sx0 - p.x, 0.0, p.x - sx0 - sc});
      const double sroom = r2 - sdx * sdx - sdy * sdy;
      if (sroom < 0.0) continue;
      const double sneed =
          best - supermax_[static_cast<std::size_t>(sj) * static_cast<std::size_t>(nsx_) +
                           static_cast<std::size_t>(si)];
      if (sneed >= 0.0 && sneed * sneed >= sroom) continue;
      for (int j = std::max(j0, sj * kSuper); j <= std::min(j1, sj * kSuper + kSuper - 1); ++j) {
        const double cy0 = origin_.y + j * cell_, cy1 = cy0 + cell_;
        const double dy = std::max({cy0 - p.y, 0.0, p.y - cy1});
        for (int i = std::max(i0, si * kSuper); i <= std::min(i1, si * kSuper + kSuper - 1); ++i) {
          const double cx0 = origin_.x + i * cell_, cx1 = cx0 + cell_;
          const double dx = std::max({cx0 - p.x, 0.0, p.x - cx1});
          const double room = r2 - dx * dx - dy * dy;  // squared reach of the ball into the cell
          if (room < 0.0) continue;
          const std::size_t c = static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) +
                                static_cast<std::size_t>(i);
          const double cneed = best - cellmax_[c];
          if (cneed >= 0.0 && cneed * cneed >= room) continue;
          for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
            const Seg& g = seg_[k];
            const double need = best - g.z;
            if (need >= 0.0 && need * need >= room) break;  // sorted: no lower level can win
            // The distance to the edge's line bounds the distance to the edge from below:
            // an edge whose line stays beyond the reach it needs cannot win. Products only
            // (no division); the relative margin keeps rounding on the safe side, so the
            // answer does not change.
            const double ex = g.ex, ey = g.ey, len2 = ex * ex + ey * ey;
            const double cross = (p.x - g.x0) * ey - (p.y - g.y0) * ex;
            const double reach2 = need > 0.0 ? r2 - need * need : r2;
            if (cross * cross > reach2 * len2 * (1.0 + 1e-9)) continue;
            // drop_on, with the square root only for an edge that can still win.
            const double t =
                len2 > 0.0 ? std::clamp(((p.x - g.x0) * ex + (p.y - g.y0) * ey) / len2, 0.0, 1.0)
                           : 0.0;
            const double qx = g.x0 + t * ex - p.x, qy = g.y0 + t * ey - p.y;
            const double left = r2 - (qx * qx + qy * qy);
            if (left < 0.0 || (need >= 0.0 && left <= need * need)) continue;
            const double h = g.z + std::sqrt(left);
            if (h > best) {
              best = h;
              best_k = k;
            }
          }
        }
      }
    }
  }
  if (hint != nullptr && best_k != SliceEnvelope::kNoHint) *hint = best_k;
  return best;
}

TriSliceTop TriSliceTop::build(const TriSliceModel& model, double bin_mm, int stride, int threads) {
  TriSliceTop t;
  t.pitch_ = model.pitch_mm * std::max(1, stride);
  // Wider bins mean fewer (slice, bin) cells per query but looser bounds and more edges per
  // cell: at coarse pitches, where a ball spans few slices, the cells dominate (third round:
  // 1 mm instead of 0.5 mm takes 11-15 % off a query at 0.25 / 0.125 / 0.05 mm, and adds 7 %
  // at 0.01 mm).
  if (!(bin_mm > 0.0)) bin_mm = auto_bin_mm(t.pitch_);
  // The three indexes are independent: one task each (each writes only its own member).
  parallel_for(3, threads, [&](std::size_t k) {
    if (k == 0) t.x_ = SliceEnvelope::build(model.family(Axis::kX), bin_mm, stride);
    if (k == 1) t.y_ = SliceEnvelope::build(model.family(Axis::kY), bin_mm, stride);
    if (k == 2)
      t.z_ = LevelEnvelope::build(model.family(Axis::kZ), auto_level_cell_mm(t.pitch_), stride);
  });
  return t;
}

double TriSliceTop::centre_height(Vec2 p, double r_mm, Axis primary, ScanHint* hint) const {
  const SliceEnvelope& a = primary == Axis::kX ? x_ : y_;
  const SliceEnvelope& b = primary == Axis::kX ? y_ : x_;
  if (hint == nullptr)
    return z_.centre_height(p, r_mm, b.centre_height(p, r_mm, a.centre_height(p, r_mm, -kInf)));
  // The three families' previous winners first: whichever family holds the point up, every
  // search then starts from about the final height and prunes from its first bound.
  const double seed =
      std::max({a.hint_height(p, r_mm, hint->primary), b.hint_height(p, r_mm, hint->secondary),
                z_.hint_height(p, r_mm, hint->level)});
  return z_.centre_height(
      p, r_mm,
      b.centre_height(p, r_mm, a.centre_height(p, r_mm, seed, &hint->primary), &hint->secondary),
      &hint->level);
}

}  // namespace swarf
