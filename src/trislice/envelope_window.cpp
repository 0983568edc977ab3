// Window queries: the envelope of seed 001 Eq. (1) over a stretch of a scan line at once.
//
// Why. A point query spends most of its time proving that no other slice beats the contact it
// found (bench/RESULTS-trislice.md, fourth round: seeded with the final answer, each family
// costs as much as the full query). Consecutive points of a scan line share nearly all of that
// proof. So a stretch [a, b] of the line is proved once: every segment whose box cannot hold a
// ball centred anywhere over [a, b] above a lower bound L of the answer all along the stretch
// is left out, and the points of the stretch are then answered from the few that remain.
//
// The lower bound. The height at which a ball of radius r centred over p rests on one segment
// (a slice edge in its plane, or a ring edge at its level) is the top of the Minkowski sum of
// the segment and the ball along the vertical through p: the top of a convex body, so concave
// along any line, and its least value over [a, b] is at a or b. The previous winners of the
// three families (the scan hint) thus give L = max over them of min(height at a, height at b),
// less 1e-6 mm for the rounding of the square roots near the ends of a segment's reach.
//
// Exactness. Every segment left out rises at most to L over the stretch (its bound is the one
// of the point queries, with the distance to the stretch instead of to the point), and the
// winner that gave L is kept and lies above L + 1e-6 mm at every point. So the highest
// computed drop is the same segment and the same double as the point query's: the answers do
// not change, to the bit (checked by hashing every CL point of the Table 2 scans).
#include <algorithm>
#include <cmath>
#include <limits>

#include "swarf/trislice/envelope.h"

namespace swarf {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Below the least height of the hinted winners: far above the rounding of drop_on's roots
// (about 1e-7 mm where a disc barely reaches a point), far below anything a CL point resolves.
constexpr double kWindowMarginMm = 1e-6;

// Distance between the intervals [a0, a1] and [b0, b1] (0 when they overlap).
double gap(double a0, double a1, double b0, double b1) {
  return std::max({b0 - a1, 0.0, a0 - b1});
}

// Along a stretch u in [u0, u1] (u measured from the centre of the arc), the most that
// base + sqrt(R2 - u^2) rises above the line f0 + m u: the arc is concave, so the excess peaks
// where the arc's slope is m, or at the stretch's end nearest to it. -infinity when the arc
// does not reach the stretch.
double arc_excess(double base, double R2, double u0, double u1, double f0, double m) {
  if (R2 < 0.0) return -kInf;
  const double u = std::clamp(-m * std::sqrt(R2) / std::sqrt(1.0 + m * m), u0, u1);
  return u * u > R2 ? -kInf : base + std::sqrt(R2 - u * u) - (f0 + m * u);
}

// The same for base + c sqrt(r^2 - u^2) (c >= 1): slope m where u = -m r / (c sqrt(1/c^2 +
// m^2))... written as u = -m r / sqrt(c^2 + m^2) c / c, i.e. u / sqrt(r^2 - u^2) = -m / c.
double ellipse_excess(double base, double c, double r, double u0, double u1, double f0, double m) {
  const double k = m / c;
  const double u = std::clamp(-k * r / std::sqrt(1.0 + k * k), u0, u1);
  return u * u > r * r ? -kInf : base + c * std::sqrt(r * r - u * u) - (f0 + m * u);
}

}  // namespace

// The most that a ball over a + u dir (u in [0, len]) rests on ring edge g above the chord
// f0 + m u: per piece, as arc_excess. The ends are arcs in u; the interior lies under the ball
// touching the edge's whole line, z + sqrt(r^2 - v^2) with v = A u + B the distance to the
// line, where the foot of the perpendicular falls on the edge.
double LevelEnvelope::level_excess(const Seg& g, Vec2 a, Vec2 dir, double len, double r, double f0,
                                   double m) {
  const double r2 = r * r;
  double ex = -kInf;
  for (const double t : {0.0, 1.0}) {
    const double px = g.x0 + t * g.ex - a.x, py = g.y0 + t * g.ey - a.y;
    const double along = px * dir.x + py * dir.y, perp = px * dir.y - py * dir.x;
    ex = std::max(ex, arc_excess(g.z, r2 - perp * perp, -along, len - along, f0 + m * along, m));
  }
  const double l2 = g.ex * g.ex + g.ey * g.ey;
  if (!(l2 > 0.0)) return ex;
  const double l = std::sqrt(l2);
  // Foot on the edge: t(u) = (t0 + u td) / l2 in [0, 1].
  const double wx = a.x - g.x0, wy = a.y - g.y0;
  const double t0 = wx * g.ex + wy * g.ey, td = dir.x * g.ex + dir.y * g.ey;
  double u0 = 0.0, u1 = len;
  const double slack = 1e-9 * l2;
  if (td != 0.0) {
    const double ua = (-slack - t0) / td, ub = (l2 + slack - t0) / td;
    u0 = std::max(u0, std::min(ua, ub));
    u1 = std::min(u1, std::max(ua, ub));
  } else if (t0 < -slack || t0 > l2 + slack) {
    return ex;
  }
  if (u0 > u1) return ex;
  // Signed distance to the line: v = (c0 + u cd) / l.
  const double A = (dir.x * g.ey - dir.y * g.ex) / l, B = (wx * g.ey - wy * g.ex) / l;
  if (std::fabs(A) < 1e-12) {
    const double left = r2 - B * B;
    if (left >= 0.0)
      ex = std::max(ex, g.z + std::sqrt(left) + 1e-9 - std::min(f0 + m * u0, f0 + m * u1));
    return ex;
  }
  const double v0 = A * u0 + B, v1 = A * u1 + B;
  return std::max(
      ex, ellipse_excess(g.z, 1.0, r, std::min(v0, v1), std::max(v0, v1), f0 - m * B / A, m / A));
}

// How far a disc of radius rho centred over s in [sa, sb] can rest above the floor
// fa + m (s - sa) on anything under the line A + B (t - mid) for t in [lo, hi]. With x = t - s
// the excess is A + B (t - mid) + sqrt(rho^2 - x^2) - fa - m (s - sa), jointly concave in
// (t, x); for each x the best t is an end of its range, which leaves two pieces linear in x
// plus the disc, each highest where the disc's slope matches (x = c rho / sqrt(1 + c^2)).
double excess_over(double A, double B, double mid, double lo, double hi, double sa, double sb,
                   double rho, double rho2, double fa, double m) {
  const double x0 = std::max(lo - sb, -rho), x1 = std::min(hi - sa, rho);
  if (x0 > x1) return -kInf;
  double best = -kInf;
  auto piece = [&](double p0, double p1, double c, double at0) {
    // value = at0 + c x + sqrt(rho^2 - x^2) over [p0, p1] within [x0, x1]
    p0 = std::max(p0, x0), p1 = std::min(p1, x1);
    if (p0 > p1) return;
    const double x = std::clamp(c * rho / std::sqrt(1.0 + c * c), p0, p1);
    best = std::max(best, at0 + c * x + std::sqrt(std::max(0.0, rho2 - x * x)));
  };
  if (B >= m) {  // t = min(hi, x + sb)
    const double xk = hi - sb;
    piece(-kInf, xk, B, A + B * (sb - mid) - fa - m * (sb - sa));  // s = sb, t = x + sb
    piece(xk, kInf, m, A + B * (hi - mid) - fa - m * (hi - sa));   // t = hi, s = hi - x
  } else {                                                         // t = max(lo, x + sa)
    const double xk = lo - sa;
    piece(xk, kInf, B, A + B * (sa - mid) - fa);                   // s = sa, t = x + sa
    piece(-kInf, xk, m, A + B * (lo - mid) - fa - m * (lo - sa));  // t = lo, s = lo - x
  }
  return best + 1e-9;
}

void SliceEnvelope::collect(Vec2 a, Vec2 b, double r, double floor_a, double floor_b,
                            std::vector<std::uint32_t>& out) const {
  const double floor = std::min(floor_a, floor_b);
  out.clear();
  if (n_ == 0 || !(r > 0.0)) return;
  const bool ax = axis_ == Axis::kX;
  const double qa = std::min(ax ? a.x : a.y, ax ? b.x : b.y);
  const double qb = std::max(ax ? a.x : a.y, ax ? b.x : b.y);
  const double sa = std::min(ax ? a.y : a.x, ax ? b.y : b.x);
  const double sb = std::max(ax ? a.y : a.x, ax ? b.y : b.x);
  // The stretch along the slices (the primary family): a chord floor from floor_a at a to
  // floor_b at b. Across them: the lower of the two all along.
  const double sa_in = ax ? a.y : a.x, sb_in = ax ? b.y : b.x;
  const double qa_in = ax ? a.x : a.y, qb_in = ax ? b.x : b.y;
  const bool chord = qa == qb && sb_in > sa_in;
  const bool across = sa == sb && qb_in > qa_in;
  const double slope = chord    ? (floor_b - floor_a) / (sb_in - sa_in)
                       : across ? (floor_b - floor_a) / (qb_in - qa_in)
                                : 0.0;
  const double s_at = sa;
  // The floor along s (constant across the slices, where s does not change).
  const double fa_s = chord ? floor_a : floor, slope_s = chord ? slope : 0.0;
  const long n = static_cast<long>(n_);
  const long jlo = std::max(0L, static_cast<long>(std::ceil((qa - r - first_) / pitch_ - 1e-9)));
  const long jhi =
      std::min(n - 1, static_cast<long>(std::floor((qb + r - first_) / pitch_ + 1e-9)));
  if (jlo > jhi) return;
  const double smax = smin_ + bin_ * nb_;
  if (sb + r < smin_ || sa - r > smax) return;
  const int b0 = std::clamp(static_cast<int>(std::floor((sa - r - smin_) / bin_)), 0, nb_ - 1);
  const int b1 = std::clamp(static_cast<int>(std::floor((sb + r - smin_) / bin_)), 0, nb_ - 1);
  const std::size_t nb = static_cast<std::size_t>(nb_);
  auto level = [&](long j) { return first_ + static_cast<double>(j) * pitch_; };
  // Squared radius of the largest disc a ball over [a, b] puts into slices [j0, j1].
  auto reach2 = [&](long j0, long j1) {
    const double d = gap(qa, qb, level(j0), level(j1));
    return r * r - d * d;
  };
  // Whether a box (highest z top, squared reach room) can hold a ball above floor.
  auto beats = [&](double top, double room) {
    if (room < 0.0) return false;
    const double need = floor - top;
    return need < 0.0 || room > need * need;
  };
  const long B = static_cast<long>(kBlock);
  for (long blk = jlo / B; blk <= jhi / B; ++blk) {
    const long j0 = std::max(jlo, blk * B), j1 = std::min(jhi, blk * B + B - 1);
    const double rb2 = reach2(j0, j1);
    if (rb2 < 0.0) continue;
    for (int m = b0; m <= b1; ++m) {
      const double lo = smin_ + bin_ * m;
      const double dx = gap(sa, sb, lo, lo + bin_);
      const std::size_t bm = static_cast<std::size_t>(m);
      const Line& BL = blockline_[static_cast<std::size_t>(blk) * nb + bm];
      if (!beats(BL.top, rb2 - dx * dx)) continue;
      const double mid = lo + 0.5 * bin_, hi = lo + bin_;
      if (BL.a > -kInf &&
          !(excess_over(BL.a, BL.b, mid, lo, hi, sa, sb, std::sqrt(rb2), rb2, fa_s, slope_s) > 0.0))
        continue;
      for (long j = j0; j <= j1; ++j) {
        const double rho2 = reach2(j, j);
        const std::size_t cell = static_cast<std::size_t>(j) * nb + bm;
        if (!beats(line_[cell].top, rho2 - dx * dx)) continue;
        const double rho = std::sqrt(rho2);
        const Line& L = line_[cell];
        if (L.a > -kInf &&
            !(excess_over(L.a, L.b, mid, lo, hi, sa, sb, rho, rho2, fa_s, slope_s) > 0.0))
          continue;
        for (std::uint32_t k = start_[cell]; k < start_[cell + 1]; ++k) {
          const Seg& g = seg_[k];
          const double dxe = gap(sa, sb, g.s0, g.s1);
          if (!beats(std::max(g.z0, g.z1), rho2 - dxe * dxe)) continue;
          // The segment's highest drop over the stretch: concave in s (see the top), so at
          // the stretch's point nearest to where the drop peaks (over the higher end, or
          // anywhere along a level segment); a larger disc only rests higher, so the
          // slice's largest disc over the stretch bounds every smaller one.
          if (chord) {
            // Along its own slices the stretch keeps rho, and the floor is the chord of the
            // winner's concave drop (below the drop all along): drop - chord is concave too,
            // highest where the support line of slope m touches the disc-swept segment.
            const double e0 = g.z0 - slope * g.s0, e1 = g.z1 - slope * g.s1;
            const double end = e0 > e1 ? g.s0 : e1 > e0 ? g.s1 : std::clamp(sa, g.s0, g.s1);
            const double at =
                std::clamp(end - slope * rho / std::sqrt(1.0 + slope * slope), sa, sb);
            if (drop_on(g, at, rho, rho2) > floor_a + slope * (at - sa)) out.push_back(k);
            continue;
          }
          if (across) {
            // Across the slices rho changes along the stretch (the ball meets slice j in a
            // disc of radius sqrt(r^2 - (q - level)^2)); bound drop - chord per piece: each
            // end is a circular arc in q, the interior lies under the ellipse of the disc
            // tangent to the segment's whole line (z_line(s) + rho(q) / nz).
            const double u0 = qa - level(j), u1 = qb - level(j), fa = floor_a - slope * u0;
            double ex = std::max(
                arc_excess(g.z0, r * r - (s_at - g.s0) * (s_at - g.s0), u0, u1, fa, slope),
                arc_excess(g.z1, r * r - (s_at - g.s1) * (s_at - g.s1), u0, u1, fa, slope));
            if (g.nz > 0.0) {
              // The tangent point s - rho ns lies on the segment for rho in [rlo, rhi], i.e.
              // for |u| in [ulo, uhi] (widened a little against rounding).
              double rlo = 0.0, rhi = r;
              if (g.ns != 0.0) {
                const double ra = (s_at - g.s1) / g.ns, rb = (s_at - g.s0) / g.ns;
                rlo = std::max(rlo, std::min(ra, rb) - 1e-9);
                rhi = std::min(rhi, std::max(ra, rb) + 1e-9);
              } else if (s_at < g.s0 || s_at > g.s1) {
                rlo = 1.0, rhi = 0.0;
              }
              if (rlo <= rhi) {
                const double ulo = std::sqrt(std::max(0.0, r * r - rhi * rhi)) - 1e-9;
                const double uhi = std::sqrt(std::max(0.0, r * r - rlo * rlo)) + 1e-9;
                const double base = g.z0 - (s_at - g.s0) * g.ns / g.nz;
                for (const double sgn : {-1.0, 1.0}) {
                  const double w0 = std::max(u0, sgn > 0 ? ulo : -uhi);
                  const double w1 = std::min(u1, sgn > 0 ? uhi : -ulo);
                  if (w0 <= w1)
                    ex = std::max(ex, ellipse_excess(base, 1.0 / g.nz, r, w0, w1, fa, slope));
                }
              }
            }
            if (ex > 0.0) out.push_back(k);
            continue;
          }
          const double peak = g.z0 > g.z1 ? g.s0 : g.z1 > g.z0 ? g.s1 : std::clamp(sa, g.s0, g.s1);
          if (drop_on(g, std::clamp(peak, sa, sb), rho, rho2) > floor) out.push_back(k);
        }
      }
    }
  }
  // A segment spanning several bins is copied into each: one copy is enough.
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end(),
                        [&](std::uint32_t u, std::uint32_t v) {
                          const Seg &g = seg_[u], &h = seg_[v];
                          return slice_of_[u] == slice_of_[v] && g.s0 == h.s0 && g.z0 == h.z0 &&
                                 g.s1 == h.s1 && g.z1 == h.z1;
                        }),
            out.end());
}

double SliceEnvelope::centre_height_among(Vec2 p, double r, double best,
                                          const std::vector<std::uint32_t>& ids,
                                          std::uint32_t* hint) const {
  if (n_ == 0 || !(r > 0.0)) return best;
  const double q = axis_ == Axis::kX ? p.x : p.y, s = axis_ == Axis::kX ? p.y : p.x;
  std::uint32_t best_id = kNoHint;
  // The same tests and the same arithmetic as centre_height's, per segment.
  auto visit = [&](std::uint32_t k) {
    const double dq = q - (first_ + static_cast<double>(slice_of_[k]) * pitch_);
    const double rho2 = r * r - dq * dq;
    if (rho2 < 0.0) return;
    const Seg& g = seg_[k];
    const double need = best - std::max(g.z0, g.z1);
    if (need >= 0.0) {
      const double dx = std::max({g.s0 - s, 0.0, s - g.s1});
      if (rho2 - dx * dx <= need * need) return;
    }
    const double rho = std::sqrt(rho2);
    if (g.nz > 0.0 && (best - g.z0) * g.nz + (s - g.s0) * g.ns >= rho + 1e-9) return;
    const double c = drop_on(g, s, rho, rho2);
    if (c > best) {
      best = c;
      best_id = k;
    }
  };
  if (hint != nullptr && *hint < seg_.size()) visit(*hint);
  for (const std::uint32_t k : ids)
    visit(k);
  if (hint != nullptr && best_id != kNoHint) *hint = best_id;
  return best;
}

void LevelEnvelope::collect(Vec2 a, Vec2 b, double r, double floor_a, double floor_b,
                            std::vector<std::uint32_t>& out) const {
  out.clear();
  const double floor = std::min(floor_a, floor_b);
  // The stretch as a + u dir, u in [0, len], and the chord floor_a + m u.
  const double len = std::fabs(b.x - a.x) + std::fabs(b.y - a.y);
  const Vec2 dir = b.x != a.x ? Vec2{1.0, 0.0} : Vec2{0.0, 1.0};
  const double m = len > 0.0 ? (floor_b - floor_a) / len : 0.0;
  if (seg_.empty() || !(r > 0.0)) return;
  const double xa = std::min(a.x, b.x), xb = std::max(a.x, b.x);
  const double ya = std::min(a.y, b.y), yb = std::max(a.y, b.y);
  const double r2 = r * r;
  const int i0 = std::max(0, static_cast<int>(std::floor((xa - r - origin_.x) / cell_)));
  const int i1 = std::min(nx_ - 1, static_cast<int>(std::floor((xb + r - origin_.x) / cell_)));
  const int j0 = std::max(0, static_cast<int>(std::floor((ya - r - origin_.y) / cell_)));
  const int j1 = std::min(ny_ - 1, static_cast<int>(std::floor((yb + r - origin_.y) / cell_)));
  for (int j = j0; j <= j1; ++j) {
    const double cy0 = origin_.y + j * cell_;
    const double dy = gap(ya, yb, cy0, cy0 + cell_);
    for (int i = i0; i <= i1; ++i) {
      const double cx0 = origin_.x + i * cell_;
      const double dx = gap(xa, xb, cx0, cx0 + cell_);
      const double room = r2 - dx * dx - dy * dy;
      if (room < 0.0) continue;
      const std::size_t c =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
      const double cneed = floor - cellmax_[c];
      if (cneed >= 0.0 && cneed * cneed >= room) continue;
      for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
        const Seg& g = seg_[k];
        const double need = floor - g.z;
        if (need >= 0.0 && need * need >= room) break;  // sorted: no lower level can win
        // The edge's own box against the stretch.
        const double ex = gap(xa, xb, std::min(g.x0, g.x0 + g.ex), std::max(g.x0, g.x0 + g.ex));
        const double ey = gap(ya, yb, std::min(g.y0, g.y0 + g.ey), std::max(g.y0, g.y0 + g.ey));
        const double left = r2 - ex * ex - ey * ey;
        if (left < 0.0 || (need >= 0.0 && left <= need * need)) continue;
        if (len > 0.0 && level_excess(g, a, dir, len, r, floor_a, m) <= 0.0) continue;
        out.push_back(k);
      }
    }
  }
  // Highest level first (so a point query stops at the first level that cannot win), one copy
  // of an edge listed in several cells.
  auto key = [&](std::uint32_t u) {
    const Seg& g = seg_[u];
    return std::make_tuple(-g.z, g.x0, g.y0, g.ex, g.ey, u);
  };
  std::sort(out.begin(), out.end(),
            [&](std::uint32_t u, std::uint32_t v) { return key(u) < key(v); });
  out.erase(std::unique(out.begin(), out.end(),
                        [&](std::uint32_t u, std::uint32_t v) {
                          const Seg &g = seg_[u], &h = seg_[v];
                          return g.z == h.z && g.x0 == h.x0 && g.y0 == h.y0 && g.ex == h.ex &&
                                 g.ey == h.ey;
                        }),
            out.end());
}

double LevelEnvelope::centre_height_among(Vec2 p, double r, double best,
                                          const std::vector<std::uint32_t>& ids,
                                          std::uint32_t* hint) const {
  if (seg_.empty() || !(r > 0.0)) return best;
  std::uint32_t best_k = SliceEnvelope::kNoHint;
  const double r2 = r * r;
  // The same tests and the same arithmetic as centre_height's, per ring edge.
  auto visit = [&](std::uint32_t k) {
    const Seg& g = seg_[k];
    const double need = best - g.z;
    if (need >= 0.0 && need * need >= r2) return false;  // sorted: no lower level can win
    const double ex = g.ex, ey = g.ey, len2 = ex * ex + ey * ey;
    const double cross = (p.x - g.x0) * ey - (p.y - g.y0) * ex;
    const double reach2 = need > 0.0 ? r2 - need * need : r2;
    if (cross * cross > reach2 * len2 * (1.0 + 1e-9)) return true;
    const double t =
        len2 > 0.0 ? std::clamp(((p.x - g.x0) * ex + (p.y - g.y0) * ey) / len2, 0.0, 1.0) : 0.0;
    const double qx = g.x0 + t * ex - p.x, qy = g.y0 + t * ey - p.y;
    const double left = r2 - (qx * qx + qy * qy);
    if (left < 0.0 || (need >= 0.0 && left <= need * need)) return true;
    const double h = g.z + std::sqrt(left);
    if (h > best) {
      best = h;
      best_k = k;
    }
    return true;
  };
  if (hint != nullptr && *hint < seg_.size()) visit(*hint);
  for (const std::uint32_t k : ids)
    if (!visit(k)) break;
  if (hint != nullptr && best_k != SliceEnvelope::kNoHint) *hint = best_k;
  return best;
}

void TriSliceTop::collect_window(Vec2 a, Vec2 b, double r, Axis primary, const ScanHint& hint,
                                 Window& w) const {
  const SliceEnvelope& pa = primary == Axis::kX ? x_ : y_;
  const SliceEnvelope& pb = primary == Axis::kX ? y_ : x_;
  const double floor =
      std::max(
          {std::min(pa.hint_height(a, r, hint.primary), pa.hint_height(b, r, hint.primary)),
           std::min(pb.hint_height(a, r, hint.secondary), pb.hint_height(b, r, hint.secondary)),
           std::min(z_.hint_height(a, r, hint.level), z_.hint_height(b, r, hint.level))}) -
      kWindowMarginMm;
  w.valid = floor > -kInf;
  if (!w.valid) return;
  // The chord of one winner (the one whose lower end is highest), below it all along.
  double fa = -kInf, fb = -kInf;
  auto pick = [&](double ha, double hb) {
    if (std::min(ha, hb) > std::min(fa, fb)) {
      fa = ha - kWindowMarginMm;
      fb = hb - kWindowMarginMm;
    }
  };
  pick(pa.hint_height(a, r, hint.primary), pa.hint_height(b, r, hint.primary));
  pick(pb.hint_height(a, r, hint.secondary), pb.hint_height(b, r, hint.secondary));
  pick(z_.hint_height(a, r, hint.level), z_.hint_height(b, r, hint.level));
  pa.collect(a, b, r, fa, fb, primary == Axis::kX ? w.x : w.y);
}

double TriSliceTop::centre_height(Vec2 p, double r, Axis primary, ScanHint* hint,
                                  const Window& w) const {
  if (!w.valid) return centre_height(p, r, primary, hint);
  const bool px = primary == Axis::kX;
  const SliceEnvelope& a = px ? x_ : y_;
  const SliceEnvelope& b = px ? y_ : x_;
  const double seed =
      std::max({a.hint_height(p, r, hint->primary), b.hint_height(p, r, hint->secondary),
                z_.hint_height(p, r, hint->level)});
  const double c1 = a.centre_height_among(p, r, seed, px ? w.x : w.y, &hint->primary);
  const double c2 = b.centre_height(p, r, c1, &hint->secondary);
  return z_.centre_height(p, r, c2, &hint->level);
}

}  // namespace swarf
