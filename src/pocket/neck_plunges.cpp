// Necks barely wider than the tool: plunged through rather than slotted.
//
// Where the pocket narrows to a few tenths of a millimetre more than the tool, every way
// through cuts a full slot (random pockets 1088, 1096: channels 0.08-0.2 mm wider than the
// tool between an island and the wall), which the issue rules out outside the entry and
// which loads the tool on its whole half-circumference at a feed chosen for the target
// engagement. The emission (adaptive.cpp) plunges the tool down along such a run instead,
// each plunge a crescent at most half a radius beyond the last hole (the tool's centre is
// always over cut space, so even the first needs no centre-cutting end mill), then takes
// the cusps between the holes backwards and goes through in the air. The plunges lie on the
// path the moves follow (with the points that keep its chords off the walls), so they keep
// off the walls as the moves do.
#include <algorithm>
#include <cmath>

#include "pocket/adaptive_internal.h"

namespace swarf::pocket {

bool walled(const WallIndex& walls, Vec2 p, Vec2 n, double r) {
  return !walls.inside(p + n * r) && !walls.inside(p - n * r);
}

bool walled_on_any_line(const WallIndex& walls, Vec2 p, int lines, double r) {
  for (int k = 0; k < lines; ++k) {
    const double a = kPi * k / lines;
    if (walled(walls, p, Vec2{std::cos(a), std::sin(a)}, r)) return true;
  }
  return false;
}

std::vector<NeckRun> neck_runs(const Model& m, const LinkedPath& lp,
                               const std::vector<std::size_t>& keep,
                               const std::vector<KeptMove>& kept) {
  // kNeckSlotDeg, 160 degrees, is a cut 97 % of the diameter wide: a full slot wherever it
  // is (the move chooser's slot test stops at 160 degrees too, move_chooser.cpp).
  // Between walls less than a millimetre beyond the tool on both sides, the model reads
  // short: its material is what the free pixel centres reach, so the slivers a few tenths
  // thick beside the tool are not in it, and a pass the sweep sees touching material across
  // its whole front half reads 145-165 degrees (random pocket 1088: a ø20 between an island
  // and the wall 20.08 mm apart, 11.8 mm of full slot by the sweep). There a cut of
  // kNeckTightDeg, 110 degrees (two thirds of the diameter wide), over a millimetre or more
  // counts as the slot.
  constexpr double kTightMarginMm = 1.0, kTightRunMm = 1.0;
  // Shorter runs of full slot are single short moves whose removal per length reads high on
  // the pixels.
  constexpr double kMinRunMm = 0.2;
  // Slot runs this close along the path, pinched between, are one neck (below).
  const double bridge_mm = std::max(1.0, m.radius_mm);
  const double reach = m.radius_mm + m.wall_stock_mm + kTightMarginMm;
  // Whether at(point) holds over at least half of move q, sampled every half millimetre: a
  // move that runs into a channel from its mouth is tight over the part in it (random
  // pocket 1130: a ø12 cut 7.4 mm of full slot by the sweep along a boundary move that began
  // 0.75 mm before two islands 12.07 mm apart, where one of them was not yet beside it; the
  // move's ends and middle had to be walled before).
  auto over_half = [&](std::size_t q, auto&& at) {
    const Vec2 a = lp.pts[keep[q - 1]], b = lp.pts[keep[q]];
    const int samples = std::max(2, static_cast<int>(std::ceil(distance(a, b) / 0.5)) + 1);
    int in = 0;
    for (int k = 0; k < samples; ++k)
      in += at(a + (b - a) * (static_cast<double>(k) / (samples - 1))) ? 1 : 0;
    return 2 * in >= samples;
  };
  // Walled within `reach` across the move (along its normal).
  auto tight = [&](std::size_t q) {
    const Vec2 d = normalized(lp.pts[keep[q]] - lp.pts[keep[q - 1]]), n{-d.y, d.x};
    return over_half(q, [&](Vec2 p) { return walled(m.walls, p, n, reach); });
  };
  // Where the room beside the tool (the narrowest chord through its centre, less the
  // diameter) is under four pixels, a heavy cut is a full slot too, from 0.2 mm: the tool
  // fills the way, and the model, whose material is what the free pixel centres reach (a
  // pixel or so short of the exact reach), misses the slivers on both sides. The line
  // between the walls may run at any angle to the move: at a channel's mouth one wall is
  // the corner of an island ahead (random pocket 617 at 10 %: a ø20 crept into the mouth of
  // a channel 0.02 mm wider than itself past a square island's corner, 143 and 134 degrees
  // by the model over 1.5 and 0.5 mm, 170-177 by the sweep; the move's normal met no island
  // there, so it was not tight). 64 lines, 2.8 degrees apart: at a corner the line that
  // meets it within the margin turns through a few degrees only.
  const double narrow_reach = m.radius_mm + m.wall_stock_mm + 2.0 * m.h;
  auto narrow = [&](std::size_t q) {
    return over_half(q, [&](Vec2 p) { return walled_on_any_line(m.walls, p, 64, narrow_reach); });
  };
  // Between walls within reach on two opposite sides, whichever way the line between them
  // runs (every 22.5 degrees): in a channel, whatever the heading of the move there.
  auto pinched = [&](Vec2 p) { return walled_on_any_line(m.walls, p, 8, reach); };
  // Move q (keep[q - 1] -> keep[q]) runs between close walls, with no retract before it.
  auto between_walls = [&](std::size_t q) {
    const Vec2 a = lp.pts[keep[q - 1]], b = lp.pts[keep[q]];
    return !lp.jump[keep[q - 1]] && pinched(a) && pinched((a + b) * 0.5) && pinched(b);
  };
  // A full slot by the model itself, or a heavy cut with under four pixels of room: runs of
  // such moves are necks from kMinRunMm.
  auto full_slot = [&](std::size_t q) {
    return kept[q].deg >= kNeckSlotDeg || (kept[q].deg >= kNeckTightDeg && narrow(q));
  };
  // A move out of a straight plunge's hole into the material round it touches it across its
  // whole front, a full slot however short (the plunge went straight down because nothing
  // else fits there: the hole is walled in, with slivers between it and the walls that the
  // model does not see). Random pocket 1535: a ø10 tip visit 0.11 mm out of such a hole
  // into a corner's tip, 135 degrees by the model, 180 by the sweep; plunged at the tip
  // instead.
  auto slot = [&](std::size_t q) {
    if (lp.jump[keep[q - 1]] || kept[q].link) return false;
    return full_slot(q) || (kept[q].deg >= kNeckTightDeg && (kept[q].out_of_hole || tight(q)));
  };
  struct Run {
    NeckRun n;
    bool full = false;  // a full slot (full_slot)
  };
  auto min_length_mm = [&](const Run& r) {
    return kept[r.n.first].out_of_hole ? 0.0 : r.full ? kMinRunMm : kTightRunMm;
  };
  std::vector<Run> runs;
  for (std::size_t q = 1; q < keep.size();) {
    if (!slot(q)) {
      ++q;
      continue;
    }
    Run r;
    r.n.first = q;
    for (; q < keep.size() && slot(q); ++q) {
      r.n.length_mm += kept[q].len;
      r.full = r.full || full_slot(q);
    }
    r.n.last = q - 1;
    // A channel only a few tenths wider than the tool, where the chooser creeps: each
    // session cuts a step or two, a link or a short move back lies between (random pocket
    // 1516: a ø8 between a round island and the wall 8.1-8.25 mm apart over 5 mm, 1.7 mm
    // of full slot by the sweep in pieces of 0.05-0.4 mm, too short to be plunged each).
    // Runs less than a tool radius (or a millimetre) of path apart, with no retract between
    // and walls on two opposite sides of every move between, are one neck: its way goes back
    // and forth there, which the plunges and the cusps taken backwards follow.
    if (!runs.empty()) {
      const NeckRun& prev = runs.back().n;
      double gap = 0.0;
      bool bridged = true;
      for (std::size_t g = prev.last + 1; g < r.n.first && bridged; ++g) {
        gap += kept[g].len;
        bridged = gap <= bridge_mm && between_walls(g);
      }
      if (bridged) {  // (a run never starts with a jump: slot() says no)
        runs.back().n.last = r.n.last;
        runs.back().n.length_mm += r.n.length_mm;
        runs.back().full = runs.back().full || r.full;
        continue;
      }
    }
    runs.push_back(r);
  }
  // Heavy moves just past a run's end (or before its start), within a tool radius (at least
  // a millimetre) of path between close walls, belong to its neck even when the model reads
  // them short of kNeckTightDeg: beside walls a few tenths off the tool the model misses the
  // slivers there (above), most of all where the chooser creeps into the neck's far end.
  // Random pocket 1516 (a ø8 in a neck 0.12-0.18 mm wider than it, 30 % stepover, target 66
  // degrees): a 0.4 mm move the model read at 108 degrees, past a link and three short moves
  // after the run, was cut by the sweep at 179 degrees, a full slot. Heavy here is 100
  // degrees or a quarter above the target, whichever is more (the band ends a fifth above
  // it), and only runs that are necks by themselves reach out so: in random pocket 2500 (a
  // ø3 at 40 % stepover, 78 degrees targeted, in a channel) single heavy moves, each too
  // short to be a neck, reached out to the moves round them, and plunging those took the
  // machining time from 28 to 71 s.
  const double bridged_deg = std::max(100.0, 1.25 * m.target_deg);
  auto heavy = [&](std::size_t q) { return !kept[q].link && kept[q].deg >= bridged_deg; };
  for (std::size_t i = 0; i < runs.size(); ++i) {
    NeckRun& n = runs[i].n;
    if (n.length_mm < min_length_mm(runs[i])) continue;  // not a neck
    const std::size_t next_first = i + 1 < runs.size() ? runs[i + 1].n.first : keep.size();
    double gap = 0.0;
    for (std::size_t g = n.last + 1; g < next_first && between_walls(g); ++g) {
      if (heavy(g)) {
        for (std::size_t h = n.last + 1; h <= g; ++h)
          n.length_mm += kept[h].len;
        n.last = g;
      }
      gap += kept[g].len;
      if (gap > bridge_mm) break;
    }
    const std::size_t prev_last = i > 0 ? runs[i - 1].n.last : 0;
    gap = 0.0;
    for (std::size_t g = n.first - 1; g > prev_last && between_walls(g); --g) {
      if (heavy(g)) {
        for (std::size_t h = g; h < n.first; ++h)
          n.length_mm += kept[h].len;
        n.first = g;
      }
      gap += kept[g].len;
      if (gap > bridge_mm) break;
    }
  }
  std::vector<NeckRun> out;
  // Tight runs shorter than a millimetre are mostly trochoidal loops in a channel, one
  // move of each reading heavy (random pocket 998: five plunges for no slot by the sweep).
  for (const Run& r : runs)
    if (r.n.length_mm >= min_length_mm(r)) out.push_back(r.n);
  return out;
}

std::vector<NeckPlunge> neck_plunge_points(const std::vector<Vec2>& way, double spacing) {
  std::vector<double> at(way.size(), 0.0);  // length along the way
  for (std::size_t k = 1; k < way.size(); ++k)
    at[k] = at[k - 1] + distance(way[k - 1], way[k]);
  const double total = at.back();
  const int n = std::max(1, static_cast<int>(std::ceil(total / spacing - 1e-9)));
  std::vector<NeckPlunge> out;
  std::size_t k = 0;
  for (int i = 1; i <= n; ++i) {
    if (i == n) {
      out.push_back({way.size() - 1, way.back()});
      break;
    }
    const double s = total * i / n;
    while (k + 2 < way.size() && at[k + 1] <= s)
      ++k;
    const double seg = at[k + 1] - at[k];
    const double t = seg > 0.0 ? (s - at[k]) / seg : 0.0;
    out.push_back({k, way[k] + (way[k + 1] - way[k]) * std::clamp(t, 0.0, 1.0)});
  }
  return out;
}

}  // namespace swarf::pocket
