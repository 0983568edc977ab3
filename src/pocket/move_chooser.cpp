// The move chooser of seed 000 sections 4.3 and 5: Algorithms 3 (best cutting move with
// early returns), 4 (boundary-following move) and 5 (both together), run until the tool
// has gone a whole boundary round without cutting.
//
// Angles are integer degrees in the paper's frame, where turning by +theta turns towards
// the material (material on the left, the paper's scan from -theta_max upwards). For climb
// milling the frame is mirrored: the actual turn is sigma * theta.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "pocket/adaptive_internal.h"

namespace swarf::pocket {

namespace {

struct Candidate {
  Vec2 p;
  int eng = PixelStock::kGouge;
  int theta = 0;
  bool valid = false;
};

class Chooser {
 public:
  Chooser(const Model& m, const PixelStock& stock) : m_(m), stock_(stock) {
    for (int d = -180; d <= 180; ++d) {
      cos_[d + 180] = std::cos(deg_to_rad(d));
      sin_[d + 180] = std::sin(deg_to_rad(d));
    }
  }

  void set_state(Vec2 pos, Vec2 dir, double step) {
    memo_.fill(kUnprobed);
    pos_ = pos;
    dir_ = dir;
    step_ = step;
  }

  // seed 000 Algorithm 1 GetEngagement: the point one step away, turned by theta.
  // Memoised per step: Algorithms 3 and 4 look at the same candidates.
  Candidate get(int theta) const {
    const int t = m_.sigma * theta;
    const double c = cos_[t + 180], s = sin_[t + 180];
    const Vec2 d{dir_.x * c - dir_.y * s, dir_.x * s + dir_.y * c};
    Candidate k;
    k.p = pos_ + d * step_;
    int& memo = memo_[theta + 180];
    if (memo == kUnprobed) {
      // The tool's disk at pos_ is free (it has been there), so the crescent's count is
      // the whole disk's. Beyond twice the target a candidate is never chosen and only
      // compares as "more than the target" (best_delta <= target): no exact count needed.
      memo = stock_.probe_disk(k.p, static_cast<int>(2.0 * m_.target_px) + 1);
      // A long (non-cutting) step also checks its inner points: a chord between two free
      // centres can clip a convex corner of an island.
      for (double u = m_.step_mm; memo >= 0 && u < step_ - 1e-9; u += m_.step_mm)
        if (stock_.gouges(pos_ + d * u)) memo = PixelStock::kGouge;
    }
    k.eng = memo;
    k.theta = theta;
    return k;
  }

  // seed 000 Algorithm 3, started at the previous turn rather than at -theta_max: the
  // engagement grows with theta near the solution, so walking from the last turn towards
  // the target finds the crossing in a few degrees instead of up to 2 theta_max + 1 probes
  // (our change, for speed and for continuity of curvature). The walk probes every
  // kStride degrees and fills in the skipped ones only round the crossing (a one-degree
  // walk cost about 20 probes a step on the benchmark pocket). When the walk reaches the end
  // of the range without nearing the target it walks the other way (below); when that
  // fails too, or at a gouge, the paper's full scan decides; taking the move nearest the
  // gouge instead cost 15 points of the +-20 % share. Longer strides without the fill-in
  // (doubling, then bisection) jump over the engagement's peak (it is unimodal in theta,
  // not monotonic) and find the far crossing: a worse path.
  Candidate best_move(int start) const {
    const double tar = m_.target_px;
    double best_delta = tar;
    Candidate best;
    auto consider = [&](const Candidate& k) {
      if (k.eng < 0) return false;
      const double delta = std::abs(k.eng - tar);
      if (delta < best_delta) {
        best_delta = delta;
        best = k;
      }
      return delta < m_.tol_px;
    };
    const int tm = m_.theta_max_deg;
    start = std::clamp(start, -tm, tm);
    Candidate k = get(start);
    if (consider(k)) return valid(k);
    // The one-degree walk of the paper's order, probed every kStride degrees: when a
    // strided probe is in the band, past the target or a gouge, the degrees skipped since
    // the last probe are walked one by one, so the move is the walk's move wherever the
    // engagement is monotonic over kStride degrees. kFound puts the move in `found`;
    // kExhausted: the end of the range, without meeting the target or a gouge.
    const bool above = k.eng > tar;
    Candidate found;
    enum class Walk { kFound, kGouge, kExhausted };
    auto walk = [&](int dir) {
      const int end = dir > 0 ? tm : -tm;
      int lo = start;
      while (lo != end) {
        int t = lo + dir * kStride;
        if ((t - end) * dir > 0) t = end;
        const Candidate n = get(t);
        const bool event = n.eng < 0 || std::abs(n.eng - tar) < m_.tol_px || (n.eng > tar) != above;
        if (!event) {
          consider(n);
          lo = t;
          continue;
        }
        for (int u = lo + dir; u != t + dir; u += dir) {
          const Candidate w = get(u);
          if (w.eng < 0) return Walk::kGouge;
          if (consider(w)) {
            found = valid(w);
            return Walk::kFound;
          }
          if ((w.eng > tar) != above) {  // crossed the target
            found = valid(best);
            return Walk::kFound;
          }
        }
        lo = t;
      }
      return Walk::kExhausted;
    };
    if (k.eng >= 0) {
      // Turning by +theta turns towards the material, so the engagement is expected to
      // approach the target in this direction.
      const Walk w = walk(above ? -1 : 1);
      if (w == Walk::kFound) return found;
      // Our change: the range ended without the engagement even approaching the target.
      // The material lies on the tool's other side (along a wall the tool reached against
      // its milling direction), so the engagement runs the other way with theta: walk the
      // other way. Left to Algorithm 3's scan below, whose early stop assumes the usual
      // direction, this case took the move back into the wall at twice the target every
      // second step, a zigzag along the wall (random pockets at 40 % stepover: 65 % of the
      // cut within +-20 %, FreeCAD's adaptive clearing 82 %). Test:
      // AdaptivePocket.HighStepoverAlongAWallReachedAgainstTheMillingDirection.
      if (w == Walk::kExhausted && walk(above ? 1 : -1) == Walk::kFound) return found;
    }
    // Algorithm 3's scan from -theta_max with its early returns, at 5 degree strides
    // (probes are the cost of the whole method), then refined to 1 degree round the best.

    best_delta = tar;
    best = Candidate{};
    auto scan = [&](int from, int to, int stride) {
      for (int t = from; t <= to; t += stride) {
        const Candidate n = get(t);
        const double delta = n.eng < 0 ? tar + 1.0 : std::abs(n.eng - tar);
        if (delta < m_.tol_px) return n;
        if (delta < best_delta) {
          best_delta = delta;
          best = n;
        }
        if (best_delta < tar && delta > best_delta) break;
      }
      Candidate none;
      none.eng = PixelStock::kGouge - 1;
      return none;
    };
    Candidate hit = scan(-tm, tm, 5);
    if (hit.eng >= 0) return valid(hit);
    if (best_delta < tar) {
      const int c = best.theta;
      hit = scan(std::max(-tm, c - 4), std::min(tm, c + 4), 1);
      if (hit.eng >= 0) return valid(hit);
    }
    best.valid = best_delta < tar;
    return best;
  }

  // seed 000 Algorithm 4, generalised: the transition is between a gouge and any
  // non-gouging move (the paper asks for engagement exactly 0, which fails when the
  // wall-side move still grazes material), and we take the transition nearest to the
  // previous turn (searching outwards, the paper's wall side first) instead of the first
  // one from -theta_max: the same move when the tool hugs a wall, found in a few probes.
  Candidate boundary_move(int start) const {
    const int tm = m_.theta_max_deg;
    start = std::clamp(start, -tm, tm);
    const Candidate k = get(start);
    const bool k_gouges = k.eng < 0;
    // Probed every kStride degrees on both sides; the window since the last stride is
    // searched degree by degree (the outward order above) only when a stride probe shows
    // a transition or a side leaves the range: the same move wherever the gouge/free
    // state does not flip and flip back within kStride degrees.
    auto flips = [&](int t) { return t >= -tm && t <= tm && (get(t).eng < 0) != k_gouges; };
    for (int top = kStride; top - kStride < 2 * tm; top += kStride) {
      const bool edge = start - top < -tm || start + top > tm;
      if (!edge && !flips(start + top) && !flips(start - top)) continue;
      for (int d = top - kStride + 1; d <= top; ++d) {
        const int lo = start - d, hi = start + d;
        if (k_gouges) {
          if (hi <= tm && get(hi).eng >= 0) return valid(get(hi));
          if (lo >= -tm && get(lo).eng >= 0) return valid(get(lo));
        } else {
          if (lo >= -tm && get(lo).eng < 0) return valid(get(lo + 1));
          if (hi <= tm && get(hi).eng < 0) return valid(get(hi - 1));
        }
        if (lo < -tm && hi > tm) return Candidate{};
      }
    }
    return Candidate{};  // no wall within reach
  }

  // The least-engaging move that still cuts, counted exactly (no cap): for when no move
  // within theta_max is near the target (each cuts nothing or more than twice as much).
  Candidate least_cutting_move() const {
    Candidate best;
    int best_eng = 0;
    for (int t = -m_.theta_max_deg; t <= m_.theta_max_deg; ++t) {
      Candidate k = get(t);
      if (k.eng < 0 || k.eng <= m_.cut_px) continue;
      const int exact = stock_.probe_disk(k.p);
      if (!best.valid || exact < best_eng) {
        best = valid(k);
        best.eng = exact;
        best_eng = exact;
      }
    }
    return best;
  }

 private:
  static Candidate valid(Candidate k) {
    k.valid = true;
    return k;
  }
  const Model& m_;
  const PixelStock& stock_;
  static constexpr int kUnprobed = -2;
  static constexpr int kStride = 4;
  Vec2 pos_, dir_;
  double step_ = 0.0;
  mutable std::array<int, 361> memo_{};
  std::array<double, 361> cos_{}, sin_{};
};

}  // namespace

namespace {

struct IdleCut {
  std::size_t step;  // index in RawPath::eng of the move that removed the pixel
  int i, j;
};

void record_idle_cut(void* user, int i, int j) {
  static_cast<std::vector<IdleCut>*>(user)->push_back({0, i, j});
}

// The material in the tool's disk at b, split by the line of the move a -> b: on the side
// the milling direction wants it (the right for climb, sigma -1) and on the other.
struct Sides {
  int right = 0, wrong = 0;
};
Sides material_sides(const Model& m, const PixelStock& stock, Vec2 a, Vec2 b) {
  const BitImage& mat = stock.material();
  const Vec2 d = b - a;
  const Vec2 q = m.grid.to_px(a);
  int left = 0, right = 0;
  for_disk_rows(m.grid, b, m.radius_mm, [&](int j, int i0, int i1) {
    const double dy = j - q.y;
    if (std::abs(d.y) < 1e-12) {
      // A horizontal move: the whole row lies on one side.
      const int n = mat.count(j, i0, i1);
      (d.x * dy > 0.0 ? left : right) += n;
      return;
    }
    // Columns with i < xs lie on the left when the move goes up (d.y > 0).
    const double xs = q.x + d.x * dy / d.y;
    const int split = static_cast<int>(std::ceil(xs)) - 1;  // last column below xs
    const int lo_end = std::min(i1, split), hi_start = std::max(i0, split + 1);
    const int below = lo_end >= i0 ? mat.count(j, i0, lo_end) : 0;
    const int above = hi_start <= i1 ? mat.count(j, hi_start, i1) : 0;
    if (d.y > 0.0) {
      left += below;
      right += above;
    } else {
      left += above;
      right += below;
    }
  });
  Sides s;
  s.right = m.sigma < 0 ? right : left;
  s.wrong = m.sigma < 0 ? left : right;
  return s;
}

}  // namespace

Result<RawPath> generate_raw_path(const Model& m, PixelStock& stock, std::vector<Entry>& entries,
                                  const Context& ctx) {
  const Entry entry = entries.front();
  std::vector<bool> used(entries.size(), false);
  used[0] = true;
  // Material given up on (no resume point reaches it); tried again from a new entry once
  // nothing else is left.
  BitImage given_up(m.grid.width, m.grid.height);
  CentreComponents components;  // labelled when a new entry first needs them
  auto give_up = [&](int i, int j) { given_up.set(i, j, true); };
  EntryAxis axis;  // medial axis, computed when first needed
  // A new entry must take at least one straight step's worth of material to be worth its
  // retract and its plunge, helix or ramp.
  const int entry_min_px = std::max(1, static_cast<int>(std::ceil(m.target_px)));
  // Whether a move's contact arc reaches kSlotDeg: the front half of a circle just outside
  // the tool (whose own disk at `at` is cleared) sampled every two degrees, from the sides
  // inwards, stopping as soon as enough samples miss the material (most moves: a few).
  // A sample in a wall or island counts as contact: where the tool rides tangent to one, the
  // material reaches the tangent point, and the circle outside the tool runs a few degrees
  // through the wall there. The independent sweep counts a slot from 170 degrees; the test
  // stops at 160, because its samples read the arc up to 15 degrees short: a ø20 going
  // through a neck 0.33 mm wider than itself read 166 degrees here at its worst step and 180
  // by the sweep, 1.8 mm of full slot (random pocket 810; the 98 pockets of seeds 500-548 and
  // 800-848 had 21 mm of slot, 6.5 mm after, most of it first moves out of a straight plunge
  // and tip visits into wedges narrower than the tool, where every way in is a slot).
  constexpr double kSlotDeg = 160.0;
  constexpr int kSamples = 90, kMayMiss = kSamples - static_cast<int>(kSlotDeg / 2.0);
  const double ring_px = (m.radius_mm + 0.5 * m.h) / m.h;
  auto slot_like = [&](Vec2 at, Vec2 d) {
    const Vec2 q = m.grid.to_px(at);
    const double base = std::atan2(d.y, d.x);
    int missed = 0;
    for (int s = 0; s < kSamples; ++s) {
      const int k = (s % 2 == 0 ? -1 : 1) * (89 - 2 * (s / 2));  // -89, 89, -87, 87, ...
      const double a = base + deg_to_rad(k);
      const int i = round_half_away(q.x + ring_px * std::cos(a));
      const int j = round_half_away(q.y + ring_px * std::sin(a));
      const bool hit = i >= 0 && j >= 0 && i < m.grid.width && j < m.grid.height &&
                       (stock.material().get(i, j) || stock.forbidden().get(i, j));
      if (!hit && ++missed > kMayMiss) return false;
    }
    return true;
  };
  auto give_up_disk = [&](Vec2 c) {
    for_disk_rows(m.grid, c, m.radius_mm, [&](int j, int i0, int i1) {
      for (int i = i0; i <= i1; ++i)
        if (stock.material().get(i, j)) give_up(i, j);
    });
  };
  RawPath raw;
  // The pixels removed by the idle moves of the raw path (each with its step's index).
  // Only idle moves are ever dropped (drop_steps_from), and dropping them puts their pixels
  // back: the stock must be what the kept path leaves. Before (session 16), up to cut_px
  // pixels per dropped move stayed cut in the stock but not on the machine, and nothing
  // went back for those crumbs (random pocket 24 with 0.3 mm of wall stock: 1.3 mm^2 in
  // crescents beside a round island).
  std::vector<IdleCut> idle_cuts;
  // Keeps the first `kept` steps of the raw path, giving the stock back what the others cut.
  auto drop_steps_from = [&](std::size_t kept) {
    while (!idle_cuts.empty() && idle_cuts.back().step >= kept) {
      const IdleCut& q = idle_cuts.back();
      if (m.walls.distance(m.grid.to_world(q.i, q.j)) > m.wall_stock_mm + kWallCrumbMm)
        stock.restore(q.i, q.j);
      idle_cuts.pop_back();
    }
    raw.eng.resize(kept);
    raw.kind.resize(kept);
    raw.jump.resize(kept);
    raw.entry.resize(kept);
    raw.pts.resize(kept + 1);
  };
  // Clears `given_up` in the disk of `radius_mm` round `c`: that material is tried again.
  auto reopen_disk = [&](Vec2 c, double radius_mm) {
    for_disk_rows(m.grid, c, radius_mm, [&](int j, int i0, int i1) { given_up.clear(j, i0, i1); });
  };
  Chooser chooser(m, stock);
  Vec2 pos = entry.start;
  Vec2 dir{std::cos(entry.start_angle_rad), std::sin(entry.start_angle_rad)};
  raw.pts.push_back(pos);
  const double reach = m.radius_mm + m.step_mm + m.h;
  const double far_reach = m.radius_mm + 3.0 * m.step_mm + m.h;
  const std::size_t max_steps =
      static_cast<std::size_t>(8.0 * m.pocket_area_mm2 / (m.stepover_mm * m.step_mm) +
                               20.0 * m.boundary_round_mm / m.step_mm + 1000.0);
  bool resumed = false;
  // Short sessions in a row (at most kCreepSteps moves) that the no-slot rule ended within a
  // tool diameter of each other: a channel about as wide as the tool, where every way on is
  // a slot and each resume creeps a step or two further (part-like pocket 2130: a ø8 in a
  // channel 0.17 mm wider than itself took 0.25 mm per session, and the 200 sessions ran
  // out with a 15 mm wide channel elsewhere never reached, 790 mm^2 left). From the sixth,
  // the session may cut the slot: nothing narrower fits there. Not sooner: through a short
  // neck the creep gets through by itself (random pocket 39: a ø8 between a round island
  // and the wall 8.1 mm apart got through after four such sessions; allowed from the third,
  // it cut 2.0 mm of slot there). Longer sessions do not count (without that limit random
  // pocket 529 cut 1.6 mm of slot it had avoided).
  int slot_run = 0;
  constexpr int kCreepSessions = 6;
  constexpr std::size_t kCreepSteps = 8;  // a session this short that the rule ends: creeping
  Vec2 last_slot{1e300, 1e300};
  std::size_t before_session = 0;
  int last_i = 0, last_j = 0;
  std::size_t iterations = 0;  // bounds the loop even when shortcuts shorten the path
  // One way: the pass under way began at pass_start, with pass_start_px removed before it.
  // A pass resumed by the one-way rule that ends by it again having removed less than
  // kShortPassSteps target steps gives up the material it was aimed at (one_way_i, _j);
  // after kMostShortPasses of those in a row, or with no resume, the wrong-way move is
  // made, and the rule rests until one_way_rest_until.
  constexpr double kShortPassSteps = 3.0;
  constexpr int kMostShortPasses = 3;
  std::size_t one_way_rest_until = 0;
  int short_passes = 0, one_way_i = 0, one_way_j = 0;
  bool one_way_resumed = false;
  Vec2 pass_start = pos;
  double removed_px = 0.0, pass_start_px = 0.0;
  // A jump of the raw path (linked, retracted or entered later) to `at`, facing `d`: a new
  // pass starts there. `entry_index`: the new entry made there, or -1 for a resume.
  auto push_jump = [&](Vec2 at, Vec2 d, int entry_index) {
    raw.eng.push_back(0);
    raw.kind.push_back(StepKind::kLink);
    raw.jump.push_back(true);
    raw.entry.push_back(entry_index);
    raw.pts.push_back(at);
    pos = at;
    dir = d;
    pass_start = at;
    pass_start_px = removed_px;
  };
  // Sessions (the moves from an entry or a resume until nothing near is left) are bounded
  // against a resume that keeps finding the same spot. The bound grows with the disks the
  // pocket holds: a pocket of many chambers, each behind necks narrower than the tool (a
  // plate of islands closer than a diameter), takes a dozen sessions each, entry and
  // resumes round its islands; a bound of 200 in all left most chambers of such a plate
  // uncut (8 x 6 islands ø6 at 15 mm apart, a ø10: 7162 mm^2 the tool reaches, session 53).
  const int max_sessions =
      200 + 16 * static_cast<int>(std::ceil(m.pocket_area_mm2 / (kPi * m.radius_mm * m.radius_mm)));
  for (int session = 0; session < max_sessions; ++session) {
    const bool allow_slot = slot_run >= kCreepSessions;
    bool ended_by_slot = false;
    int last_theta = 0;
    double idle_mm = 0.0;
    const double shortcut_mm = 2.0 * m.radius_mm;
    double next_shortcut_mm = shortcut_mm;
    bool shortcut_pending = false, cut_since_shortcut = false;
    int short_i = 0, short_j = 0;
    std::size_t reopened_tail = 0;  // the last cut whose front was reopened
    // A resume within the session: the jump, and the session's walk state starts afresh.
    auto jump_to = [&](Vec2 at, Vec2 d) {
      push_jump(at, d, -1);
      idle_mm = 0.0;
      next_shortcut_mm = shortcut_mm;
      last_theta = 0;
    };
    while (raw.eng.size() < max_steps && ++iterations < max_steps) {
      if ((raw.eng.size() & 1023u) == 0 && ctx.cancelled())
        return Status(Error::kCancelled, "adaptive pocket cancelled");
      // seed 000 Algorithm 5. Skip the cutting search when no material is within reach,
      // and then take boundary steps of up to 3 x delta_step as long as no material is
      // within reach of the longer step either (it cuts nothing, so only its smoothness
      // matters; the paper's conclusion suggests adaptive step lengths).
      Candidate c;
      StepKind kind = StepKind::kCut;
      const bool near = stock.material_in_disk(pos, reach, 0) > 0;
      const bool far_clear = !near && stock.material_in_disk(pos, far_reach, 0) == 0;
      chooser.set_state(pos, dir, far_clear ? 3.0 * m.step_mm : m.step_mm);
      if (near) c = chooser.best_move(last_theta);
      if (!c.valid) {
        c = chooser.boundary_move(last_theta);
        kind = StepKind::kBoundary;
        if (!c.valid) {
          // Neither: open space all round. Go straight until something is met (our
          // addition; the paper's strategy would stop here).
          c = chooser.get(0);
          kind = StepKind::kLink;
          if (c.eng < 0) break;
        }
        // Our addition: neither fallback looks at what lies ahead. Algorithm 4 follows the
        // boundary, and where the room between an island and a wall is narrower than about
        // one stepover the boundary runs through uncut material: a full slot round the
        // island. With no wall within reach the straight move goes on whatever it cuts: out
        // of a neck about as wide as the tool into uncut material every move within
        // theta_max cuts nothing or more than twice the target (random pocket seed 541, ø12
        // through a neck with 0.28 mm of room: 2.3 mm at 145-177 degrees). When the fallback
        // would cut above the band, nibble instead with the move that cuts least, if it
        // takes clearly less (10 %; a near tie only perturbs the path). It costs path length
        // there; on the benchmark pockets it also lowers the largest engagement (L 133 -> 106
        // deg, Kiri:Moto 83 -> 65 deg). Tests:
        // AdaptivePocket.IslandsLessThanAMillimetreFromTheWalls,
        // RandomPocketWhereTheToolLeavesANeckIntoUncutMaterial.
        if (near && c.eng > m.target_px + m.tol_px) {
          const Candidate l = chooser.least_cutting_move();
          if (l.valid && l.eng < 0.9 * stock.probe_disk(c.p)) {
            c = l;
            kind = StepKind::kCut;
          }
        }
      }
      // One way (our addition; AdaptiveParams::one_way): a move that takes half a target
      // step or more, two thirds of it or more on the wrong side of its line (the left for
      // climb), ends the pass. Seed 000's chooser takes the move nearest the target whichever
      // side the material is on, so where a pass ends against a wall the next comes back as
      // a conventional pass, with a reversal between (the L: 68 % climb by the sweep). The
      // next pass starts instead where the material nearest the start of this one begins
      // (trace_front_upstream), facing along the front; the jump there is linked over the cleared
      // floor or retracted by post-processing, as a resume is.
      if (m.one_way && c.eng > 0.5 * m.target_px && raw.eng.size() >= one_way_rest_until) {
        const Sides sd = material_sides(m, stock, pos, c.p);
        if (sd.wrong > 2 * sd.right) {
          if (one_way_resumed && removed_px - pass_start_px < kShortPassSteps * m.target_px) {
            give_up_disk(m.grid.to_world(one_way_i, one_way_j));
            ++short_passes;
          } else {
            short_passes = 0;
          }
          Vec2 at, d;
          int si = 0, sj = 0;
          // The material near the pass's start first (the next strip beside it), then any.
          const bool found =
              short_passes < kMostShortPasses &&
              (find_resume(m, stock, pass_start, at, d, si, sj, given_up, 2.0 * m.radius_mm) ||
               find_resume(m, stock, pass_start, at, d, si, sj, given_up));
          if (found) {
            Vec2 along = perp(d) * static_cast<double>(-m.sigma);  // along the front
            trace_front_upstream(m, stock, at, along);
            jump_to(at, along);
            one_way_resumed = true;
            one_way_i = si;
            one_way_j = sj;
            continue;
          }
          one_way_rest_until =
              raw.eng.size() + static_cast<std::size_t>(2.0 * m.radius_mm / m.step_mm);
          short_passes = 0;
          one_way_resumed = false;
        }
      }
      // Our addition: no full slot outside an entry. A move whose contact arc reaches
      // kSlotDeg is not taken: it goes into the tip of a wedge narrower than the tool
      // (between an island and a wall, or two walls), where every way in has material on
      // both sides. The session ends there and what the move would have cut is given up
      // for now, to be taken from a new entry (find_entry_for_material below) once nothing
      // else is left.
      if (!allow_slot && slot_like(pos, c.p - pos)) {
        give_up_disk(c.p);
        ended_by_slot = true;
        const bool creeping = raw.eng.size() <= before_session + 1 + kCreepSteps;
        const bool same_place = distance(c.p, last_slot) < 2.0 * m.radius_mm;
        slot_run = !creeping ? 0 : same_place ? slot_run + 1 : 1;
        last_slot = c.p;
        break;
      }
      // An idle move (cutting at most cut_px) may be dropped below with the idle tail; the
      // pixels it removed are kept so that they can be put back then (a probe's count is
      // the cut's, so c.eng says beforehand which moves to record).
      const bool may_drop = c.eng <= m.cut_px;
      const std::size_t idle_before = idle_cuts.size();
      const int removed =
          may_drop ? stock.cut(pos, c.p, &record_idle_cut, &idle_cuts) : stock.cut(pos, c.p);
      if (removed > m.cut_px) {
        idle_cuts.resize(idle_before);
      } else {
        for (std::size_t k = idle_before; k < idle_cuts.size(); ++k)
          idle_cuts[k].step = raw.eng.size();
      }
      removed_px += removed;
      raw.eng.push_back(removed);
      raw.kind.push_back(kind);
      raw.jump.push_back(false);
      raw.entry.push_back(-1);
      raw.pts.push_back(c.p);
      dir = normalized(c.p - pos);
      pos = c.p;
      last_theta = kind == StepKind::kLink ? 0 : c.theta;
      // Termination (seed 000 4.1): a whole boundary round without cutting.
      idle_mm = removed > m.cut_px ? 0.0 : idle_mm + distance(raw.pts[raw.pts.size() - 2], pos);
      if (idle_mm > m.boundary_round_mm) break;
      // Shortcut (our addition): once the tool has followed the boundary for a while
      // without cutting, look for material near the end of the last cut; when some is
      // reachable from cleared space, drop the idle moves and resume there. Saves most of
      // the boundary rounds of Algorithm 4 that post-processing would throw away.
      // The idle walk that counts starts at the last cut: without this reset, each failed
      // try pushed the next one 2 R further for the rest of the session, and once the
      // fronts were farther apart than that, none was tried again.
      if (removed > m.cut_px) {
        cut_since_shortcut = true;
        next_shortcut_mm = shortcut_mm;
      }
      if (idle_mm > next_shortcut_mm) {
        next_shortcut_mm = idle_mm + shortcut_mm;
        // A shortcut that led to no cutting: give up on that pixel, go on following.
        if (shortcut_pending && !cut_since_shortcut) give_up(short_i, short_j);
        shortcut_pending = false;
        std::size_t tail = raw.eng.size();
        while (tail > 0 && raw.eng[tail - 1] <= m.cut_px && !raw.jump[tail - 1])
          --tail;
        // The material at the front the session has just cut from is reachable, whatever
        // was given up there before (a move there once ended a session as a slot, or a
        // resume point was not found then). Left given up, no shortcut could find it: in
        // channels a millimetre or so wider than the tool, where the cut stops after each
        // crescent, the tool followed the boundary from one channel's front to the other's
        // and back (random pocket 2440, a ø20: 55 walks of 50 to 60 mm, 11.6 m in the air
        // and 270 s; now 1.9 m and 148 s). Once per cut (a failed shortcut gives up its
        // pixel for good unless the tool cuts again), so the search still terminates.
        if (tail > 0 && raw.eng[tail - 1] > m.cut_px && tail != reopened_tail) {
          reopen_disk(raw.pts[tail], m.radius_mm + 3.0 * m.step_mm);
          reopened_tail = tail;
        }
        Vec2 at, d;
        int si = 0, sj = 0;
        if (tail > 0 &&
            find_resume(m, stock, raw.pts[tail], at, d, si, sj, given_up, 1.5 * shortcut_mm)) {
          shortcut_pending = true;
          cut_since_shortcut = false;
          short_i = si;
          short_j = sj;
          drop_steps_from(tail);
          jump_to(at, d);
          one_way_resumed = false;
        }
      }
    }
    if (!ended_by_slot) slot_run = 0;
    // Drop the idle tail: it only proved there is nothing left within reach. A new entry
    // stays even when its session cut nothing more: its helix or ramp has cut the stock,
    // and the moves after it were chosen on that stock (dropped, the final path met the
    // ramp's material uncut, in a full slot).
    std::size_t kept = raw.eng.size();
    while (kept > 0 && raw.eng[kept - 1] <= m.cut_px &&
           !(raw.jump[kept - 1] && raw.entry[kept - 1] >= 0))
      --kept;
    drop_steps_from(kept);
    pos = raw.pts.back();
    if (raw.eng.size() >= max_steps || iterations >= max_steps) break;
    // A resumed session that cut nothing gives up the material within a tool radius of the
    // pixel it was aimed at, not that pixel alone: the next resume is then aimed elsewhere
    // instead of at its neighbour (one L with three islands spent 117 sessions in a row on
    // one spot and hit the session limit with 1640 mm^2 left; a new entry takes such
    // material in the end).
    if (resumed && raw.eng.size() <= before_session) give_up_disk(m.grid.to_world(last_i, last_j));
    Vec2 at, d;
    int new_entry = -1;
    if (!find_resume(m, stock, pos, at, d, last_i, last_j, given_up)) {
      // Nothing reachable from the cleared area: enter anew where the stock is untouched
      // (seed 000 4.1's several plunge holes), at the widest unused medial-axis point.
      const double full = kPi * m.radius_mm * m.radius_mm / (m.h * m.h);
      for (std::size_t k = 1; k < entries.size() && new_entry < 0; ++k)
        if (!used[k] && stock.material_in_disk(entries[k].centre, m.radius_mm) > 0.9 * full)
          new_entry = static_cast<int>(k);
      if (new_entry < 0) {
        // Our addition: material no resume point reaches and no entry above covers: behind
        // a neck whose own region has no medial-axis maximum among the entries, or where
        // every centre near it still has material in its disk (the corner of a wedge whose
        // tip is narrower than the tool). The material given up on is tried again: the tool
        // enters anew where its disk takes the most of what is left (the random pocket
        // sweep left up to 226 mm^2 behind before this). Each such entry clears its disk, so
        // the material strictly shrinks.
        // No entry can take entry_min_px when less than that is left in all (the usual end:
        // a few pixels in corners); the medial axis and its walks then cost 7 % of the
        // benchmark L's time for nothing.
        if (stock.material().count_all() < static_cast<std::size_t>(entry_min_px)) break;
        if (axis.pixels.empty()) axis = make_entry_axis(m, m.radius_mm / m.h + 0.75);
        Entry e;
        if (!find_entry_for_material(m, stock, axis, entry_min_px, e)) break;
        // Only the given-up material this entry's cuts can reach is tried again. All of it
        // was: on a plate of chambers, each behind necks narrower than the tool, every
        // chamber's crumbs after each new entry (the 8 x 6 plate above: 2038 resumes that
        // cut nothing, 60 s, 4656 mm^2 still left at the session bound; now 15 s and
        // none). Where the free centres are all one region, all of it, as before.
        if (components.label.empty()) components = label_centre_components(m);
        forget_given_up_near(m, components, e.centre, given_up);
        entries.push_back(e);
        used.push_back(false);
        new_entry = static_cast<int>(entries.size()) - 1;
      }
      used[static_cast<std::size_t>(new_entry)] = true;
      const Entry& e = entries[static_cast<std::size_t>(new_entry)];
      cut_entry(stock, m, e);
      at = e.start;
      d = {std::cos(e.start_angle_rad), std::sin(e.start_angle_rad)};
      resumed = false;
    } else {
      resumed = true;
    }
    before_session = raw.eng.size();
    push_jump(at, d, new_entry);
    one_way_resumed = false;
  }
  return raw;
}

}  // namespace swarf::pocket
