// The path's reach to the walls, after post-processing (our additions to seed 000): passes
// along a wall snapped onto its exact offset, and visits into the tips of the tool centres'
// region that the pixel model stops short of.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <vector>

#include "pocket/adaptive_internal.h"
#include "pocket/geometry.h"
#include "swarf/polygon/polygon.h"

namespace swarf::pocket {
namespace {

// Passes along a wall, snapped onto one exact offset of it (our addition). The chooser
// follows a wall at a pixel's accuracy: its boundary steps turn in whole degrees against
// pixel walls, and smoothing and simplification move points by a fraction of a pixel, so
// successive passes along one wall sit anywhere from -0.02 to +0.06 mm off the nominal
// offset (sweep of the benchmark L), and each later pass re-cuts a hair of the previous
// one's: a long cut at an engagement of a few degrees. Points within kSnapRidingPx pixels of
// the offset wall stock + kWallClearanceMm are put exactly on it (nearest wall point +
// normal x distance), so passes along a wall coincide and the wall is cut to size once;
// a point whose snapped place would come nearer another wall stays where it is. On the
// four benchmark pockets this raised the share within +-20 % by 1-5 points by both of the
// sweep's measures and lowered the residual material.
// Session 10: a pass that rides a wall sits 0 to about a pixel off the offset (the forbidden
// half pixel and the lattice), but passes at 1.25 to 2 pixels are mostly fronts running
// beside the wall, and snapping them too (the band was 2 pixels) bent them onto it with a
// kink at each end. Yet with the coarse pixels of large tools the last pass round a round
// island rides up to 2 pixels off, and left unsnapped it leaves a hair of up to half a
// millimetre on the island. So a point between kSnapRidingPx and kSnapLastPx is snapped
// only when it is the last pass along that stretch of wall: no later point of the path
// comes nearer the wall (by a quarter pixel) within kLastPassReach x R of its foot.
// Within +-20 % by the sweep: L 91.9 -> 92.2 %, Kiri:Moto 94.6 -> 95.1 %, star 94.0 ->
// 94.4 %, PCB-vice bar 92.3 -> 92.8 %, six islands 78.8 -> 79.6 %; residual unchanged
// (bench/RESULTS-pocket.md, session 10).
// Session 50: the last-pass band narrowed from 2 to 1.5 pixels. Judged by the corrected sweep
// (session 49, which reads a ride along a wall the same on every side), a last pass 1.5 to 2
// pixels off the wall was more often a front beside it than the pass that finishes it, and
// snapping bent it onto the wall: 48 random pockets (seeds 2000-2047) 88.89 -> 89.09 % on
// average, 35 up and 1 down, the star 94.8 -> 95.2 %, residual unchanged. Narrower still
// (1.25 pixels) left a skin on the walls at a high stepover
// (AdaptivePocketStock.ScallopsLeftOnTheWallsAtAHighStepoverAreTakenOff: 0.19 mm^2 left).
// The channel rule below keeps its 2 pixels (kChannelPx): a pass in a channel not that much
// wider than the tool goes down its middle wherever it sits.
// Session 51: the riding band narrowed from 1.25 to 1 pixel. A pass 1 to 1.25 pixels off a
// wall was more often a front beside it than a ride along it: 48 random pockets 89.09 ->
// 89.18 % on average (29 up, 13 down), the L 94.9 -> 95.0 %, the star 95.2 -> 95.4 %, the
// PCB-vice bar 95.8 -> 96.3 %, residual unchanged. It leaves a skin under a pixel where
// such a pass goes by, which the ways to the wall rides kept on the exact offset grazed at
// the link feed until they were lifted off it too (wall_rides.cpp).
constexpr double kSnapRidingPx = 1.0, kSnapLastPx = 1.5, kLastPassReach = 0.1, kChannelPx = 2.0;
// Session 52: sliver passes. A pass that runs beside a wall a little off its offset, where a
// later pass rides the wall, leaves the later one a sliver: on the benchmark L a pass 0.10 mm
// (1.6 pixels) off the left wall, outside both bands, and a ride along it 10.6 mm long at 6
// to 16 degrees against a target of 37. Such a pass, over a run of at least
// kSliverRunShare x the stepover within kSliverShare x the stepover of the offset, is put
// onto it, with its ends eased over kSliverTaperShare x the stepover unless they meet points
// snapped already; the later ride then cuts nothing there. A fifth of the stepover keeps the
// moved pass within +-20 % (taking 1.2 x the stepover reads at most 1.1 x the target
// angle). Snapping every such point regardless of the run (a bent kink at each end where
// a front crosses the band) took the L down from 95.0 to 92.1 %. Measured with the
// corrected sweep: the L 94.98 -> 95.12 %, 48 random pockets (seeds 2000-2047) 89.18 ->
// 89.27 % (25 up, 1 down), 48 fresh ones (3000-3047) 91.47 -> 91.56 % (20 up, 5 down by at
// most 0.1 point), residual unchanged. A band of 0.35 x the stepover gained the L more (95.16
// %) but lost as many random pockets as it gained; runs of a quarter of the stepover lost
// more than they gained.
constexpr double kSliverShare = 0.2, kSliverRunShare = 0.75, kSliverTaperShare = 0.5;

// A point whose snapped place comes nearer another wall is where two walls (or a wall and
// an island) are less than a tool diameter apart. The chooser's pixel test keeps the disk
// within about a fifth of a pixel of them, not exactly off them: the random pocket sweep
// found a point 3.4 um into an island 1.9 mm from a wall (ø3 tool, pixel 0.027 mm). Such a
// point is pushed out along the nearest wall's normal, and once another wall is the
// nearest, to the corner of the two walls' offset lines; if 16 rounds do not get it clear
// it keeps the position that gouges least. A point is pushed while nearer the walls than
// `at_least` (the reach for the path's own points).
void push_out_of_walls(const Model& m, Vec2& p, double on, double at_least) {
  Vec2 best = p;
  double best_d = m.walls.distance(p);
  Vec2 c = p, q_prev, n_prev;
  bool have_prev = false;
  for (int round = 0; round < 16 && best_d < at_least - 1e-9; ++round) {
    const Vec2 q = m.walls.nearest(c);
    const double d = distance(c, q);
    if (d < 1e-9 || !m.walls.inside(c)) break;
    const Vec2 n = (c - q) / d;
    Vec2 next = q + n * on;
    // Alternating projections crawl where the two walls meet at a small angle (a ø12 point
    // stayed 4 um inside after 16 rounds between a round and a square island): once the
    // nearest wall has changed, go to the corner of the two walls' offset lines, which
    // the curvature of the walls moves by second-order terms only.
    const double det = cross(n, n_prev);
    if (have_prev && distance(q, q_prev) > 1e-6 && std::abs(det) > 1e-3) {
      const double b1 = on + dot(n, q), b2 = on + dot(n_prev, q_prev);
      const Vec2 x{(b1 * n_prev.y - b2 * n.y) / det, (n.x * b2 - n_prev.x * b1) / det};
      if (distance(x, c) < 0.1 * m.radius_mm) next = x;
    }
    q_prev = q;
    n_prev = n;
    have_prev = true;
    c = next;
    const double dc = m.walls.distance(c);
    if (dc > best_d && m.walls.inside(c)) {
      best = c;
      best_d = dc;
    }
  }
  p = best;
}

}  // namespace

void snap_to_wall_offset(const Model& m, LinkedPath& lp) {
  const double on = m.radius_mm + m.wall_stock_mm + kWallClearanceMm;
  const double reach = m.radius_mm + m.wall_stock_mm;
  const double riding = kSnapRidingPx * m.h, last = kSnapLastPx * m.h, channel = kChannelPx * m.h;
  const double sliver = std::max(last, kSliverShare * m.stepover_mm);
  const double look = std::max(channel, sliver);
  const std::size_t n = lp.pts.size();
  std::vector<Vec2> foot(n);
  std::vector<double> dist(n, std::numeric_limits<double>::infinity());
  // A link lifted off a wall (apply_lifted) stands for one on its offset: it no longer
  // cuts the wall, but it did when the passes before it were made, and snapping them as the
  // last ones there bent them onto the wall (PCB-vice bar: 1.3 points of the band).
  const double lifted_link = on + m.link_lift_mm + 0.5 * m.h;
  auto is_link = [&](std::size_t j) {
    return j > 0 && lp.kind[j - 1] == StepKind::kLink && !lp.jump[j - 1];
  };
  for (std::size_t k = 0; k < n; ++k) {
    // Only points within on + channel (or the sliver band) of a wall are looked at: the
    // rest, most of them, are known to lie farther by the pixels.
    if (far_from_walls(m, lp.pts[k], lp.pts[k], is_link(k) ? lifted_link : on + look)) continue;
    foot[k] = m.walls.nearest(lp.pts[k]);
    dist[k] = distance(lp.pts[k], foot[k]);
  }
  // The distance a later point stands for, as the snapping of earlier ones sees it.
  auto eff = [&](std::size_t j) {
    return is_link(j) && dist[j] < lifted_link ? std::min(dist[j], on) : dist[j];
  };
  // The points near a wall, by the cell of their foot on it (cells of kLastPassReach x R).
  const double cell = kLastPassReach * m.radius_mm;
  auto cell_of = [&](Vec2 v) {
    return std::pair<long, long>{static_cast<long>(std::floor(v.x / cell)),
                                 static_cast<long>(std::floor(v.y / cell))};
  };
  std::map<std::pair<long, long>, std::vector<std::size_t>> near_wall;
  for (std::size_t k = 0; k < n; ++k)
    if (eff(k) < on + look) near_wall[cell_of(foot[k])].push_back(k);
  // Whether a later point near the wall within `cell` of k's foot stands for a distance
  // under `below`.
  auto later_nearer = [&](std::size_t k, double below) {
    const auto [cx, cy] = cell_of(foot[k]);
    for (long dx = -1; dx <= 1; ++dx) {
      for (long dy = -1; dy <= 1; ++dy) {
        const auto it = near_wall.find({cx + dx, cy + dy});
        if (it == near_wall.end()) continue;
        for (const std::size_t j : it->second) {
          if (j > k && eff(j) < below && distance(foot[j], foot[k]) < cell) return true;
        }
      }
    }
    return false;
  };
  auto last_pass = [&](std::size_t k) { return !later_nearer(k, dist[k] - 0.25 * m.h); };
  // A later point of the path rides the wall (within the riding band) at k's foot.
  auto ridden_later = [&](std::size_t k) { return later_nearer(k, on + riding); };
  // A point pushed out of the walls is where two walls (or a wall and an island) meet
  // within a tool diameter: in a corner, where the passes that ran towards it leave slivers
  // thinner than a pixel between their disks, which the re-simulation reads as cut. The
  // move to it runs at the cutting feed (random pocket 955, ø16 at 10 %: the last move of a
  // pass into the corner of an L's arm ran at the link feed on a read of nothing and took
  // 0.67 mm^2 in 0.36 mm by the sweep).
  // A point the push leaves inside lies past the tip of the region of tool centres, where
  // no place near it is clear of both walls: the chooser's pixels let the disk come within
  // about a fifth of a pixel of each wall, which in a tip of a few degrees is tenths of a
  // millimetre past its end (random pocket 5421, ø8 between a wall and a bar's corner
  // 7.944 mm apart: a session ended 0.34 mm past the tip, and the push kept the place that
  // gouged least, 0.042 mm into the wall by the sweep). It goes back along the path, towards
  // a neighbour clear of the walls, to the last place that the move from there keeps clear
  // (a bisection: once the move cuts in, every longer one does).
  auto retreat = [&](std::size_t k) {
    Vec2& p = lp.pts[k];
    std::vector<std::size_t> neighbours;
    if (k > 0) neighbours.push_back(k - 1);
    if (k + 1 < n) neighbours.push_back(k + 1);
    for (const std::size_t j : neighbours) {
      const Vec2 a = lp.pts[j];
      if (!m.walls.inside(a) || m.walls.distance(a) < reach - 1e-9) continue;
      double lo = 0.0, hi = 1.0;
      for (int it = 0; it < 40; ++it) {
        const double t = 0.5 * (lo + hi);
        (m.walls.segment_distance(a, a + (p - a) * t) >= reach - 1e-9 ? lo : hi) = t;
      }
      p = a + (p - a) * lo;
      return;
    }
  };
  auto push_out = [&](std::size_t k) {
    Vec2& p = lp.pts[k];
    push_out_of_walls(m, p, on, reach);
    if (m.walls.distance(p) < reach - 1e-9) retreat(k);
    lp.design_cut_ends.push_back(p);
  };
  // The share of the way to the wall's offset each point of a pass beside a later ride goes
  // (sliver passes, above): 1 along the run, less over its tapered ends, 0 elsewhere.
  std::vector<double> weight(n, 0.0);
  {
    std::vector<char> cand(n, 0);
    for (std::size_t k = 0; k < n; ++k)
      cand[k] = dist[k] >= on + riding && dist[k] < on + sliver && !is_link(k) && ridden_later(k);
    const double min_run = kSliverRunShare * m.stepover_mm;
    const double taper = kSliverTaperShare * m.stepover_mm;
    for (std::size_t a = 0; a < n;) {
      if (!cand[a]) {
        ++a;
        continue;
      }
      std::size_t b = a;
      while (b + 1 < n && cand[b + 1])
        ++b;
      std::vector<double> at(b - a + 1, 0.0);
      for (std::size_t k = a + 1; k <= b; ++k)
        at[k - a] = at[k - a - 1] + distance(lp.pts[k], lp.pts[k - 1]);
      const double len = at.back();
      if (len >= min_run) {
        const bool snapped_before = a > 0 && dist[a - 1] < on + riding;
        const bool snapped_after = b + 1 < n && dist[b + 1] < on + riding;
        for (std::size_t k = a; k <= b; ++k) {
          double w = 1.0;
          if (!snapped_before) w = std::min(w, at[k - a] / taper);
          if (!snapped_after) w = std::min(w, (len - at[k - a]) / taper);
          weight[k] = w;
        }
      }
      a = b + 1;
    }
  }
  for (std::size_t k = 0; k < n; ++k) {
    const double d = dist[k];
    if (d < 1e-9 || d >= on + look) continue;
    const bool banded = d < on + channel && (d < on + riding || last_pass(k));
    // Onto the offset all the way (riding, or a last pass within its band); a sliver pass
    // goes its weight's share of the way.
    const bool full = banded && d < on + last;
    if (!banded && weight[k] <= 0.0) continue;
    Vec2& p = lp.pts[k];
    const Vec2 s = foot[k] + (p - foot[k]) * (on / d);
    // In a channel less than kChannelPx pixels wider than the tool, the other wall's band
    // holds the point too, and the chooser's pixel path wanders between the two rims of its
    // strip of free centres (which reach up to half a pixel past the exact offset): pushed
    // out onto the nearer wall's offset each time, it became a zig-zag of +-24 degrees
    // between the two offsets (a ø10 through a neck 10.1 mm wide, once the pixels were fine
    // enough for free centres to fit in it), cutting the neck at 145-165 degrees, where a
    // straight pass is the plain slot that the neck plunges take. Such a point goes to the
    // middle of the channel, the place with the most room, so the pass runs straight down
    // it whatever the pixel.
    const Vec2 across = s + (p - foot[k]) * ((on + channel) / d);
    if (!m.walls.inside(across)) {
      if (!banded) continue;  // in a channel, a sliver pass is left to the channel rule's band
      const Vec2 mid = (foot[k] + m.walls.nearest(across)) * 0.5;
      if (m.walls.inside(mid) && m.walls.distance(mid) > d && distance(mid, p) < 2.0 * channel)
        p = mid;
      if (m.walls.distance(p) < reach - 1e-9) push_out(k);
    } else if (!full && weight[k] <= 0.0) {
      continue;  // past the last-pass band: only the channel rule moves it
    } else if (m.walls.distance(s) >= on - 1e-9 && m.walls.inside(s)) {
      p = full ? s : p + (s - p) * weight[k];
    } else if (d < reach - 1e-9) {
      push_out(k);
    }
  }
}

// Tips of the region of tool centres (our addition). Where two walls meet at a corner under
// 180 degrees, or a wall and an island come nearer than the tool, the region the tool
// centre may occupy ends in a sharp tip, and the tool only clears the material near the
// corner from the tip itself. The chooser's pixel model keeps half a pixel off each wall,
// which moves the tip back by half a pixel / sin(half the tip angle): 0.3 mm in a 30 degree
// wedge at a 0.15 mm pixel, and the disk left a crescent of 5-10 mm^2 there (random pocket
// sweep). The exact tips are the sharp convex vertices of the pocket shrunk by the tool
// radius, wall stock and kWallClearanceMm; the path point nearest to a tip it does not
// reach, if within kTipReachPx pixels or half the tool radius (whichever is more) and with
// a way there clear of the walls, gets a short visit to the tip and back. Half the radius
// (session 8): a path that stopped 1-3 mm short of a tip left 1.5 mm^2 in the wedge
// (random pocket 36, ø12); the visit takes it, at up to 0.2 mm more of near slot there.
constexpr double kTipReachPx = 8.0, kTipSpanPx = 1.5;

void reach_into_tips(const Model& m, LinkedPath& lp) {
  const double on = m.radius_mm + m.wall_stock_mm + kWallClearanceMm;
  const double reach = m.radius_mm + m.wall_stock_mm;
  const PolygonSet centres = offset(m.region, -on);
  std::vector<Vec2> tips;
  std::vector<double> tip_near;  // per tip, how far from the path it is still visited
  const double near = std::max(kTipReachPx * m.h, 0.5 * m.radius_mm);
  // A sharp convex corner turns left by more than 20 degrees, at one vertex (the round joins
  // of the offset turn by a few degrees per vertex) or over a few of them within kTipSpanPx
  // pixels: the offset of a pocket corner rounded a little wider than the tool is a tiny
  // arc, which the free pixel centres do not follow either (part-like pocket 2312: a corner
  // rounded 0.2 mm wider than a ø20, 12 vertices of 7.5 degrees; the path stopped 0.4 mm
  // short and a scallop dab into it took 1.8 mm^2 at the link feed). One tip per run of
  // such vertices, where half its turn is done.
  const double span = kTipSpanPx * m.h;
  for (const Ring& r : centres.rings) {
    const std::size_t n = r.size();
    if (n < 3) continue;
    std::vector<double> turn(n), at(n + 1, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      const Vec2 u = r[k] - r[(k + n - 1) % n], v = r[(k + 1) % n] - r[k];
      // Interior on the left: a left turn is a convex corner.
      turn[k] = std::atan2(cross(u, v), dot(u, v));
      at[k + 1] = at[k] + norm(v);
    }
    const double perimeter = at[n];
    // Per vertex, the turn of the vertices within `span` of it along the ring.
    std::vector<double> near_turn(n, 0.0);
    for (std::size_t k = 0; k < n; ++k) {
      near_turn[k] = turn[k];
      std::size_t ahead = 1;
      for (; ahead < n; ++ahead) {
        const std::size_t j = (k + ahead) % n;
        if (std::fmod(at[j] - at[k] + perimeter, perimeter) > span) break;
        near_turn[k] += turn[j];
      }
      for (std::size_t back = 1; back + ahead < n + 1; ++back) {
        const std::size_t j = (k + n - back) % n;
        if (std::fmod(at[k] - at[j] + perimeter, perimeter) > span) break;
        near_turn[k] += turn[j];
      }
    }
    const double sharp = deg_to_rad(20.0);
    auto marked = [&](std::size_t k) { return turn[k] > 0.0 && near_turn[k] > sharp; };
    // Whether vertex k's run goes on to the next vertex: both marked, at most `span` apart.
    auto joined = [&](std::size_t k) {
      const std::size_t j = (k + 1) % n;
      return marked(k) && marked(j) && at[k + 1] - at[k] <= span;
    };
    // Runs of marked vertices, from one that does not continue its predecessor's run (none
    // does not: the whole ring is one run).
    std::size_t first = 0;
    while (first < n && !(marked(first) && !joined((first + n - 1) % n)))
      ++first;
    const bool whole_ring = first == n;
    if (whole_ring) first = 0;
    for (std::size_t q = 0; q < n;) {
      if (!marked((first + q) % n)) {
        ++q;
        continue;
      }
      std::vector<std::size_t> run;
      double total = 0.0;
      do {
        run.push_back((first + q) % n);
        total += turn[run.back()];
        ++q;
      } while (q < n && joined(run.back()));
      if (total <= sharp) continue;
      std::size_t apex = run.front();
      for (double done = 0.0; const std::size_t k : run) {
        done += turn[k];
        apex = k;
        if (done >= 0.5 * total) break;
      }
      tips.push_back(r[apex]);
      // The free pixels end about 1.5 pixels (the half-pixel margin and the sampling) /
      // sin(half the tip's angle) short of the exact tip. Past 8.6 degrees that is within
      // `near`; a sharper tip is visited from as far as that shortfall (session 16: random
      // pocket seed 710, ø16 between a round wall and an island's straight edge 16.3 mm
      // apart, nearly tangent: the region of centres ends in a 6.6 degree sliver, the path
      // stopped 4.2 mm short of its tip and 4.7 mm^2 were left on both sides). At most R: the
      // way there is clear of the walls, but a long one would cut as a slot.
      const double half_tip = 0.5 * (kPi - std::min(total, kPi));
      tip_near.push_back(
          std::max(near, std::min(1.5 * m.h / std::max(std::sin(half_tip), 1e-3), m.radius_mm)));
    }
  }
  // Corridors of the region of centres (our addition): where the pocket narrows to within
  // a pixel or so of the tool's width over a stretch, the region of centres there is a strip
  // narrower than a pixel, with no free pixel centre in it, and the path from either end
  // stops where the free pixels do. The tool's disks from the two ends cover the middle of
  // the way but not the lens-shaped slivers each side, which only centres in the strip
  // reach (random pocket 617 at 10 % stepover: a ø20 in a channel 0.02 mm wider than
  // itself along an island, 8.7 mm of it untravelled, 3.6 mm^2 left in slivers up to 0.8
  // mm thick). Points of the strip's edges at most `near` / 2 apart, none within two pixels
  // of a free pixel centre or within `near` of a sharp tip, are visited as tips are, each
  // from the path or from the last one visited; the visits' heavy moves there are plunged
  // through with the necks (neck_runs: under four pixels of room).
  {
    const std::size_t sharp_tips = tips.size();
    const double thin = 1.5 * m.h, spacing = 0.5 * near;
    auto beside_free = [&](Vec2 q) {
      const Vec2 c = m.grid.to_px(q);
      const int i0 = static_cast<int>(std::lround(c.x)), j0 = static_cast<int>(std::lround(c.y));
      for (int j = j0 - 2; j <= j0 + 2; ++j) {
        for (int i = i0 - 2; i <= i0 + 2; ++i) {
          if (i >= 0 && j >= 0 && i < m.grid.width && j < m.grid.height && m.free_centres.get(i, j))
            return true;
        }
      }
      return false;
    };
    auto far_from = [&](Vec2 q, std::size_t first, std::size_t last, double d) {
      for (std::size_t k = first; k < last; ++k)
        if (distance(tips[k], q) < d) return false;
      return true;
    };
    for (const Ring& r : centres.rings) {
      const std::size_t n = r.size();
      if (n < 3) continue;
      for (std::size_t k = 0; k < n; ++k) {
        const Vec2 a = r[k], b = r[(k + 1) % n];
        const double len = distance(a, b);
        if (len <= 0.0) continue;
        const Vec2 along = (b - a) / len, in{-along.y, along.x};  // interior on the left
        const int pieces = std::max(1, static_cast<int>(std::ceil(len / m.h)));
        for (int q = 0; q < pieces; ++q) {
          const Vec2 v = a + along * (len * (q + 0.5) / pieces);
          if (beside_free(v) || point_in_region(centres, v + in * thin)) continue;
          if (!far_from(v, 0, sharp_tips, near) || !far_from(v, sharp_tips, tips.size(), spacing))
            continue;
          tips.push_back(v);
          tip_near.push_back(near);
        }
      }
    }
  }
  if (tips.empty() || lp.pts.size() < 2) return;
  auto clear = [&](Vec2 a, Vec2 b) { return m.walls.segment_distance(a, b) >= reach - 1e-7; };
  // The straight way from `from` to the tip t, else one through 1, 3, 7 or 15 points spread
  // along it and pushed out of the walls; empty when none keeps clear. The straight way
  // grazes the wall it runs along where the chord between two points on the offset of a
  // convex corner dips inside it (0.3 um on an L with a rectangular island, and the wedge
  // kept 1.6 mm^2); in a wedge between a wall and an island's corner the way bends round
  // the corner's arc, and one midpoint was not enough (random pocket seed 132: 0.9 mm short
  // of the tip, 11.5 mm^2 left by the sweep). The points are pushed to the clearance, not
  // just to the reach: along a wall's corner (a vertex of a polygonal round island, whose
  // offset is an arc of the tool radius) a chord between points at the bare reach dips
  // inside it, and no number of pieces cleared it (random pocket seed 1041, ø20: the path
  // 0.41 mm from the tip, 3.3 mm^2 left).
  auto way_to = [&](Vec2 from, Vec2 t) {
    std::vector<Vec2> way;
    for (int pieces = 1; pieces <= 16 && way.empty(); pieces *= 2) {
      Vec2 prev = from;
      bool ok = true;
      for (int q = 1; q <= pieces && ok; ++q) {
        Vec2 p = q == pieces ? t : from + (t - from) * (static_cast<double>(q) / pieces);
        if (q < pieces) push_out_of_walls(m, p, on, on - 1e-6);
        ok = m.walls.inside(p) && clear(prev, p);
        way.push_back(p);
        prev = p;
      }
      if (!ok) way.clear();
    }
    return way;
  };
  // Per path point, the tips it visits (in the order found), each as the points of the way
  // there (the tip last). A tip nearer a tip already visited than to the path is reached
  // from that tip, the way extended (session 15: random pocket seed 504, ø20, where an
  // island's offset cuts the offset corner of the outer wall, the region of centres ends
  // in two tips 0.7 mm apart; the path came 4.5 mm from one and 5.08 from the other, just
  // beyond the reach, and the sweep found a crescent of 11 mm^2 left beside the island).
  std::vector<std::vector<std::vector<Vec2>>> visits(lp.pts.size());
  struct Visited {
    std::size_t at, index;  // visits[at][index]
  };
  std::vector<Visited> visited;
  std::vector<bool> pending(tips.size(), false);
  bool any = false;
  for (std::size_t ti = 0; ti < tips.size(); ++ti) {
    const Vec2 t = tips[ti];
    double best = 1e300, reached = 1e300;
    std::size_t at = 0;
    for (std::size_t k = 0; k < lp.pts.size(); ++k) {
      const double d = distance(lp.pts[k], t);
      if (d < best) {
        best = d;
        at = k;
      }
      if (k + 1 < lp.pts.size() && !lp.jump[k])
        reached = std::min(reached, pocket::point_segment_distance(t, lp.pts[k], lp.pts[k + 1]));
    }
    if (reached < 0.05 * m.h) continue;
    if (m.walls.distance(t) < reach - 1e-9 || !m.walls.inside(t)) continue;
    if (best > tip_near[ti]) {
      pending[ti] = true;
      continue;
    }
    std::vector<Vec2> way = way_to(lp.pts[at], t);
    if (way.empty()) continue;
    visits[at].push_back(std::move(way));
    visited.push_back({at, visits[at].size() - 1});
    any = true;
  }
  // The tips beyond the path's reach, from the nearest tip visited, while any is taken.
  for (bool grew = true; grew;) {
    grew = false;
    for (std::size_t ti = 0; ti < tips.size(); ++ti) {
      if (!pending[ti]) continue;
      const Vec2 t = tips[ti];
      double best = tip_near[ti];
      const Visited* from = nullptr;
      for (const Visited& v : visited) {
        const double d = distance(visits[v.at][v.index].back(), t);
        if (d < best) {
          best = d;
          from = &v;
        }
      }
      if (from == nullptr) continue;
      std::vector<Vec2>& way = visits[from->at][from->index];
      const std::vector<Vec2> more = way_to(way.back(), t);
      if (more.empty()) continue;
      way.insert(way.end(), more.begin(), more.end());
      pending[ti] = false;
      grew = true;
    }
  }
  if (!any) return;
  LinkedPath out = lp;
  out.pts.clear();
  out.kind.clear();
  out.jump.clear();
  out.entry.clear();
  for (std::size_t k = 0; k < lp.pts.size(); ++k) {
    out.pts.push_back(lp.pts[k]);
    for (const std::vector<Vec2>& way : visits[k]) {
      out.beyond_free.insert(out.beyond_free.end(), way.begin(), way.end());
      // As at the points pushed out of the walls: the move into the tip cuts by design.
      out.design_cut_ends.push_back(way.back());
      // There and back the same way.
      for (std::size_t q = 0; q < 2 * way.size(); ++q) {
        out.pts.push_back(q < way.size()           ? way[q]
                          : q + 1 < 2 * way.size() ? way[2 * way.size() - 2 - q]
                                                   : lp.pts[k]);
        out.kind.push_back(StepKind::kCut);
        out.jump.push_back(false);
        out.entry.push_back(-1);
      }
    }
    if (k + 1 < lp.pts.size()) {
      out.kind.push_back(lp.kind[k]);
      out.jump.push_back(lp.jump[k]);
      out.entry.push_back(lp.entry[k]);
    }
  }
  lp = std::move(out);
}

namespace {

// A step to `to` of the same kind, jump and entry as step i of lp, appended to out; and
// out's steps put in place of lp's (the points, kinds, jumps and entries, not the rest).
void append_step(LinkedPath& out, const LinkedPath& lp, std::size_t i, Vec2 to) {
  out.pts.push_back(to);
  out.kind.push_back(lp.kind[i]);
  out.jump.push_back(lp.jump[i]);
  out.entry.push_back(lp.entry[i]);
}
void take_steps(LinkedPath& lp, LinkedPath& out) {
  lp.pts = std::move(out.pts);
  lp.kind = std::move(out.kind);
  lp.jump = std::move(out.jump);
  lp.entry = std::move(out.entry);
}

}  // namespace

// Spurs (our addition). A pass ends against a wall; the way on steps back along it
// cutting nothing (a resume point, which sits half a step back from the material it faces,
// or Algorithm 4's boundary move), and the next cut turns round and goes out past where
// the pass ended. The L's channels beside the square island had one at each crossing's
// end: 0.15 mm back and 0.22 mm forward along the wall, two reversals of the heading within
// a few tenths of a millimetre, each a stop for the machine (92 such in the L's G-code, 39
// in a 40 x 12 mm channel's for a ø10). The step back is left out and the next cut
// starts where the pass ended: a move from there sweeps what the return sweeps beyond the
// spur's root, so the same material, with one turn instead of two. Only a one-step link
// between two cuts whose return turns by more than 150 degrees and passes its root, and
// only where the straight move keeps off the walls by exact geometry (as the output's
// chords are held).
void drop_spurs(const Model& m, LinkedPath& lp) {
  constexpr double kSpurCos = 0.866;  // cos 150 degrees
  const double reach = m.radius_mm + m.wall_stock_mm;
  LinkedPath out;
  out.pts.push_back(lp.pts.front());
  const std::size_t n = lp.kind.size();  // segments
  for (std::size_t i = 0; i < n; ++i) {
    if (i + 1 < n && i > 0 && lp.kind[i] == StepKind::kLink && !lp.jump[i] &&
        lp.kind[i - 1] == StepKind::kCut && !lp.jump[i - 1] && lp.kind[i + 1] == StepKind::kCut &&
        !lp.jump[i + 1]) {
      const Vec2 a = out.pts.back(), b = lp.pts[i + 1], c = lp.pts[i + 2];
      const Vec2 ab = b - a, bc = c - b;
      if (dot(ab, bc) < -kSpurCos * norm(ab) * norm(bc) && dot(c - a, a - b) > 0.0 &&
          m.walls.segment_distance(a, c) >= reach - 1e-7)
        continue;
    }
    append_step(out, lp, i, lp.pts[i + 1]);
  }
  take_steps(lp, out);
}

// Chords round a wall's offset (our addition). Points on a wall's exact offset keep
// kWallClearanceMm off it, but where the offset is an arc (round a convex corner of an
// island or of the outline) the straight move between two of them sags towards the wall
// by chord^2 / (8 x radius): 2.8 um for a 0.3 mm chord round a ø8's corner, 0.8 um into
// the island (the rectangle-with-an-island test pocket, with smooth links: the
// re-simulation counted two gouging steps; the output, as swept, was clear). Such a move
// gets midpoints put onto the offset, halving it until it keeps clear. On 29 pockets at
// 10 and 30 % (default flags) it changed 6 programs, none's band by more than 0.1 point.
void keep_chords_off_walls(const Model& m, LinkedPath& lp) {
  const double on = m.radius_mm + m.wall_stock_mm + kWallClearanceMm;
  const double reach = m.radius_mm + m.wall_stock_mm;
  // Most moves lie far from every wall by the pixels' clearance: those need no exact query
  // (it cost 8 % of the L's CPU on every move).
  auto clear = [&](Vec2 a, Vec2 b) { return keeps_off_walls(m, a, b, reach - 1e-9); };
  // The offset point nearest the middle of a and b, if it keeps clear of every wall.
  auto onto_offset = [&](Vec2 a, Vec2 b, Vec2& s) {
    const Vec2 mid = (a + b) * 0.5, foot = m.walls.nearest(mid);
    const double d = distance(mid, foot);
    if (d < 1e-9 || !m.walls.inside(mid)) return false;
    s = foot + (mid - foot) * (on / d);
    return m.walls.inside(s) && m.walls.distance(s) >= on - 1e-9;
  };
  LinkedPath out;
  out.pts.push_back(lp.pts.front());
  const std::size_t n = lp.kind.size();
  std::vector<Vec2> between;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = lp.pts[i], b = lp.pts[i + 1];
    between.clear();
    if (!lp.jump[i] && !clear(a, b) && m.walls.distance(a) >= reach - 1e-9 &&
        m.walls.distance(b) >= reach - 1e-9) {
      // Depth-first halving, left half first, so `between` comes out in path order.
      struct Piece {
        Vec2 a, b;
        int depth;
      };
      std::vector<Piece> todo{{a, b, 0}};
      while (!todo.empty()) {
        const Piece p = todo.back();
        todo.pop_back();
        Vec2 s;
        if (p.depth < 8 && !clear(p.a, p.b) && onto_offset(p.a, p.b, s)) {
          todo.push_back({s, p.b, p.depth + 1});
          todo.push_back({p.a, s, p.depth + 1});
        } else if (p.b != b) {
          between.push_back(p.b);
        }
      }
    }
    // Only moves that are no jump are split, so the pieces take step i's kind and entry (-1).
    for (const Vec2& v : between)
      append_step(out, lp, i, v);
    append_step(out, lp, i, b);
  }
  take_steps(lp, out);
}

}  // namespace swarf::pocket
