// Rides along the walls over the scallops the adaptive path left on them (our addition).
//
// A front that grows outwards meets a wall at an angle and turns back; the next front meets
// it one stepover further on. Between two such arrivals the wall keeps a scallop of height
// R - sqrt(R^2 - (ae / (2 sin alpha))^2) (docs/pocket.md, session 11): 0.03 mm for a ø10 at
// 10 % stepover, 0.67 mm for a ø16 at 40 % meeting the wall square. The move chooser does
// not go back for them: each is less than the smallest cut it counts as one (cut_px), so
// the sessions that find them end as idle and are dropped. Seed 000 has no such pass. A
// machinist finishing to size expects the walls clean, so where the re-simulated stock
// keeps material higher than `scallop_mm` against a wall, the tool takes it off: a dab
// square to the wall where the scallop is narrower than the tool, else a ride along the
// wall's tool-centre offset (wall on the right for climb milling), each a visit from the
// last pass that comes near it. A pocket whose scallops stay lower gets none.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdlib>
#include <map>
#include <vector>

#include "pocket/adaptive_internal.h"
#include "pocket/geometry.h"
#include "swarf/polygon/polygon.h"

namespace swarf::pocket {
namespace {

struct RingPlace {
  std::size_t ring = 0;
  double s = 0.0;  ///< arc length from the ring's first vertex
};

struct Rings {
  std::vector<Ring> rings;
  std::vector<std::vector<double>> at;  ///< per ring, arc length at each vertex (and the end)

  explicit Rings(std::vector<Ring> r) : rings(std::move(r)) {
    for (const Ring& ring : rings) {
      std::vector<double> a(1, 0.0);
      for (std::size_t k = 0; k < ring.size(); ++k)
        a.push_back(a.back() + distance(ring[k], ring[(k + 1) % ring.size()]));
      at.push_back(std::move(a));
    }
  }
  double length(std::size_t r) const { return at[r].back(); }
  RingPlace nearest(Vec2 p, double& dist) const {
    RingPlace best;
    dist = 1e300;
    for (std::size_t r = 0; r < rings.size(); ++r) {
      for (std::size_t k = 0, n = rings[r].size(); k < n; ++k) {
        const Vec2 a = rings[r][k], b = rings[r][(k + 1) % n];
        const Vec2 q = nearest_on_segment(p, a, b);
        const double d = distance(p, q);
        if (d < dist) {
          dist = d;
          best = {r, at[r][k] + distance(a, q)};
        }
      }
    }
    return best;
  }
  Vec2 point(std::size_t r, double s) const {
    const double len = length(r);
    s = std::fmod(s, len);
    if (s < 0.0) s += len;
    const std::vector<double>& a = at[r];
    const std::size_t k =
        static_cast<std::size_t>(std::upper_bound(a.begin(), a.end(), s) - a.begin()) - 1;
    const std::size_t n = rings[r].size();
    const Vec2 p = rings[r][k % n], q = rings[r][(k + 1) % n];
    const double e = a[k + 1] - a[k];
    return e > 0.0 ? p + (q - p) * ((s - a[k]) / e) : p;
  }
  /// The points of ring r from arc length s0 forwards to s1 (s1 >= s0, may pass the end).
  std::vector<Vec2> stretch(std::size_t r, double s0, double s1) const {
    std::vector<Vec2> out{point(r, s0)};
    const double len = length(r);
    const std::size_t n = rings[r].size();
    for (int lap = 0; lap < 2; ++lap) {
      for (std::size_t k = 0; k < n; ++k) {
        const double s = at[r][k] + lap * len;
        if (s > s0 && s < s1) out.push_back(rings[r][k]);
      }
    }
    out.push_back(point(r, s1));
    return out;
  }
};

// 8-connected groups of the pixels listed in `px` (grid indices, sorted).
std::vector<std::vector<std::size_t>> groups(const std::vector<std::size_t>& px, int width) {
  std::vector<int> group(px.size(), -1);
  std::vector<std::vector<std::size_t>> out;
  std::vector<std::size_t> todo;
  const auto w = static_cast<std::size_t>(width);
  for (std::size_t seed = 0; seed < px.size(); ++seed) {
    if (group[seed] >= 0) continue;
    const int g = static_cast<int>(out.size());
    out.emplace_back();
    group[seed] = g;
    todo.assign(1, seed);
    while (!todo.empty()) {
      const std::size_t k = todo.back();
      todo.pop_back();
      out.back().push_back(px[k]);
      const auto i = static_cast<long>(px[k] % w), j = static_cast<long>(px[k] / w);
      for (long nj = j - 1; nj <= j + 1; ++nj) {
        for (long ni = i - 1; ni <= i + 1; ++ni) {
          if (ni < 0 || nj < 0 || ni >= width || (ni == i && nj == j)) continue;
          const std::size_t q = static_cast<std::size_t>(nj) * w + static_cast<std::size_t>(ni);
          const auto it = std::lower_bound(px.begin(), px.end(), q);
          if (it == px.end() || *it != q) continue;
          const auto n = static_cast<std::size_t>(it - px.begin());
          if (group[n] >= 0) continue;
          group[n] = g;
          todo.push_back(n);
        }
      }
    }
  }
  return out;
}

struct Ride {
  std::vector<Vec2> pts;     ///< a dab: from the cleared floor to the wall; else along it
  bool dab = false;          ///< the way back out is the way in
  std::vector<Vec2> pixels;  ///< centres of the material it takes
};

}  // namespace

bool ride_walls_over_scallops(const Model& m, const PixelStock& after, double scallop_mm,
                              LinkedPath& lp) {
  if (scallop_mm <= 0.0 || lp.pts.empty()) return false;
  const double reach = m.radius_mm + m.wall_stock_mm;
  // The material left, as grid indices, keeping what a tool riding a wall can reach.
  std::vector<std::size_t> px;
  const BitImage& left = after.material();
  for (int j = 0; j < left.height(); ++j) {
    for (int w = 0; w < left.words_per_row(); ++w) {
      for (std::uint64_t bits = left.word(j, w); bits != 0; bits &= bits - 1) {
        const int i = 64 * w + std::countr_zero(bits);
        if (m.walls.distance(m.grid.to_world(i, j)) < reach) px.push_back(m.grid.index(i, j));
      }
    }
  }
  if (px.empty()) return false;
  std::sort(px.begin(), px.end());
  const Rings rings(offset(m.region, -(reach + kWallClearanceMm)).rings);
  std::vector<Ride> rides;
  const auto w = static_cast<std::size_t>(m.grid.width);
  auto centre = [&](std::size_t q) {
    return m.grid.to_world(static_cast<int>(q % w), static_cast<int>(q / w));
  };
  const double covers = m.radius_mm - 0.5 * m.h;  // a pixel centre this near is cut
  for (const std::vector<std::size_t>& g : groups(px, m.grid.width)) {
    double height = 0.0;
    for (std::size_t q : g)
      height = std::max(height, m.walls.distance(centre(q)) - m.wall_stock_mm);
    if (height < scallop_mm || height > m.stepover_mm) continue;
    // Where on the tool-centre offset each pixel is nearest, per ring: the stretch of the
    // ring from which the tool reaches all of them. Only scallops: a group thicker than a
    // stepover, or with pixels out of reach of a tool on the wall's offset, is stock left
    // for another reason (a chamber the tool may not enter), and taking it in one ride
    // would cut more than the target.
    std::map<std::size_t, std::vector<std::pair<double, Vec2>>> on_ring;
    bool scallop = true;
    for (std::size_t q : g) {
      double d = 0.0;
      const RingPlace place = rings.nearest(centre(q), d);
      scallop = scallop && d < m.radius_mm + m.h;
      on_ring[place.ring].push_back({place.s, centre(q)});
    }
    if (!scallop) continue;
    for (auto& [r, at] : on_ring) {
      std::sort(at.begin(), at.end(),
                [](const auto& x, const auto& y) { return x.first < y.first; });
      const double len = rings.length(r);
      double gap = at.front().first + len - at.back().first;
      std::size_t first = 0;
      for (std::size_t k = 1; k < at.size(); ++k) {
        if (at[k].first - at[k - 1].first > gap) {
          gap = at[k].first - at[k - 1].first;
          first = k;
        }
      }
      double s0 = at[first].first, s1 = at[(first + at.size() - 1) % at.size()].first;
      if (s1 < s0) s1 += len;
      // A scallop narrower than the tool is taken by a dab: straight at the wall from the
      // cleared floor, square to it, and back (under a millimetre of cutting, where a ride
      // along the wall would graze it over its width plus the tool's chord at that depth).
      // Up to three dabs side by side; a longer run of material gets the ride.
      std::vector<Vec2> dabs;
      for (int n = 1; n <= 3 && dabs.empty(); ++n) {
        for (int k = 0; k < n; ++k)
          dabs.push_back(rings.point(r, s0 + (s1 - s0) * (k + 0.5) / n));
        for (const auto& [sq, c] : at) {
          bool cut = false;
          for (const Vec2& d : dabs)
            cut = cut || distance(c, d) < covers;
          if (!cut) {
            dabs.clear();
            break;
          }
        }
      }
      std::vector<Ride> these;
      for (const Vec2& d : dabs) {
        const Vec2 out = normalized(d - m.walls.nearest(d));
        const Vec2 start = d + out * (height + 2.0 * m.h);
        if (m.walls.segment_distance(start, d) < reach - 1e-7) {
          these.clear();
          break;
        }
        these.push_back(Ride{{start, d}, true, {}});
      }
      if (these.empty()) {
        const double margin = std::min(m.step_mm, 0.5 * std::max(0.0, len - (s1 - s0)));
        Ride ride{rings.stretch(r, s0 - margin, s1 + margin), false, {}};
        // The rings run with the pocket on their left (the wall on the right), which is
        // climb milling with an M3 spindle; conventional rides the other way.
        if (m.sigma > 0) std::reverse(ride.pts.begin(), ride.pts.end());
        these.push_back(std::move(ride));
      }
      for (Ride& ride : these) {
        for (const auto& [sq, c] : at)
          ride.pixels.push_back(c);
        rides.push_back(std::move(ride));
      }
    }
  }
  if (rides.empty()) return false;
  // Each ride's points with those it goes through to keep off the walls (a ride along an
  // island's offset: the chords of its round joins).
  for (Ride& ride : rides) {
    std::vector<Vec2> pts{ride.pts.front()};
    for (std::size_t k = 1; k < ride.pts.size(); ++k) {
      keep_off_walls(m.walls, reach, kWallClearanceMm, ride.pts[k - 1], ride.pts[k], pts);
      pts.push_back(ride.pts[k]);
    }
    ride.pts = std::move(pts);
    lp.design_cut_ends.insert(lp.design_cut_ends.end(), ride.pts.begin() + 1, ride.pts.end());
  }
  // Whether the moves from a through `way` stay in the pocket and off the walls.
  auto keeps_clear = [&](Vec2 a, const std::vector<Vec2>& way) {
    for (std::size_t k = 0; k < way.size(); ++k) {
      if (!m.walls.inside(way[k]) ||
          m.walls.segment_distance(k == 0 ? a : way[k - 1], way[k]) < reach - 1e-7)
        return false;
    }
    return true;
  };
  // The way from a to b over the cleared floor: straight, or round the walls in its way
  // (points pushed off them), b last; empty when neither keeps off the walls.
  auto way_between = [&](Vec2 a, Vec2 b) {
    std::vector<Vec2> way;
    keep_off_walls(m.walls, reach, kWallClearanceMm, a, b, way);
    way.push_back(b);
    return keeps_clear(a, way) ? way : std::vector<Vec2>{};
  };
  // The same, kept Model::link_lift_mm off the walls between its ends: the way runs over
  // the cleared floor at the link feed, and along a wall's exact offset it grazed the skin
  // that the passes leave there (random pocket 2033, ø16 at 40 %: a way round a convex
  // corner of the wall to a dab, there and back, took 0.06 mm^2 at 2-5 degrees by the sweep once
  // the passes riding a wall were snapped from a pixel off instead of 1.25). Each end steps square
  // off its wall to the lift first (where the room is there); the plain way where the lifted one
  // does not keep off the walls.
  const double lifted = reach + kWallClearanceMm + m.link_lift_mm;
  auto lift_off = [&](Vec2 p) {
    const double d = m.walls.distance(p);
    if (d >= lifted || d < 1e-9) return p;
    const Vec2 foot = m.walls.nearest(p);
    const Vec2 q = foot + (p - foot) * (lifted / d);
    return m.walls.inside(q) && m.walls.distance(q) >= lifted - 1e-7 ? q : p;
  };
  auto lifted_way = [&](Vec2 a, Vec2 b) {
    const Vec2 a1 = lift_off(a), b1 = lift_off(b);
    std::vector<Vec2> way;
    if (distance(a1, a) > 0.0) way.push_back(a1);
    keep_off_walls(m.walls, lifted - kWallClearanceMm, kWallClearanceMm, a1, b1, way);
    if (distance(b1, b) > 0.0) way.push_back(b1);
    way.push_back(b);
    return keeps_clear(a, way) ? way : way_between(a, b);
  };
  // Each ride as a visit from the last move of the path whose tool comes within two pixels
  // of the material it takes, there and back from that move's point nearest to it: no later
  // move comes near, so the material there is what the path leaves, and the tool is next to
  // it (no link across the pocket, no retract). A ride with no way there joins a tour after
  // the path's end.
  struct Visit {
    std::size_t segment = 0;  ///< split segment (pts[k] -> pts[k + 1]); size(): after the end
    double t = 0.0;           ///< where along it
    std::vector<Vec2> way;
  };
  std::vector<Visit> visits;
  std::vector<Ride> tour;
  const std::size_t segments = lp.kind.size();
  for (Ride& ride : rides) {
    // Segment k's tool disk comes within two pixels of the material the ride takes.
    Box2 box;
    for (const Vec2& p : ride.pixels)
      box.add(p);
    const double touch = m.radius_mm + 2.0 * m.h;
    auto near = [&](std::size_t k) {
      const Vec2 a = lp.jump[k] ? lp.pts[k + 1] : lp.pts[k], b = lp.pts[k + 1];
      if (std::min(a.x, b.x) > box.max.x + touch || std::max(a.x, b.x) < box.min.x - touch ||
          std::min(a.y, b.y) > box.max.y + touch || std::max(a.y, b.y) < box.min.y - touch)
        return false;
      for (const Vec2& p : ride.pixels) {
        if (point_segment_distance(p, a, b) < touch) return true;
      }
      return false;
    };
    Visit v;
    bool found = false;
    for (std::size_t k = segments; k-- > 0 && !found;) {
      if (!near(k)) continue;
      found = true;
      // A jump is in the air: the visit starts where it lands.
      v.segment = lp.jump[k] ? k + 1 : k;
      if (!lp.jump[k]) {
        const Vec2 a = lp.pts[k], b = lp.pts[k + 1];
        const double len2 = norm_sq(b - a);
        v.t = len2 > 0.0 ? std::clamp(dot(ride.pts.front() - a, b - a) / len2, 0.0, 1.0) : 0.0;
        if (v.t > 1.0 - 1e-9) {  // at the segment's end: from there, not from a copy of it
          v.segment = k + 1;
          v.t = 0.0;
        }
      }
    }
    const Vec2 from = v.segment < segments
                          ? lp.pts[v.segment] + (lp.pts[v.segment + 1] - lp.pts[v.segment]) * v.t
                          : lp.pts.back();
    if (found) v.way = lifted_way(from, ride.pts.front());
    if (!v.way.empty()) v.way.insert(v.way.end(), ride.pts.begin() + 1, ride.pts.end());
    if (v.way.empty()) {
      tour.push_back(std::move(ride));
    } else {
      visits.push_back(std::move(v));
    }
  }
  if (!visits.empty()) {
    std::stable_sort(visits.begin(), visits.end(), [](const Visit& x, const Visit& y) {
      return x.segment != y.segment ? x.segment < y.segment : x.t < y.t;
    });
    LinkedPath out = lp;
    out.pts.assign(1, lp.pts.front());
    out.kind.clear();
    out.jump.clear();
    out.entry.clear();
    auto add = [&](Vec2 p, StepKind kind, bool jump, int entry) {
      out.pts.push_back(p);
      out.kind.push_back(kind);
      out.jump.push_back(jump);
      out.entry.push_back(entry);
    };
    std::size_t next = 0;
    for (std::size_t k = 0; k <= segments; ++k) {
      for (; next < visits.size() && visits[next].segment == k; ++next) {
        const Visit& v = visits[next];
        Vec2 from = out.pts.back();
        if (k < segments && v.t > 0.0) {
          from = lp.pts[k] + (lp.pts[k + 1] - lp.pts[k]) * v.t;
          add(from, lp.kind[k], false, -1);
        }
        for (const Vec2& p : v.way)
          add(p, StepKind::kCut, false, -1);
        out.beyond_free.insert(out.beyond_free.end(), v.way.begin(), v.way.end());
        for (std::size_t q = v.way.size() - 1; q-- > 0;)
          add(v.way[q], StepKind::kCut, false, -1);
        add(from, StepKind::kCut, false, -1);
      }
      if (k < segments) add(lp.pts[k + 1], lp.kind[k], lp.jump[k], lp.entry[k]);
    }
    lp = std::move(out);
  }
  rides = std::move(tour);
  // The rest from where the tool is, nearest first: a straight link over the cleared floor
  // where it keeps off the walls, else a retract.
  auto push = [&](Vec2 p, StepKind kind, bool jump) {
    lp.pts.push_back(p);
    lp.kind.push_back(kind);
    lp.jump.push_back(jump);
    lp.entry.push_back(-1);
  };
  std::vector<bool> done(rides.size(), false);
  for (std::size_t n = 0; n < rides.size(); ++n) {
    const Vec2 at = lp.pts.back();
    std::size_t next = 0;
    double best = 1e300;
    for (std::size_t k = 0; k < rides.size(); ++k) {
      if (!done[k] && distance(at, rides[k].pts.front()) < best) {
        best = distance(at, rides[k].pts.front());
        next = k;
      }
    }
    done[next] = true;
    const std::vector<Vec2>& pts = rides[next].pts;
    const std::vector<Vec2> way = lifted_way(at, pts.front());
    if (!way.empty()) {
      for (const Vec2& v : way)
        push(v, StepKind::kLink, false);
    } else if (after.material_in_disk(pts.front(), m.radius_mm + m.h, 0) == 0) {
      // A retract comes down there: only where no material is left under the tool.
      push(pts.front(), StepKind::kLink, true);
    } else {
      continue;  // no way there but down into material
    }
    for (std::size_t k = 1; k < pts.size(); ++k)
      push(pts[k], StepKind::kBoundary, false);
    if (rides[next].dab) {
      push(pts.front(), StepKind::kBoundary, false);
      lp.beyond_free.insert(lp.beyond_free.end(), pts.begin(), pts.end());
    }
  }
  return true;
}

}  // namespace swarf::pocket
