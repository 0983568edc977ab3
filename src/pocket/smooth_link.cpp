// Smooth links (AdaptiveParams::smooth_links; our addition to seed 000's gap patching, 6.5):
// a link whose straight line turns back on the cut it leaves or on the cut it joins is
// flown instead as a Dubins path, arc - straight - arc or three arcs, over the cleared floor.
//
// Both ways (seed 000), a pass that ends against a wall is followed by one that comes back
// along it; one way, a pass ends against a wall and the next starts back where the front
// begins. Either way the straight link turns back on a cut: a place where the machine stops
// and reverses (the sweep's reversals, a heading turning by more than 135 degrees within
// 1 mm: 70.6 per metre on the L both ways, 116 on the PCB-vice bar, against FreeCAD's 30 and
// 14, whose passes loop back through the cleared floor). The smooth link leaves the pass
// along its heading, or turned by at most 90 degrees where the pass ran into a wall, turns
// round on arcs and comes into the next pass the same way. It is taken when it keeps off the
// walls by exact geometry, cuts no pixel of the stock as it is then, and no 1 mm of it and
// of the steps either side turns by more than kMostTurnDeg. The cheapest such path is kept,
// among the corners of kCornersDeg at either end, the tightest radius each corner allows and
// the wider ones of kRadii, and the six Dubins words (Shkel and Lumelsky's closed forms).
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "pocket/adaptive_internal.h"
#include "swarf/core/vec.h"

namespace swarf::pocket {
namespace {

constexpr double kTwoPi = 2.0 * kPi;
// A straight link turning back on either cut by this much or more is flown smooth instead.
constexpr double kBackDeg = 120.0;
// No millimetre of the smooth link and the cuts' steps either side turns by more (the
// sweep counts a reversal past 135 degrees).
constexpr double kMostTurnDeg = 120.0;
// Turning radii tried beside the tightest, in tool radii, the least radius (mm), and the
// corners (degrees) the link may leave or join a cut at: a pass that ran into a wall has to
// leave along it.
constexpr std::array<double, 3> kRadii{1.0, 0.5, 0.25};
constexpr double kLeastRadiusMm = 0.5;
constexpr std::array<double, 5> kCornersDeg{0.0, 45.0, -45.0, 90.0, -90.0};
// Candidates flown (cheapest first), and checked against the walls and the stock, at most.
// A candidate the pixels put into a wall as it is flown counts as checked; 32 such checks
// find the same loops on the L as 24 did when every candidate was flown whole and only the
// ones turning gently were counted (session 38; 29 pockets: 58 -> 55 reversals per metre,
// machining +0.25 %), at 15 ms of the L's CPU instead of 43.
constexpr int kMostFlown = 96, kMostChecks = 32;

double mod2pi(double a) {
  a = std::fmod(a, kTwoPi);
  return a < 0.0 ? a + kTwoPi : a;
}

// A Dubins word: three pieces, each a left arc (+1), a straight (0) or a right arc (-1),
// with lengths in turning radii (an arc's is its angle in radians).
struct Word {
  std::array<int, 3> turn{};
  std::array<double, 3> len{};
  double total() const { return len[0] + len[1] + len[2]; }
};

// The six words from (0, 0) heading alpha to (d, 0) heading beta, in units of the radius
// (the normal form of Shkel and Lumelsky, "Classification of the Dubins set", 2001). Words
// that do not exist for these ends are left out. The ends' sines and cosines come with
// them: they depend on the corners only, not on the radius.
struct Ends {
  double alpha, beta, sa, sb, ca, cb, cab;
  Ends(double a, double b)
      : alpha(a),
        beta(b),
        sa(std::sin(a)),
        sb(std::sin(b)),
        ca(std::cos(a)),
        cb(std::cos(b)),
        cab(std::cos(a - b)) {}
};

void dubins_words(const Ends& ends, double d, std::vector<Word>& out) {
  const auto [alpha, beta, sa, sb, ca, cb, cab] = ends;
  // LSL
  {
    const double p2 = 2.0 + d * d - 2.0 * cab + 2.0 * d * (sa - sb);
    if (p2 >= 0.0) {
      const double tmp = std::atan2(cb - ca, d + sa - sb);
      out.push_back({{1, 0, 1}, {mod2pi(tmp - alpha), std::sqrt(p2), mod2pi(beta - tmp)}});
    }
  }
  // RSR
  {
    const double p2 = 2.0 + d * d - 2.0 * cab + 2.0 * d * (sb - sa);
    if (p2 >= 0.0) {
      const double tmp = std::atan2(ca - cb, d - sa + sb);
      out.push_back({{-1, 0, -1}, {mod2pi(alpha - tmp), std::sqrt(p2), mod2pi(tmp - beta)}});
    }
  }
  // LSR
  {
    const double p2 = -2.0 + d * d + 2.0 * cab + 2.0 * d * (sa + sb);
    if (p2 >= 0.0) {
      const double p = std::sqrt(p2);
      const double tmp = std::atan2(-ca - cb, d + sa + sb) - std::atan2(-2.0, p);
      out.push_back({{1, 0, -1}, {mod2pi(tmp - alpha), p, mod2pi(tmp - beta)}});
    }
  }
  // RSL
  {
    const double p2 = -2.0 + d * d + 2.0 * cab - 2.0 * d * (sa + sb);
    if (p2 >= 0.0) {
      const double p = std::sqrt(p2);
      const double tmp = std::atan2(ca + cb, d - sa - sb) - std::atan2(2.0, p);
      out.push_back({{-1, 0, 1}, {mod2pi(alpha - tmp), p, mod2pi(beta - tmp)}});
    }
  }
  // RLR
  {
    const double c = (6.0 - d * d + 2.0 * cab + 2.0 * d * (sa - sb)) / 8.0;
    if (std::abs(c) <= 1.0) {
      const double p = mod2pi(kTwoPi - std::acos(c));
      const double t = mod2pi(alpha - std::atan2(ca - cb, d - sa + sb) + p / 2.0);
      out.push_back({{-1, 1, -1}, {t, p, mod2pi(alpha - beta - t + p)}});
    }
  }
  // LRL
  {
    const double c = (6.0 - d * d + 2.0 * cab + 2.0 * d * (sb - sa)) / 8.0;
    if (std::abs(c) <= 1.0) {
      const double p = mod2pi(kTwoPi - std::acos(c));
      const double t = mod2pi(-alpha - std::atan2(ca - cb, d + sa - sb) + p / 2.0);
      out.push_back({{1, -1, 1}, {t, p, mod2pi(beta - alpha - t + p)}});
    }
  }
}

// Points along a word flown from `a` heading `heading` (radians) with turning radius rho,
// at most `spacing` apart, `a` left out, the end included, each offered to `accept` as it
// is made; `heading` becomes the end's. False (and the flight cut short) at the first point
// `accept` refuses.
template <typename Accept>
bool fly(Vec2 a, double& heading, double rho, const Word& w, double spacing, std::vector<Vec2>& pts,
         Accept&& accept) {
  pts.clear();
  Vec2 p = a;
  double th = heading;
  for (std::size_t s = 0; s < 3; ++s) {
    const double len = w.len[s] * rho;
    if (len <= 0.0) continue;
    const int n = std::max(1, static_cast<int>(std::ceil(len / spacing)));
    const int turn = w.turn[s];
    const Vec2 p0 = p;
    const double th0 = th;
    const Vec2 dir{std::cos(th0), std::sin(th0)};
    // An arc's centre lies on its turning side; its heading turns by l / rho.
    const Vec2 c = p0 + perp(dir) * (turn * rho);
    for (int k = 1; k <= n; ++k) {
      const double l = len * k / n;
      if (turn == 0) {
        p = p0 + dir * l;
      } else {
        th = th0 + turn * l / rho;
        p = c + Vec2{std::sin(th), -std::cos(th)} * (turn * rho);
      }
      if (!accept(p)) return false;
      pts.push_back(p);
    }
  }
  heading = th;
  return true;
}

// Whether the polyline turns its heading by at most most_deg between any two of its pieces
// (zero-length ones skipped) less than window_mm of path apart: the sweep's reversal rule,
// which compares each heading with those over the last millimetre of path.
bool turns_gently(const std::vector<Vec2>& pts, double window_mm, double most_deg) {
  const double cos_most = std::cos(deg_to_rad(most_deg));
  struct Piece {
    double start, end;
    Vec2 dir;
  };
  std::vector<Piece> pieces;
  double along = 0.0;
  for (std::size_t k = 1; k < pts.size(); ++k) {
    const double l = distance(pts[k - 1], pts[k]);
    if (l < 1e-9) continue;
    pieces.push_back({along, along + l, (pts[k] - pts[k - 1]) / l});
    along += l;
  }
  std::size_t first = 0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    while (pieces[first].end < pieces[k].start - window_mm)
      ++first;
    for (std::size_t q = first; q < k; ++q)
      if (dot(pieces[q].dir, pieces[k].dir) < cos_most) return false;
  }
  return true;
}

}  // namespace

bool smooth_link(const Model& m, const PixelStock& stock, Vec2 before_a, Vec2 a, Vec2 b,
                 Vec2 after_b, std::vector<Vec2>& out) {
  const double la = distance(before_a, a), lb = distance(b, after_b), ab = distance(a, b);
  if (la < 1e-9 || lb < 1e-9 || ab < 1e-9) return false;
  const Vec2 ha = (a - before_a) / la, hb = (after_b - b) / lb;
  // Only links whose straight line turns back on either cut by kBackDeg or more.
  const double cos_back = std::cos(deg_to_rad(kBackDeg));
  const Vec2 u = (b - a) / ab;
  if (dot(ha, u) > cos_back && dot(u, hb) > cos_back) return false;

  struct Candidate {
    double cost;
    int order;               // made in this order: ties in cost go by it
    double rho, start, end;  // radius, headings at a and b (radians)
    Word word;
  };
  // The longest way that is still worth it.
  const double most_len = ab + kTwoPi * std::max(kLeastRadiusMm, m.radius_mm) + 2.0 * m.radius_mm;
  std::vector<Candidate> cands;
  std::vector<Word> words;
  const double head_a = std::atan2(ha.y, ha.x), head_b = std::atan2(hb.y, hb.x);
  const double dx = b.x - a.x, dy = b.y - a.y, phi = std::atan2(dy, dx);
  for (double ca : kCornersDeg) {
    for (double cb : kCornersDeg) {
      // The tightest arc that a corner of this size allows: the corner and the arc's first
      // millimetre turn by at most kMostTurnDeg together. It and the wider radii of kRadii.
      const double corner = std::max(std::abs(ca), std::abs(cb));
      const double tightest = std::max(kLeastRadiusMm, 1.05 / deg_to_rad(kMostTurnDeg - corner));
      std::array<double, kRadii.size() + 1> radii{};
      std::size_t n_radii = 0;
      radii[n_radii++] = tightest;
      for (double rho_r : kRadii)
        if (rho_r * m.radius_mm > tightest) radii[n_radii++] = rho_r * m.radius_mm;
      const double s = head_a + deg_to_rad(ca), e = head_b - deg_to_rad(cb);
      // A corner costs what a tool radius of path does per right angle.
      const double corner_cost = (std::abs(ca) + std::abs(cb)) / 90.0 * m.radius_mm;
      if (ab + corner_cost > most_len) continue;  // no word is shorter than the chord
      const Ends ends(mod2pi(s - phi), mod2pi(e - phi));
      for (std::size_t k = 0; k < n_radii; ++k) {
        const double rho = radii[k];
        words.clear();
        dubins_words(ends, ab / rho, words);
        for (const Word& w : words) {
          const double cost = w.total() * rho + corner_cost;
          if (cost <= most_len)
            cands.push_back({cost, static_cast<int>(cands.size()), rho, s, e, w});
        }
      }
    }
  }
  // Taken cheapest first (ties in the order made) from a heap: a few dozen are looked at of
  // the hundreds made, so they are not all sorted.
  auto dearer = [](const Candidate& x, const Candidate& y) {
    return x.cost > y.cost || (x.cost == y.cost && x.order > y.order);
  };
  std::make_heap(cands.begin(), cands.end(), dearer);
  const double reach = m.radius_mm + m.wall_stock_mm;
  const double least_wall =
      std::min({reach + kWallClearanceMm, m.walls.distance(a), m.walls.distance(b)}) - 1e-9;
  // A point whose pixels put it nearer a wall than least_wall is: the wall is no farther
  // from it than its nearest pixel centre's clearance, half that pixel's diagonal, and the
  // band of forbidden pixels inside the walls (wall stock and half a pixel, make_model).
  // Such a candidate is dropped as it is flown, before the exact checks, which would drop
  // it too.
  const double band = 1.92 * m.h + m.wall_stock_mm;
  auto clear_by_pixels = [&](Vec2 p) { return clearance_at(m, p) + band >= least_wall; };
  int checked = 0, flown = 0;
  std::vector<Vec2> pts, whole;
  while (!cands.empty()) {
    std::pop_heap(cands.begin(), cands.end(), dearer);
    const Candidate c = cands.back();
    cands.pop_back();
    if (checked >= kMostChecks || ++flown > kMostFlown) break;
    double end_heading = c.start;
    if (!fly(a, end_heading, c.rho, c.word, std::min(m.step_mm, 0.25 * c.rho), pts,
             clear_by_pixels)) {
      ++checked;  // as the exact check it stands in for
      continue;
    }
    const double end_miss = std::abs(std::remainder(end_heading - c.end, kTwoPi));
    if (pts.empty() || distance(pts.back(), b) > 1e-6 || end_miss > 1e-6) continue;
    pts.back() = b;
    // The link with a step of each cut either side: no millimetre turning by more.
    whole.assign({before_a, a});
    whole.insert(whole.end(), pts.begin(), pts.end());
    whole.push_back(after_b);
    if (!turns_gently(whole, 1.0, kMostTurnDeg)) continue;
    ++checked;
    bool ok = true;
    Vec2 prev = a;
    for (std::size_t k = 0; k < pts.size() && ok; ++k) {
      ok = keeps_off_walls(m, prev, pts[k], least_wall) && stock.probe(prev, pts[k], 0) == 0;
      prev = pts[k];
    }
    if (!ok) continue;
    out.insert(out.end(), pts.begin(), pts.end());
    return true;
  }
  return false;
}

}  // namespace swarf::pocket
