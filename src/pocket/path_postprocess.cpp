// Post-processing of the raw path (seed 000 section 6): cutting and non-cutting regions
// (Algorithm 6), trochoidal stacks (Algorithm 7), boundary groups (6.3), composition
// (Algorithm 8), gap patching with checked straight links and a boundary-following
// fallback (6.5), retracts where staying down is slower, Chaikin smoothing of the joins
// (6.6).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <queue>

#include "pocket/adaptive_internal.h"
#include "pocket/distance_transform.h"
#include "swarf/toolpath/postprocess.h"

namespace swarf::pocket {

namespace {

struct Region {
  std::size_t first = 0, last = 0;  // point indices; segments first..last-1
  bool cutting = false;
  int group = -1;
};

// seed 000 Algorithm 6.
std::vector<Region> segment_regions(const Model& m, const RawPath& raw) {
  std::vector<Region> out;
  const std::size_t n = raw.eng.size();
  std::size_t i = 0;
  while (i < n) {
    const bool cutting = raw.eng[i] > m.cut_px;
    std::size_t j = i;
    while (j < n && (raw.eng[j] > m.cut_px) == cutting)
      ++j;
    out.push_back({i, j, cutting, -1});
    i = j;
  }
  return out;
}

double distance_to_polyline(const std::vector<Vec2>& pts, const Region& r, Vec2 p) {
  double d = 1e300;
  for (std::size_t k = r.first; k < r.last; ++k) {
    const Vec2 a = pts[k], b = pts[k + 1];
    const Vec2 ab = b - a;
    const double l2 = norm_sq(ab);
    const double t = l2 > 0 ? std::clamp(dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    d = std::min(d, distance(p, a + ab * t));
  }
  return d;
}

// seed 000 Algorithm 7's parallel test: sample the region, compare the closest distances
// to the stack's top with the stepover.
bool parallel(const Model& m, const std::vector<Vec2>& pts, const Region& top, const Region& r) {
  const int samples = 7;
  int ok = 0;
  for (int s = 1; s <= samples; ++s) {
    const std::size_t k = r.first + (r.last - r.first) * s / (samples + 1);
    const double d = distance_to_polyline(pts, top, pts[k]);
    if (d > 0.5 * m.stepover_mm && d < 1.5 * m.stepover_mm + m.step_mm) ++ok;
  }
  return ok >= samples - 2;
}

struct Groups {
  int trochoid = 0;
  int boundary = 0;
};

// Algorithm 7 and section 6.3. A cutting region joins the stack of the cutting region
// just before it when parallel to its top; we do not search older stacks, so composing
// (Algorithm 8) never reorders cuts and the material state every later check sees is the
// one the raw path saw (the paper re-simulates and accepts the change).
Groups group_regions(const Model& m, const RawPath& raw, std::vector<Region>& regions) {
  Groups g;
  int last_cut = -1, last_boundary = -1;
  std::vector<std::size_t> top_cut, top_boundary;  // region index of each stack's top
  for (std::size_t k = 0; k < regions.size(); ++k) {
    Region& r = regions[k];
    if (r.cutting) {
      if (last_cut >= 0 && parallel(m, raw.pts, regions[top_cut[last_cut]], r)) {
        r.group = last_cut;
        top_cut[last_cut] = k;
      } else {
        r.group = g.trochoid++;
        top_cut.push_back(k);
      }
      last_cut = r.group;
    } else {
      // Overlapping boundary moves: the top's end points lie on this (longer) region.
      const double tol = m.step_mm + 2.0 * m.h;
      if (last_boundary >= 0) {
        const Region& top = regions[top_boundary[last_boundary]];
        if (distance_to_polyline(raw.pts, r, raw.pts[top.first]) < tol &&
            distance_to_polyline(raw.pts, r, raw.pts[top.last]) < tol) {
          r.group = last_boundary;
          continue;
        }
      }
      r.group = g.boundary++;
      top_boundary.push_back(k);
      last_boundary = r.group;
    }
  }
  return g;
}

// The sub-steps of a straight move from a to b (pieces of at most a path step): step(from,
// to) for each in order until it returns false; whether none did.
template <class Step>
bool for_substeps(const Model& m, Vec2 a, Vec2 b, Step&& step) {
  const int n = std::max(1, static_cast<int>(std::ceil(distance(a, b) / m.step_mm)));
  Vec2 prev = a;
  for (int k = 1; k <= n; ++k) {
    const Vec2 p = a + (b - a) * (static_cast<double>(k) / n);
    if (!step(prev, p)) return false;
    prev = p;
  }
  return true;
}

// A straight move from a to b in sub-steps: true when it never gouges and never takes more
// than the target engagement plus its tolerance (a link may graze the material front as it
// arrives at the next cut, but never overloads the tool). Changes nothing. Sub-steps see
// the stock as it was before the link: a link that would cut its own way is rejected
// anyway, so the error is on the safe side.
bool straight_ok(const Model& m, const PixelStock& stock, Vec2 a, Vec2 b) {
  return for_substeps(m, a, b, [&](Vec2 from, Vec2 to) {
    const int e = stock.probe(from, to);
    return e >= 0 && e <= (m.target_px + m.tol_px) * distance(from, to) / m.step_mm;
  });
}

// Whether a straight move from a to b would touch any material (probes only; the disk at a
// is clear, so the first contact shows in some sub-step's crescent).
bool grazes(const Model& m, const PixelStock& stock, Vec2 a, Vec2 b) {
  return !for_substeps(m, a, b, [&](Vec2 from, Vec2 to) { return stock.probe(from, to, 0) <= 0; });
}

// Whether the raw moves first..last removed no pixel at all.
bool region_removes_nothing(const RawPath& raw, std::size_t first, std::size_t last) {
  for (std::size_t q = first; q < last; ++q)
    if (raw.eng[q] > 0) return false;
  return true;
}

// Cuts the link from `from` through the points of `chain` (dense: at most a path step
// apart, the last one where the link must end) and appends to `out` the points as they
// were and to `lift` how far each was moved: off the wall it lies nearer than the tool
// radius, wall stock and Model::link_lift_mm, to that distance, where the disk there, grown
// by two pixels, holds no material (the pixels place the material's edge only to within a
// pixel, and a lifted link must not shave the front the next pass is to take) and the
// moves there and on stay off the walls. The points either side of a move that removes
// material stay where they are (what it takes, the link still takes). The lift changes by
// at most 1 in 2 of the way (27 degrees), and grows from nothing at either end (1 in 20
// took 0.4 points of the band on the PCB-vice bar at half the bench's pixel: it lifted
// less; at 1 in 5, until session 57, a link leaving a pass that ended on a wall ran its
// first half millimetre or so within the scallops' height of the wall, and the sweep read
// it cutting at 4-15 degrees: 0.6 % of the cutting length of a gear at ø10, 10 %, where
// 1 in 2 makes the band 94.2 -> 94.7 %). Our addition to seed 000's links (6.5).
void apply_lifted(const Model& m, PixelStock& stock, Vec2 from, const std::vector<Vec2>& chain,
                  std::vector<Vec2>& out, std::vector<Vec2>& lift) {
  constexpr double kSlope = 0.5;
  const double reach = m.radius_mm + m.wall_stock_mm;
  const std::size_t n = chain.size();
  if (n == 0) return;
  // The wall distance each point may be lifted to (its own where it may not be; infinity
  // where it lies far enough already, setting no limit to its neighbours'), then the slope
  // limit by a pass each way.
  constexpr double kFar = std::numeric_limits<double>::infinity();
  std::vector<double> d(n, 0.0), want(n, kFar), step(n, 0.0);
  std::vector<Vec2> foot(n);
  want[n - 1] = 0.0;
  // Whether the move into chain[k] removes material: asked once each (a point asks of the
  // moves either side, its neighbour of one of the same).
  std::vector<std::int8_t> removes(n, -1);
  // Whether the tool's disk at `cand`, grown by two pixels, holds material that is nearer
  // `cand` than `point`: what a lift from `point` to `cand` brings the link nearer to, such
  // as the front the next pass is to take. Material on the wall's side of the lift, the
  // scallops and skin the passes left there, only gets farther. Until session 63 any
  // material in the grown disk kept the point on the wall's offset, so beside the scallops
  // along a wall the link rode them at the cutting feed (random pocket 3001, ø10 at 40 %:
  // 82.8 -> 83.8 % within +-20 %).
  const double grown = m.radius_mm + 2.0 * m.h;
  const BitImage& material = stock.material();
  const auto meets_nearer_material = [&](Vec2 cand, Vec2 point) {
    if (stock.material_in_disk(cand, grown, 0) == 0) return false;
    // Pixel centres q nearer cand than point: dot(q - mid, u) > 0, u = cand - point.
    const Vec2 mid = m.grid.to_px(0.5 * (cand + point));
    const Vec2 u = cand - point;
    bool found = false;
    for_disk_rows(m.grid, cand, grown, [&](int j, int i0, int i1) {
      if (found) return;
      const double rest = (j - mid.y) * u.y;  // dot's part from the row
      if (std::abs(u.x) < 1e-12) {
        found = rest > 0.0 && material.count(j, i0, i1) > 0;
        return;
      }
      // Where the dot is 0 on this row, kept within the span (a nearly vertical u puts it
      // far beyond any int).
      const double x = std::clamp(mid.x - rest / u.x, i0 - 1.0, i1 + 1.0);
      if (u.x > 0.0) i0 = std::max(i0, static_cast<int>(std::floor(x)) + 1);
      if (u.x < 0.0) i1 = std::min(i1, static_cast<int>(std::ceil(x)) - 1);
      found = i0 <= i1 && material.count(j, i0, i1) > 0;
    });
    return found;
  };
  const auto removes_into = [&](std::size_t k) {
    if (removes[k] < 0)
      removes[k] = stock.probe(k == 0 ? from : chain[k - 1], chain[k], 0) != 0 ? 1 : 0;
    return removes[k] == 1;
  };
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 prev = k == 0 ? from : chain[k - 1];
    step[k] = distance(prev, chain[k]);
    if (k + 1 == n || m.walls.distance(chain[k]) >= reach + m.link_lift_mm) continue;
    foot[k] = m.walls.nearest(chain[k]);
    d[k] = distance(chain[k], foot[k]);
    want[k] = d[k];
    if (d[k] < 1e-9 || removes_into(k) || removes_into(k + 1)) continue;
    const Vec2 unit = (chain[k] - foot[k]) / d[k];
    // The whole lift, else half of it, else a quarter: three tries, counted (a test of the
    // lift left against a quarter of the whole never failed where the point lay within
    // 4e-12 mm of the full lift, and random pocket 6032 hung there).
    const double full = reach + m.link_lift_mm;
    double to_d = full;
    for (int t = 0; t < 3; ++t, to_d = d[k] + 0.5 * (to_d - d[k])) {
      const Vec2 cand = foot[k] + unit * to_d;
      if (m.walls.distance(cand) >= to_d - 1e-9 && !meets_nearer_material(cand, chain[k])) {
        want[k] = to_d;
        break;
      }
    }
  }
  // As a lift above the point's own distance: 0 at either end and wherever no lift may be.
  std::vector<double> up(n, 0.0);
  for (std::size_t k = 0; k < n; ++k)
    up[k] = want[k] == kFar ? kFar : want[k] - d[k];
  double carry = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    carry = std::min(up[k], carry + kSlope * step[k]);
    up[k] = carry;
  }
  carry = 0.0;
  for (std::size_t k = n; k-- > 0;) {
    up[k] = std::min(up[k], carry);
    carry = up[k] + kSlope * step[k];
  }
  Vec2 at = from;
  for (std::size_t k = 0; k < n; ++k) {
    Vec2 to = chain[k];
    if (up[k] > 1e-9 && up[k] < kFar) {
      const double to_d = d[k] + up[k];
      const Vec2 cand = foot[k] + (chain[k] - foot[k]) * (to_d / d[k]);
      // The move there comes no nearer a wall than the reach, or than the point it leaves
      // where that is nearer: the raw path's points along a wall lie up to a few microns
      // inside the reach (snap_to_wall_offset puts them on the offset later), and asking
      // the reach of the move out of such a point failed every lift along a wall. The link
      // rode the offset at the cutting feed, grazing the scallops there: random pocket 723
      // (ø6 at 10 %), 27 mm along a wall at 0-7 degrees by the sweep, the band 92.9 -> 93.7 %.
      if (m.walls.distance(cand) >= to_d - 1e-9 &&
          m.walls.segment_distance(at, cand) >=
              std::min(reach + kWallClearanceMm, m.walls.distance(at)) - 1e-9 &&
          !meets_nearer_material(cand, chain[k]) && stock.probe(at, cand, 0) == 0)
        to = cand;
    }
    stock.cut(at, to);
    out.push_back(chain[k]);
    lift.push_back(to - chain[k]);
    at = to;
  }
}

// The sub-step points of the straight moves from `from` through `pts`.
std::vector<Vec2> substeps_through(const Model& m, Vec2 from, const std::vector<Vec2>& pts) {
  std::vector<Vec2> chain;
  for (const Vec2& p : pts) {
    for_substeps(m, from, p, [&](Vec2, Vec2 to) {
      chain.push_back(to);
      return true;
    });
    from = p;
  }
  return chain;
}

// Shortens the boundary-following fallback (seed 000 6.5) by pulling it taut: from each
// point, the farthest later point of the raw path reachable by a checked straight move
// (exponential then binary search). Raw steps themselves are always acceptable.
// Returns the kept indices after `first`; checks only, the caller cuts.
std::vector<std::size_t> pull_taut(const Model& m, const PixelStock& stock,
                                   const std::vector<Vec2>& pts, std::size_t first,
                                   std::size_t last) {
  std::vector<std::size_t> out;
  std::size_t cur = first;
  while (cur < last) {
    std::size_t good = cur + 1, step = 2;
    std::size_t bad = last + 1;
    while (cur + step <= last) {
      if (straight_ok(m, stock, pts[cur], pts[cur + step])) {
        good = cur + step;
        step *= 2;
      } else {
        bad = cur + step;
        break;
      }
    }
    if (bad == last + 1 && good != last && straight_ok(m, stock, pts[cur], pts[last])) {
      good = last;
    } else {
      std::size_t lo = good, hi = std::min(bad, last + 1);
      while (hi - lo > 1) {
        const std::size_t mid = (lo + hi) / 2;
        if (straight_ok(m, stock, pts[cur], pts[mid])) {
          lo = mid;
        } else {
          hi = mid;
        }
      }
      good = lo;
    }
    out.push_back(good);
    cur = good;
  }
  return out;
}

// A keep-down way from a to b over floor already cleared, for a resume elsewhere (a jump of
// the raw path) that the straight link cannot make: the shortest 8-connected chain of tool
// centres whose disks hold no material (within a pixel) and touch no wall, by A* on every
// stride-th pixel of the grid (a sixth of the tool radius apart) within a window round a
// and b, then pulled taut, every pulled move checked as a straight link is. Our addition:
// seed 000 links only straight or along the raw path, and a resume has no raw path to
// follow, so every resume the straight link missed was a retract and a plunge (about 4.7 per
// pocket on 49 random pockets, seeds 950-998). Empty when there is none, or none shorter
// than max_len_mm.
std::vector<Vec2> cleared_way(const Model& m, const PixelStock& stock, Vec2 a, Vec2 b,
                              double max_len_mm) {
  const double r_px = m.radius_mm / m.h;
  const double reach_px = 0.5 * distance(a, b) / m.h + 4.0 * r_px;
  const Vec2 pa = m.grid.to_px(a), pb = m.grid.to_px(b);
  // The window: pixels [i0, i1] x [j0, j1].
  const int i0 = std::max(0, static_cast<int>(std::floor(std::min(pa.x, pb.x) - reach_px)));
  const int i1 =
      std::min(m.grid.width - 1, static_cast<int>(std::ceil(std::max(pa.x, pb.x) + reach_px)));
  const int j0 = std::max(0, static_cast<int>(std::floor(std::min(pa.y, pb.y) - reach_px)));
  const int j1 =
      std::min(m.grid.height - 1, static_cast<int>(std::ceil(std::max(pa.y, pb.y) + reach_px)));
  // Centres within a tool radius less a pixel of material: the ends' own disks touch the
  // material front (a cut ends there, the next begins); the pulled moves' checks decide.
  // Only the material in the window and a radius round it counts. Asked node by node as the
  // search reaches it, and remembered per node: dilating the whole stock at every search was
  // 4 % of a ø6 pocket's time with 13 resumes, and dilating the window a fifth of the L's
  // CPU with --one-way, whose links go back along each pass.
  const BitImage& mat = stock.material();
  const int pad = static_cast<int>(std::ceil(r_px)) + 1;
  const int wi0 = std::max(0, i0 - pad), wj0 = std::max(0, j0 - pad);
  const int wi1 = std::min(m.grid.width - 1, i1 + pad), wj1 = std::min(m.grid.height - 1, j1 + pad);
  const std::vector<int> half = disk_half_widths(r_px - 1.0);
  const auto near_material = [&](int i, int j) {
    return !half.empty() && near_set_pixel(mat, half, i, j, wi0, wj0, wi1, wj1);
  };
  // The search on every stride-th pixel: (i0 + stride u, j0 + stride v), u < nu, v < nv.
  auto search = [&](int stride) -> std::vector<Vec2> {
    const int nu = (i1 - i0) / stride + 1, nv = (j1 - j0) / stride + 1;
    const auto node_of = [&](Vec2 p) {
      const int u = std::clamp(static_cast<int>(std::lround((p.x - i0) / stride)), 0, nu - 1);
      const int v = std::clamp(static_cast<int>(std::lround((p.y - j0) / stride)), 0, nv - 1);
      return static_cast<std::size_t>(v) * static_cast<std::size_t>(nu) +
             static_cast<std::size_t>(u);
    };
    const std::size_t start = node_of(pa), goal = node_of(pb);
    const auto uv = [&](std::size_t n) {
      return std::pair<int, int>{static_cast<int>(n % static_cast<std::size_t>(nu)),
                                 static_cast<int>(n / static_cast<std::size_t>(nu))};
    };
    const int gu = uv(goal).first, gv = uv(goal).second;
    std::vector<std::int8_t> known(static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv), -1);
    const auto passable = [&](int u, int v) {
      std::int8_t& k = known[static_cast<std::size_t>(v) * static_cast<std::size_t>(nu) +
                             static_cast<std::size_t>(u)];
      if (k < 0) {
        const int i = i0 + stride * u, j = j0 + stride * v;
        k = static_cast<double>(m.clearance_sq[m.grid.index(i, j)]) > r_px * r_px &&
                    !near_material(i, j)
                ? 1
                : 0;
      }
      return k == 1;
    };
    // Octile distance to the goal, in nodes: exact on an empty grid, so A* stays narrow.
    const auto estimate = [&](int u, int v) {
      const int du = std::abs(u - gu), dv = std::abs(v - gv);
      return static_cast<float>(std::max(du, dv)) +
             0.41421356F * static_cast<float>(std::min(du, dv));
    };
    std::vector<float> cost(static_cast<std::size_t>(nu) * static_cast<std::size_t>(nv),
                            std::numeric_limits<float>::infinity());
    std::vector<std::int32_t> parent(cost.size(), -1);
    using Node = std::pair<float, std::size_t>;  // estimate, node (ties: the lower index)
    std::priority_queue<Node, std::vector<Node>, std::greater<>> open;
    cost[start] = 0.0F;
    open.push({estimate(uv(start).first, uv(start).second), start});
    const auto limit = static_cast<float>(max_len_mm / (m.h * stride));
    constexpr std::array<std::array<int, 2>, 8> kSteps = {
        {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}}};
    bool found = false;
    while (!open.empty()) {
      const auto [f, at] = open.top();
      open.pop();
      if (at == goal) {
        found = true;
        break;
      }
      const auto [u, v] = uv(at);
      if (f > cost[at] + estimate(u, v) + 1e-3F) continue;  // a stale entry
      for (const auto& s : kSteps) {
        const int nu2 = u + s[0], nv2 = v + s[1];
        if (nu2 < 0 || nu2 >= nu || nv2 < 0 || nv2 >= nv) continue;
        const std::size_t n = static_cast<std::size_t>(nv2) * static_cast<std::size_t>(nu) +
                              static_cast<std::size_t>(nu2);
        if (n != goal && !passable(nu2, nv2)) continue;
        const float c = cost[at] + (s[0] != 0 && s[1] != 0 ? 1.41421356F : 1.0F);
        if (c >= cost[n] || c + estimate(nu2, nv2) > limit) continue;
        cost[n] = c;
        parent[n] = static_cast<std::int32_t>(at);
        open.push({c + estimate(nu2, nv2), n});
      }
    }
    if (!found) return {};
    std::vector<Vec2> chain{b};
    for (std::int32_t k = parent[goal]; k >= 0; k = parent[static_cast<std::size_t>(k)]) {
      const auto [u, v] = uv(static_cast<std::size_t>(k));
      chain.push_back(m.grid.to_world(i0 + stride * u, j0 + stride * v));
    }
    if (chain.size() < 2) return {};
    chain.back() = a;  // the start node stands for a itself
    std::reverse(chain.begin(), chain.end());
    std::vector<Vec2> way;
    double len = 0.0;
    Vec2 from = a;
    for (std::size_t k : pull_taut(m, stock, chain, 0, chain.size() - 1)) {
      if (!straight_ok(m, stock, from, chain[k])) return {};
      len += distance(from, chain[k]);
      from = chain[k];
      way.push_back(from);
    }
    if (len > max_len_mm) return {};
    return way;
  };
  // A sixth of the radius apart, and where that finds no way, a third of that: between two
  // islands the clear centres may be a strip narrower than the coarse stride, and the tool
  // lifted for a hop of a few millimetres (random pocket 977, ø3: three of its five lifts;
  // seeds 950-998: 78 -> 62).
  const int coarse = std::max(1, static_cast<int>(r_px / 6.0));
  std::vector<Vec2> way = search(coarse);
  if (way.empty() && coarse >= 3) way = search(coarse / 3);
  return way;
}

}  // namespace

void simplify_indices(const std::vector<Vec2>& pts, std::size_t first, std::size_t last, double tol,
                      std::vector<std::size_t>& keep,
                      const std::function<bool(std::size_t, std::size_t)>& chord_ok) {
  // Iterative Douglas-Peucker (no recursion depth limit on long paths).
  std::vector<std::pair<std::size_t, std::size_t>> stack{{first, last}};
  std::vector<bool> kept(last - first + 1, false);
  kept.front() = kept.back() = true;
  while (!stack.empty()) {
    const auto [a, b] = stack.back();
    stack.pop_back();
    double worst = -1.0;
    std::size_t at = a;
    const Vec2 pa = pts[a], pb = pts[b];
    const Vec2 ab = pb - pa;
    const double l2 = norm_sq(ab);
    for (std::size_t k = a + 1; k < b; ++k) {
      const double t = l2 > 0 ? std::clamp(dot(pts[k] - pa, ab) / l2, 0.0, 1.0) : 0.0;
      const double d = distance(pts[k], pa + ab * t);
      if (d > worst) {
        worst = d;
        at = k;
      }
    }
    if (worst <= tol && b > a + 1 && chord_ok && !chord_ok(a, b)) {
      at = a + (b - a) / 2;  // within the tolerance but too near a wall: split in the middle
      worst = tol + 1.0;
    }
    if (worst > tol) {
      kept[at - first] = true;
      stack.push_back({a, at});
      stack.push_back({at, b});
    }
  }
  for (std::size_t k = first; k <= last; ++k)
    if (kept[k - first]) keep.push_back(k);
}

LinkedPath postprocess(const Model& m, const std::vector<Entry>& entries, const RawPath& raw,
                       const LinkCosts& costs) {
  const Entry& entry = entries.front();
  LinkedPath out;
  std::vector<Region> regions = segment_regions(m, raw);
  const Groups groups = group_regions(m, raw, regions);
  out.trochoid_groups = groups.trochoid;
  out.boundary_groups = groups.boundary;
  // Algorithm 8 (as printed it marks T_stack[t.group]; r.group is meant) composes the cutting
  // regions (whole trochoid stacks, in order, see group_regions) with the first region of each
  // boundary group; the gaps it leaves are patched (6.5). We patch every gap between two cutting
  // regions the same way: a straight link, checked against walls (gouge) and material (it must not
  // cut) on the stock as it is at that moment, else the raw boundary-following path between them
  // (safe by construction), or a retract when that is faster than staying down.
  PixelStock stock = fresh_stock(m);
  cut_entry(stock, m, entry);
  out.pts.push_back(raw.pts.front());
  // Raw moves as they are; a jump among them stays a jump (a retract, or a new entry), not a
  // straight move at depth: a region that holds a new entry and, after it, another jump
  // (the entry's own session cut nothing) had its later jump turned into a move through
  // uncut material, a slot in the final path.
  auto append_raw = [&](std::size_t first, std::size_t last, bool link) {
    for (std::size_t k = first; k < last; ++k) {
      if (raw.jump[k]) {
        if (raw.entry[k] >= 0) {
          cut_entry(stock, m, entries[static_cast<std::size_t>(raw.entry[k])]);
        } else {
          stock.stamp(raw.pts[k + 1]);
        }
      } else {
        stock.cut(raw.pts[k], raw.pts[k + 1]);
      }
      out.pts.push_back(raw.pts[k + 1]);
      out.kind.push_back(link || raw.jump[k] ? StepKind::kLink : raw.kind[k]);
      out.jump.push_back(raw.jump[k]);
      out.entry.push_back(raw.jump[k] ? raw.entry[k] : -1);
    }
  };
  std::vector<std::pair<std::size_t, std::size_t>> joins;  // out point index ranges to smooth
  // Link points at depth after out point `before`; a join to smooth unless `smooth_join` is
  // false.
  // Link points moved off the walls (apply_lifted): out point index, how far. Added after
  // the smoothing of the joins, which sees the links as they were: the lift changes the
  // link's length, and the smoothed window is resampled by length, so the passes' last
  // and first cuts either side would move (by up to 0.07 mm on the PCB-vice bar, 1.3
  // points of the band).
  std::vector<std::pair<std::size_t, Vec2>> lifts;
  auto append_link = [&](const std::vector<Vec2>& pts, std::size_t before, bool smooth_join,
                         const std::vector<Vec2>& lift = {}) {
    for (std::size_t k = 0; k < lift.size(); ++k)
      if (lift[k].x != 0.0 || lift[k].y != 0.0) lifts.push_back({out.pts.size() + k, lift[k]});
    for (Vec2 p : pts) {
      out.pts.push_back(p);
      out.kind.push_back(StepKind::kLink);
      out.jump.push_back(false);
      out.entry.push_back(-1);
    }
    if (smooth_join) joins.push_back({before, out.pts.size() - 1});
  };
  for (std::size_t k = 0; k < regions.size(); ++k) {
    const Region& r = regions[k];
    const bool between_cuts = !r.cutting && k > 0 && k + 1 < regions.size();
    if (!between_cuts) {
      // Cutting regions, and a non-cutting head (moves from the entry to the material).
      append_raw(r.first, r.last, false);
      continue;
    }
    const Vec2 a = raw.pts[r.first], b = raw.pts[r.last];
    const std::size_t before = out.pts.size() - 1;
    bool has_jump = false;
    for (std::size_t q = r.first; q < r.last; ++q)
      has_jump = has_jump || raw.jump[q];
    // A new entry: lift, enter there, then the raw moves to the next cut. Every entry of the
    // region is made, in order: an entry whose session cut nothing more still cut its hole
    // or its ramp in the raw path's stock, and the moves after it were chosen on that stock.
    // Before, only the region's last entry was: random pocket 2010 (ø6) lost a ramp along a
    // channel 0.24 mm wider than the tool, and the final path cut the channel in a full slot
    // (5.8 mm).
    std::size_t fresh = r.last;
    for (std::size_t q = r.first; q < r.last; ++q) {
      if (!raw.jump[q] || raw.entry[q] < 0) continue;
      fresh = q;
      cut_entry(stock, m, entries[static_cast<std::size_t>(raw.entry[q])]);
      out.pts.push_back(raw.pts[q + 1]);
      out.kind.push_back(StepKind::kLink);
      out.jump.push_back(true);
      out.entry.push_back(raw.entry[q]);
    }
    if (fresh < r.last) {
      append_raw(fresh + 1, r.last, true);
      continue;
    }
    std::vector<Vec2> link;
    // With smooth_links, a straight link that would turn back on either cut is flown as a
    // loop over the cleared floor where one fits (smooth_link.cpp); the steps either side
    // give the cuts' headings. Only where the raw moves between cut nothing at all: what
    // they cut, the loop (which cuts nothing) would leave. The loop is already smooth, so
    // its joins are not Chaikin-cut (that would pull them towards the walls).
    if (m.smooth_links && r.first > 0 && r.last + 1 < raw.pts.size() && !raw.jump[r.first - 1] &&
        !raw.jump[r.last] && region_removes_nothing(raw, r.first, r.last) &&
        smooth_link(m, stock, raw.pts[r.first - 1], a, b, raw.pts[r.last + 1], link)) {
      append_link(link, before, false);
      continue;
    }
    std::vector<Vec2> lift;
    if (straight_ok(m, stock, a, b)) {
      apply_lifted(m, stock, a, substeps_through(m, a, {b}), link, lift);
      append_link(link, before, true, lift);
      continue;
    }
    // Fallback: the raw boundary-following path, pulled taut, unless a retract is faster.
    std::vector<std::size_t> taut;
    if (!has_jump) taut = pull_taut(m, stock, raw.pts, r.first, r.last);
    double taut_len = 0.0;
    Vec2 q0 = a;
    for (std::size_t q : taut) {
      taut_len += distance(q0, raw.pts[q]);
      q0 = raw.pts[q];
    }
    // Both in minutes: the way round at the link feed, or at the cutting feed where it
    // grazes material (such a way is cutting length at a few degrees, out of the band, so it
    // is weighed as before links went at the link feed); a retract as the output makes it.
    // Whether it grazes is probed only when that decides.
    const double lift_s = retract_minutes(costs, distance(a, b));
    if (has_jump) {
      // A resume: a way over the cleared floor, when it is no more than three times
      // slower than lifting over (the rule below).
      const std::vector<Vec2> way =
          cleared_way(m, stock, a, b, 3.0 * lift_s * costs.link_feed_mm_min);
      if (!way.empty()) {
        std::vector<Vec2> pts;
        apply_lifted(m, stock, a, substeps_through(m, a, way), pts, lift);
        append_link(pts, before, true, lift);
        continue;
      }
    }
    bool retract = has_jump || 3.0 * lift_s < taut_len / costs.link_feed_mm_min;
    if (!retract && 3.0 * lift_s < taut_len / costs.feed_mm_min) {
      q0 = a;
      for (std::size_t q : taut) {
        retract = retract || grazes(m, stock, q0, raw.pts[q]);
        q0 = raw.pts[q];
      }
    }
    // Keep the tool down where that is safe (seed 000 6.5); retract only when the way
    // round is more than three times slower than lifting over.
    if (retract) {
      stock.stamp(b);
      out.pts.push_back(b);
      out.kind.push_back(StepKind::kLink);
      out.jump.push_back(true);
      out.entry.push_back(-1);
    } else {
      std::vector<Vec2> corners;
      corners.reserve(taut.size());
      for (std::size_t q : taut)
        corners.push_back(raw.pts[q]);
      std::vector<Vec2> pts;
      apply_lifted(m, stock, a, substeps_through(m, a, corners), pts, lift);
      append_link(pts, before, true, lift);
    }
  }
  // Chaikin smoothing of each straight link with a few points of the cuts on either side
  // (seed 000 6.6); a smoothed window that would gouge is left as it was.
  const std::size_t w = 4;
  std::vector<Vec2> smoothed = out.pts;
  const PixelStock walls = fresh_stock(m);  // gouge test only (forbidden pixels)
  for (const auto& [j0, j1] : joins) {
    const std::size_t a = j0 >= w ? j0 - w : 0;
    const std::size_t b = std::min(out.pts.size() - 1, j1 + w);
    bool clean = true;
    for (std::size_t k = a; k < b; ++k)
      clean = clean && !out.jump[k];
    if (!clean || b <= a + 2) continue;
    std::vector<Vec2> win(out.pts.begin() + static_cast<std::ptrdiff_t>(a),
                          out.pts.begin() + static_cast<std::ptrdiff_t>(b) + 1);
    std::vector<Vec2> sm = chaikin_smooth(win, costs.smoothing_iterations);
    // Resample back to the window's point count so kinds stay aligned.
    std::vector<double> cum{0.0};
    for (std::size_t k = 1; k < sm.size(); ++k)
      cum.push_back(cum.back() + distance(sm[k - 1], sm[k]));
    std::vector<double> wcum{0.0};
    for (std::size_t k = 1; k < win.size(); ++k)
      wcum.push_back(wcum.back() + distance(win[k - 1], win[k]));
    std::vector<Vec2> res(win.size());
    std::size_t seg = 0;
    for (std::size_t k = 0; k < win.size(); ++k) {
      const double t = wcum.back() > 0 ? wcum[k] / wcum.back() * cum.back() : 0.0;
      while (seg + 2 < sm.size() && cum[seg + 1] < t)
        ++seg;
      const double l = cum[seg + 1] - cum[seg];
      const double u = l > 0 ? std::clamp((t - cum[seg]) / l, 0.0, 1.0) : 0.0;
      res[k] = sm[seg] + (sm[seg + 1] - sm[seg]) * u;
    }
    // Check the vertices and points a pixel apart along the new segments (a chord can cut
    // a convex corner its ends clear).
    bool ok = true;
    for (std::size_t k = 0; k < res.size() && ok; ++k) {
      ok = !walls.gouges(res[k]);
      if (k == 0) continue;
      const int n = static_cast<int>(distance(res[k - 1], res[k]) / m.h);
      for (int q = 1; q < n && ok; ++q)
        ok = !walls.gouges(res[k - 1] + (res[k] - res[k - 1]) * (static_cast<double>(q) / n));
    }
    if (ok) {
      for (std::size_t k = 0; k < res.size(); ++k)
        smoothed[a + k] = res[k];
    }
  }
  out.pts = std::move(smoothed);
  for (const auto& [k, off] : lifts)
    out.pts[k] = out.pts[k] + off;
  return out;
}

}  // namespace swarf::pocket
