// Eq. (1) evaluated on a scan line without polygon unions: see envelope.h for the argument.
#include "swarf/trislice/envelope.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace swarf {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace

SliceEnvelope SliceEnvelope::build(const SliceFamily& family, double bin_mm) {
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
          s = {a.x, a.y, b.x, b.y};
        } else {  // kY: (u, v) = (z, x)
          nz = dv;
          s = {a.y, a.x, b.y, b.x};
        }
        if (nz < -1e-12 * std::hypot(du, dv)) continue;
        if (s.s0 > s.s1) s = {s.s1, s.z1, s.s0, s.z0};
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
  for (const auto& v : per) total += v.size();
  e.seg_.reserve(total);
  e.start_.assign(e.n_ * nb + 1, 0);
  e.binmax_.assign(e.n_ * nb, -kInf);
  auto bin_of = [&](double s) {
    return std::clamp(static_cast<int>(std::floor((s - e.smin_) / e.bin_)), 0, e.nb_ - 1);
  };
  // Count, then fill (CSR).
  for (std::size_t j = 0; j < e.n_; ++j)
    for (const Seg& s : per[j])
      for (int b = bin_of(s.s0); b <= bin_of(s.s1); ++b) ++e.start_[j * nb + static_cast<std::size_t>(b) + 1];
  for (std::size_t c = 0; c < e.n_ * nb; ++c) e.start_[c + 1] += e.start_[c];
  e.items_.resize(e.start_.back());
  std::vector<std::uint32_t> fill(e.start_.begin(), e.start_.end() - 1);
  for (std::size_t j = 0; j < e.n_; ++j) {
    for (const Seg& s : per[j]) {
      const auto id = static_cast<std::uint32_t>(e.seg_.size());
      e.seg_.push_back(s);
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

double SliceEnvelope::centre_height(Vec2 p, double r, double best) const {
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
  auto level = [&](long j) { return first_ + static_cast<double>(j) * pitch_; };
  auto visit_block = [&](long blk) {
    const long j0 = std::max(jlo, blk * B), j1 = std::min(jhi, blk * B + B - 1);
    const double l0 = level(j0), l1 = level(j1);
    const double dmin = (q >= l0 && q <= l1) ? 0.0 : std::min(std::fabs(q - l0), std::fabs(q - l1));
    const double rho_max = std::sqrt(std::max(0.0, r * r - dmin * dmin));
    int b0 = 0, b1 = -1;
    if (!bins(rho_max, b0, b1)) return;
    double bound = -kInf;
    for (int b = b0; b <= b1; ++b) bound = std::max(bound, blockmax_[static_cast<std::size_t>(blk) * nb + static_cast<std::size_t>(b)]);
    if (bound + rho_max <= best) return;
    for (long j = j0; j <= j1; ++j) {
      const double dq = q - level(j);
      const double rho2 = r * r - dq * dq;
      if (rho2 < 0.0) continue;
      const double rho = std::sqrt(rho2);  // seed 001 Eq. (1), with (i - j) ds -> y - y_j
      int c0 = 0, c1 = -1;
      if (!bins(rho, c0, c1)) continue;
      for (int b = c0; b <= c1; ++b) {
        const std::size_t cell = static_cast<std::size_t>(j) * nb + static_cast<std::size_t>(b);
        if (binmax_[cell] + rho <= best) continue;
        for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
          const Seg& g = seg_[items_[k]];
          // A disc of radius rho dropped at s onto the segment: end points, then the interior
          // (contact where the upward normal points at the centre).
          const double d0 = s - g.s0, d1 = s - g.s1;
          if (std::fabs(d0) <= rho) best = std::max(best, g.z0 + std::sqrt(rho2 - d0 * d0));
          if (std::fabs(d1) <= rho) best = std::max(best, g.z1 + std::sqrt(rho2 - d1 * d1));
          const double dsg = g.s1 - g.s0;
          if (dsg > 0.0) {
            const double dz = g.z1 - g.z0;
            const double len = std::hypot(dsg, dz);
            const double qs = s + rho * dz / len;
            if (qs >= g.s0 && qs <= g.s1)
              best = std::max(best, g.z0 + (qs - g.s0) / dsg * dz + rho * dsg / len);
          }
        }
      }
    }
  };
  visit_block(bc);
  for (long k = 1; bc - k >= blo || bc + k <= bhi; ++k) {
    if (bc - k >= blo) visit_block(bc - k);
    if (bc + k <= bhi) visit_block(bc + k);
  }
  return best;
}

TriSliceTop TriSliceTop::build(const TriSliceModel& model, double bin_mm) {
  TriSliceTop t;
  t.x_ = SliceEnvelope::build(model.family(Axis::kX), bin_mm);
  t.y_ = SliceEnvelope::build(model.family(Axis::kY), bin_mm);
  return t;
}

double TriSliceTop::centre_height(Vec2 p, double r_mm, Axis primary) const {
  const SliceEnvelope& a = primary == Axis::kX ? x_ : y_;
  const SliceEnvelope& b = primary == Axis::kX ? y_ : x_;
  return b.centre_height(p, r_mm, a.centre_height(p, r_mm, -kInf));
}

}  // namespace swarf
