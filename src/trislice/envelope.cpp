// Eq. (1) evaluated on a scan line without polygon unions: see envelope.h for the argument.
#include "swarf/trislice/envelope.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

namespace swarf {
#ifdef SWARF_ENV_COUNT
std::atomic<long> g_blocks{0}, g_bins{0}, g_segs{0};
#endif
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

SliceEnvelope SliceEnvelope::build(const SliceFamily& family_in, double bin_mm, int stride) {
  SliceFamily strided;
  if (stride > 1) {
    // Keep the slices on the coarser lattice (level index divisible by stride), so coarse
    // and fine envelopes of one model share their slices.
    strided.axis = family_in.axis;
    strided.pitch_mm = family_in.pitch_mm * stride;
    const long base = std::lround(family_in.first_level / family_in.pitch_mm);
    bool first = true;
    for (std::size_t j = 0; j < family_in.size(); ++j) {
      const long k = base + static_cast<long>(j);
      if (((k % stride) + stride) % stride != 0) continue;
      if (first) strided.first_level = family_in.level(j);
      first = false;
      strided.slices.push_back(family_in.slices[j]);
    }
  }
  const SliceFamily& family = stride > 1 ? strided : family_in;
  SliceEnvelope e;
  e.axis_ = family.axis;
  e.first_ = family.first_level;
  e.pitch_ = family.pitch_mm;
  e.n_ = family.size();
  e.bin_ = bin_mm > 0.0 ? bin_mm : 1.0;
  // Upward-facing edges of every slice, as (s, z) segments. Rings are normalized (outers
  // counter-clockwise, holes clockwise in the plane's (u, v)), so the outward normal of an
  // edge (du, dv) is (dv, -du) and its z component says whether the edge faces up. An edge
  // facing down can never be the first contact of a disc coming from above (the disc would
  // have to cross the solid to reach it).
  std::vector<std::vector<Seg>> per(e.n_);
  double smin = kInf, smax = -kInf;
  for (std::size_t j = 0; j < e.n_; ++j) {
    for (const Ring& ring : family.slices[j].rings) {
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
        const double du = b.x - a.x, dv = b.y - a.y;
        double nz = 0.0;
        Seg s{};
        if (family.axis == Axis::kX) {  // (u, v) = (y, z)
          nz = -du;
          s = {a.x, a.y, b.x, b.y, 0.0, 0.0, 0.0};
        } else {  // kY: (u, v) = (z, x)
          nz = dv;
          s = {a.y, a.x, b.y, b.x, 0.0, 0.0, 0.0};
        }
        if (nz < -1e-12 * std::hypot(du, dv)) continue;
        if (s.s0 > s.s1) s = {s.s1, s.z1, s.s0, s.z0, 0, 0, 0};
        // Upward unit normal (ns, nz) = (-dz, ds) / len, and the slope for the interior test.
        const double ds_ = s.s1 - s.s0, dz_ = s.z1 - s.z0, len = std::hypot(ds_, dz_);
        if (ds_ > 1e-12 && len > 0.0) {
          s.ns = -dz_ / len;
          s.nz = ds_ / len;
          s.slope = dz_ / ds_;
        }  // else vertical (nz stays 0): only its end points can be touched
        smin = std::min(smin, s.s0);
        smax = std::max(smax, s.s1);
        per[j].push_back(s);
      }
    }
  }
  if (smin > smax) {
    smin = 0.0;
    smax = 0.0;
  }
  e.smin_ = smin;
  e.nb_ = static_cast<int>(std::floor((smax - smin) / e.bin_)) + 1;
  const std::size_t nb = static_cast<std::size_t>(e.nb_);
  std::size_t total = 0;
  for (const auto& v : per)
    total += v.size();
  e.seg_.reserve(total);
  e.start_.assign(e.n_ * nb + 1, 0);
  e.binmax_.assign(e.n_ * nb, -kInf);
  auto bin_of = [&](double s) {
    return std::clamp(static_cast<int>(std::floor((s - e.smin_) / e.bin_)), 0, e.nb_ - 1);
  };
  // Count, then fill (CSR).
  for (std::size_t j = 0; j < e.n_; ++j)
    for (const Seg& s : per[j])
      for (int b = bin_of(s.s0); b <= bin_of(s.s1); ++b)
        ++e.start_[j * nb + static_cast<std::size_t>(b) + 1];
  for (std::size_t c = 0; c < e.n_ * nb; ++c)
    e.start_[c + 1] += e.start_[c];
  e.items_.resize(e.start_.back());
  std::vector<std::uint32_t> fill(e.start_.begin(), e.start_.end() - 1);
  for (std::size_t j = 0; j < e.n_; ++j) {
    for (const Seg& s : per[j]) {
      const auto id = static_cast<std::uint32_t>(e.seg_.size());
      e.seg_.push_back(s);
      e.slice_of_.push_back(static_cast<std::uint32_t>(j));
      for (int b = bin_of(s.s0); b <= bin_of(s.s1); ++b) {
        const std::size_t c = j * nb + static_cast<std::size_t>(b);
        e.items_[fill[c]++] = id;
        e.binmax_[c] = std::max(e.binmax_[c], std::max(s.z0, s.z1));
      }
    }
  }
  const std::size_t nblock = (e.n_ + kBlock - 1) / kBlock;
  e.blockmax_.assign(nblock * nb, -kInf);
  for (std::size_t j = 0; j < e.n_; ++j)
    for (std::size_t b = 0; b < nb; ++b) {
      double& m = e.blockmax_[(j / kBlock) * nb + b];
      m = std::max(m, e.binmax_[j * nb + b]);
    }
  return e;
}

std::size_t SliceEnvelope::memory_bytes() const {
  return seg_.size() * sizeof(Seg) + (start_.size() + items_.size()) * sizeof(std::uint32_t) +
         (binmax_.size() + blockmax_.size()) * sizeof(double);
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
  const long bc = jc / B, blo = jlo / B, bhi = jhi / B;
  const std::size_t nb = static_cast<std::size_t>(nb_);
  const double smax = smin_ + bin_ * nb_;
  auto bins = [&](double rho, int& b0, int& b1) {
    if (s + rho < smin_ || s - rho > smax) return false;
    b0 = std::clamp(static_cast<int>(std::floor((s - rho - smin_) / bin_)), 0, nb_ - 1);
    b1 = std::clamp(static_cast<int>(std::floor((s + rho - smin_) / bin_)), 0, nb_ - 1);
    return true;
  };
  // Can a disc of radius sqrt(rho2) centred at s, resting on the top of bin b's box (height
  // top), put its centre above `best`? Squared, so no square root per bin.
  auto can_beat = [&](int b, double top, double rho2) {
    const double lo = smin_ + bin_ * b, hi = lo + bin_;
    const double dx = std::max({lo - s, 0.0, s - hi});
    const double room = rho2 - dx * dx;
    if (room < 0.0) return false;
    const double need = best - top;
    return need < 0.0 || room > need * need;
  };
  auto level = [&](long j) { return first_ + static_cast<double>(j) * pitch_; };
  std::uint32_t best_id = kNoHint;
  // A disc of radius rho dropped at s onto segment id: end points, then the interior (contact
  // where the upward normal points at the centre).
  auto drop = [&](std::uint32_t id, double rho, double rho2) {
    const Seg& g = seg_[id];
    double c = -kInf;
    const double d0 = s - g.s0, d1 = s - g.s1;
    if (std::fabs(d0) <= rho) c = g.z0 + std::sqrt(rho2 - d0 * d0);
    if (std::fabs(d1) <= rho) c = std::max(c, g.z1 + std::sqrt(rho2 - d1 * d1));
    if (g.nz > 0.0) {
      const double qs = s - rho * g.ns;
      if (qs >= g.s0 && qs <= g.s1) c = std::max(c, g.z0 + (qs - g.s0) * g.slope + rho * g.nz);
    }
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
  auto visit_block = [&](long blk) {
    const long j0 = std::max(jlo, blk * B), j1 = std::min(jhi, blk * B + B - 1);
    const double l0 = level(j0), l1 = level(j1);
    const double dmin = (q >= l0 && q <= l1) ? 0.0 : std::min(std::fabs(q - l0), std::fabs(q - l1));
    const double rho_max = std::sqrt(std::max(0.0, r * r - dmin * dmin));
    int b0 = 0, b1 = -1;
    if (!bins(rho_max, b0, b1)) return;
    // Bins of this block that can still beat the best centre; only those are opened below.
    int pass[4096];
    int npass = 0;
    for (int b = b0; b <= b1 && npass < 4096; ++b)
      if (can_beat(b, blockmax_[static_cast<std::size_t>(blk) * nb + static_cast<std::size_t>(b)],
                   rho_max * rho_max))
        pass[npass++] = b;
#ifdef SWARF_ENV_COUNT
    g_blocks++;
    g_bins += npass;
#endif
    if (npass == 0) return;
    for (long j = j0; j <= j1; ++j) {
      const double dq = q - level(j);
      const double rho2 = r * r - dq * dq;
      if (rho2 < 0.0) continue;
      const double rho = std::sqrt(rho2);  // seed 001 Eq. (1), with (i - j) ds -> y - y_j
      for (int m = 0; m < npass; ++m) {
        const int b = pass[m];
        const std::size_t cell = static_cast<std::size_t>(j) * nb + static_cast<std::size_t>(b);
        if (!can_beat(b, binmax_[cell], rho2)) continue;
        for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
          drop(items_[k], rho, rho2);
        }
      }
    }
  };
  visit_block(bc);
  for (long k = 1; bc - k >= blo || bc + k <= bhi; ++k) {
    if (bc - k >= blo) visit_block(bc - k);
    if (bc + k <= bhi) visit_block(bc + k);
  }
  if (hint != nullptr && best_id != kNoHint) *hint = best_id;
  return best;
}

TriSliceTop TriSliceTop::build(const TriSliceModel& model, double bin_mm, int stride) {
  TriSliceTop t;
  t.x_ = SliceEnvelope::build(model.family(Axis::kX), bin_mm, stride);
  t.y_ = SliceEnvelope::build(model.family(Axis::kY), bin_mm, stride);
  return t;
}

double TriSliceTop::centre_height(Vec2 p, double r_mm, Axis primary, ScanHint* hint) const {
  const SliceEnvelope& a = primary == Axis::kX ? x_ : y_;
  const SliceEnvelope& b = primary == Axis::kX ? y_ : x_;
  std::uint32_t* ha = hint != nullptr ? &hint->primary : nullptr;
  std::uint32_t* hb = hint != nullptr ? &hint->secondary : nullptr;
  return b.centre_height(p, r_mm, a.centre_height(p, r_mm, -kInf, ha), hb);
}

}  // namespace swarf
