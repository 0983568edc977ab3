// Channels a little wider than the tool: plunged along one side, then side-milled in band.
//
// Where the pocket narrows to less than about two stepovers more than the tool (twice the
// radial depth of a cut at 1.2 times the target angle), the move chooser can only go on by
// tight trochoidal loops (a tenth of a millimetre across in a
// channel 0.4 mm wider than a ø4): every move of a loop is in band on average, but along
// it the contact swings from nothing to a full half of the tool (random pocket 715, ø4 at
// 10 %: 42 mm of loops, 27 mm of them out of the band by the sweep, 5.4 % of its cut). No
// horizontal way into such a channel cuts less than its whole width at once: whatever the
// path, the front ahead spans wall to wall. So the channel is plunged instead, along the
// offset of one wall, each plunge a crescent at most three quarters of a radius beyond the
// last hole (necks take half a radius, neck_plunges.cpp; the tool's centre is still over
// cut space); what is left is a strip along the other wall as thick as the channel's room,
// which one pass (two where the room is over the band's depth) takes as a side cut, at the
// target engagement when the room is within the band's radial depths, on the milling side
// (climb by default). A last pass along the holes' wall takes the cusps between them, below
// the band. AdaptiveParams::channel_plunge, on by default; adaptive.cpp replaces a run only
// where that is no slower at the feeds than its loops (channel_plunges_time_s against
// channel_loops_time_s): a small tool plunging deep at the plunge feed is slower (random
// pocket 715, ø4 6 mm deep; docs/pocket.md, How it works 7).
#include <algorithm>
#include <cmath>

#include "pocket/adaptive_internal.h"

namespace swarf::pocket {

namespace {

// Resamples the polyline `way` at spacing at most `ds`, ends kept.
std::vector<Vec2> resample(const std::vector<Vec2>& way, double ds) {
  std::vector<Vec2> out{way.front()};
  for (std::size_t k = 1; k < way.size(); ++k) {
    const double len = distance(way[k - 1], way[k]);
    const int n = std::max(1, static_cast<int>(std::ceil(len / ds - 1e-9)));
    for (int i = 1; i <= n; ++i)
      out.push_back(way[k - 1] + (way[k] - way[k - 1]) * (static_cast<double>(i) / n));
  }
  return out;
}

}  // namespace

std::vector<ChannelRun> channel_runs(const Model& m, const LinkedPath& lp,
                                     const std::vector<std::size_t>& keep,
                                     const std::vector<KeptMove>& kept,
                                     const std::vector<std::vector<Vec2>>& via,
                                     const std::vector<NeckRun>& necks) {
  std::vector<ChannelRun> out;
  if (keep.size() < 2) return out;
  const double radius = m.radius_mm;
  const double reach = radius + m.wall_stock_mm;
  // The band's radial depths: a pass whose strip is between them is in the band.
  const double lo = stepover_for_angle_mm(0.8 * m.target_deg, radius);
  const double hi = stepover_for_angle_mm(std::min(1.2 * m.target_deg, 90.0), radius);
  // Channels with room for at most two passes in the band (wider ones leave the chooser
  // room for wider loops, and the emission takes at most two passes).
  const double room_max = 2.0 * hi;
  std::vector<bool> in_neck(keep.size(), false);
  for (const NeckRun& n : necks) {
    for (std::size_t q = n.first; q <= n.last; ++q)
      in_neck[q] = true;
  }
  // Walls within room_max beyond the tool on both sides of p, along one of 16 lines.
  auto thin = [&](Vec2 p) { return walled_on_any_line(m.walls, p, 16, reach + room_max); };
  auto in_channel = [&](std::size_t q) {
    if (lp.jump[keep[q - 1]] || in_neck[q]) return false;
    if (!thin(lp.pts[keep[q]])) return false;
    for (const Vec2& v : via[q])
      if (!thin(v)) return false;
    return true;
  };
  // How far from p along the unit vector d the tool's centre may go (the exact wall
  // distance stays at reach + clearance), up to `limit`; -1 where the wall is not within it.
  const double keep_off = reach + kWallClearanceMm;
  auto room_along = [&](Vec2 p, Vec2 d, double limit) {
    if (m.walls.distance(p) < keep_off - 1e-9) return 0.0;
    double in = 0.0, outv = limit;
    if (m.walls.distance(p + d * limit) >= keep_off) return -1.0;
    for (int it = 0; it < 40 && outv - in > 1e-5; ++it) {
      const double mid = 0.5 * (in + outv);
      (m.walls.distance(p + d * mid) >= keep_off ? in : outv) = mid;
    }
    return in;
  };
  // Every straight piece of `line` keeps the tool off the walls.
  auto clear = [&](const std::vector<Vec2>& line) {
    for (std::size_t k = 1; k < line.size(); ++k)
      if (m.walls.segment_distance(line[k - 1], line[k]) < reach - 1e-6) return false;
    return true;
  };
  // `line` with the points that keep each straight piece off the walls.
  auto kept_off = [&](const std::vector<Vec2>& line) {
    std::vector<Vec2> out_line{line.front()};
    for (std::size_t k = 1; k < line.size(); ++k) {
      keep_off_walls(m.walls, reach, kWallClearanceMm, line[k - 1], line[k], out_line);
      out_line.push_back(line[k]);
    }
    return out_line;
  };
  // The milling side: climb (sigma -1) has the material on the right. The passes run from
  // the run's end back to its start, so the strip they take lies left of the way forwards.
  const double strip_side = m.sigma < 0 ? 1.0 : -1.0;
  for (std::size_t q = 1; q < keep.size();) {
    if (!in_channel(q) || !thin(lp.pts[keep[q - 1]])) {
      ++q;
      continue;
    }
    ChannelRun c;
    c.first = q;
    std::size_t run_last = q;
    for (; q < keep.size() && in_channel(q); ++q)
      run_last = q;
    // The way along the channel: the path's points at least `spacing` apart from every
    // point kept before (the loops fold back on themselves, less than the room apart). The
    // run ends with the move that reaches the way's last point, and before the path comes
    // back within half `spacing` of a point before that: past either it goes back over the
    // channel or loops at its far end, and is cut as it was. Except that the way goes on to
    // the move end furthest on along it before the path comes back: the loops that reach
    // the far end of a channel that ends there (random pocket 715; a channel 8.8 x 40).
    const double spacing = std::max(2.0 * room_max, 0.5 * radius);
    Vec2 start = lp.pts[keep[c.first - 1]];
    std::vector<Vec2> way{start};
    std::vector<std::size_t> way_move{c.first - 1};  // the move each way point lies on
    c.last = c.first;
    bool back = false;
    std::size_t tip = 0;  // the move whose end is furthest on past the way's last point
    double tip_on = 0.0;
    for (std::size_t r = c.first; r <= run_last && !back; ++r) {
      // The move's points at most a quarter of `spacing` apart: a long link back along the
      // channel comes back too.
      std::vector<Vec2> line{lp.pts[keep[r - 1]]};
      line.insert(line.end(), via[r].begin(), via[r].end());
      line.push_back(lp.pts[keep[r]]);
      std::vector<Vec2> pts = resample(line, 0.25 * spacing);
      pts.erase(pts.begin());
      for (std::size_t i = 0; i < pts.size() && !back; ++i) {
        const Vec2 p = pts[i];
        for (std::size_t w = 0; w + 1 < way.size() && !back; ++w)
          back = distance(p, way[w]) < 0.5 * spacing;
        bool far = !back;
        for (std::size_t w = way.size(); far && w-- > 0;)
          far = distance(p, way[w]) >= spacing;
        if (far) {
          way.push_back(p);
          way_move.push_back(r);
          c.last = r;
          tip = 0;
          tip_on = 0.0;
        } else if (!back && i + 1 == pts.size() && way.size() >= 2) {
          const Vec2 d = normalized(way.back() - way[way.size() - 2]);
          const double on = dot(p - way.back(), d);
          if (on > tip_on) {
            tip = r;
            tip_on = on;
          }
        }
      }
    }
    if (tip > c.last) c.last = tip;
    const Vec2 end = lp.pts[keep[c.last]];
    if (distance(way.back(), end) > 1e-9) way.push_back(end);
    q = c.last + 1;
    // The run starts where it first takes half a slot's worth of material over a piece of
    // the way: before, it passes over strips of a channel cut before (the pass back along
    // a ramp's slot, random pocket 715's first loops).
    for (std::size_t i = 1; i < way_move.size(); ++i) {
      double removed = 0.0;
      for (std::size_t r = way_move[i - 1] + 1; r <= way_move[i]; ++r)
        removed += kept[r].px * m.h * m.h;
      if (removed >= radius * distance(way[i - 1], way[i])) {
        if (i > 1) {
          c.first = way_move[i - 1] + 1;
          start = lp.pts[keep[way_move[i - 1]]];
          way.erase(way.begin(), way.begin() + static_cast<std::ptrdiff_t>(i - 1));
          way.front() = start;
        }
        break;
      }
    }
    double length = 0.0, cutting = 0.0, removed_mm2 = 0.0;
    for (std::size_t r = c.first; r <= c.last; ++r) {
      length += kept[r].len;
      if (!kept[r].link) cutting += kept[r].len;
      removed_mm2 += kept[r].px * m.h * m.h;
    }
    // Loops that go on along an uncut channel: at least a tool radius of it, two and a half
    // times as much path as progress, cutting over a third of the path, and taking at
    // least half of a slot's worth of material over the way (not a pass back over the
    // strips of a channel cut before).
    const double progress = distance(start, end);
    if (progress < radius || length < 2.5 * progress || cutting < length / 3.0 ||
        removed_mm2 < radius * progress)
      continue;
    if (!clear(way)) continue;
    const std::vector<Vec2> stations = resample(way, std::min(0.25, 0.25 * radius));
    // The room at each station across the way, along the normal to the direction along the
    // channel there (over a millimetre either side: the way turns at its points): the side
    // the plunges keep to (a) and the side of the strip (b). Where a side has no wall within
    // 1.5 room_max (where the channel turns a corner into another, or opens at its ends),
    // the lines keep that far out; at most 30 % of the stations may.
    std::vector<Vec2> side_a, side_b;
    std::vector<double> room;
    const std::size_t reach_k =
        static_cast<std::size_t>(std::ceil(1.0 / std::min(0.25, 0.25 * radius)));
    std::size_t open = 0;
    for (std::size_t k = 0; k < stations.size(); ++k) {
      const Vec2 t = normalized(stations[std::min(k + reach_k, stations.size() - 1)] -
                                stations[k > reach_k ? k - reach_k : 0]);
      const Vec2 n = Vec2{-t.y, t.x} * strip_side;
      double to_b = room_along(stations[k], n, 1.5 * room_max);
      double to_a = room_along(stations[k], n * -1.0, 1.5 * room_max);
      if (to_a < 0.0 || to_b < 0.0) {
        ++open;
        to_a = to_a < 0.0 ? 1.5 * room_max : to_a;
        to_b = to_b < 0.0 ? 1.5 * room_max : to_b;
      } else {
        room.push_back(to_a + to_b);
      }
      side_a.push_back(stations[k] - n * to_a);
      side_b.push_back(stations[k] + n * to_b);
    }
    bool ok = 10 * open <= 3 * stations.size() && !room.empty();
    if (!ok) continue;
    std::sort(room.begin(), room.end());
    const double median = room[room.size() / 2];
    const int passes = median <= hi ? 1 : 2;
    // A strip thinner than the band's depth would be cut below it: the loops are left. So
    // are they where the room is over two target depths or a quarter of the tool's radius:
    // there the loops are wide enough to keep most of their cut in the band, and the cusp
    // pass, below it, cost more of the band than the loops did. Drawn random pockets, ø10 to
    // ø20, by the sweep: with 0.36-0.8 R of room 3022 91.0 -> 87.7 %, 3023 95.3 -> 94.4,
    // 3036 95.6 -> 95.2, 3101 94.3 -> 93.3, 3116 81.3 -> 77.4, each for 0-5 s; with
    // 0.2-0.24 R 3044 96.2 -> 97.0 (-11 s) and 3108 94.6 -> 94.7, and the test channels
    // (0.2 R) gain 7-12 points (docs/pocket.md, How it works 7).
    if (median / passes < lo || median / passes > hi) continue;
    if (median > std::min(2.0 * stepover_for_angle_mm(m.target_deg, radius), 0.25 * radius) + 1e-9)
      continue;
    // The holes' line, with the points that keep it off a wall's convex corner.
    const std::vector<Vec2> hole_line = kept_off(side_a);
    std::vector<Vec2> plunge_way{start};
    plunge_way.insert(plunge_way.end(), hole_line.begin(), hole_line.end());
    for (const NeckPlunge& h : neck_plunge_points(plunge_way, 0.75 * radius))
      c.holes.push_back(h.at);
    for (int j = 1; j <= passes; ++j) {
      std::vector<Vec2> pass;
      for (std::size_t k = stations.size(); k-- > 0;)
        pass.push_back(side_a[k] + (side_b[k] - side_a[k]) * (static_cast<double>(j) / passes));
      c.passes.push_back(pass);
    }
    // Every piece keeps off the walls: the line of holes and the passes go round a wall's
    // convex corner through points pushed off it, and the steps across between them must.
    for (auto& pass : c.passes)
      pass = kept_off(pass);
    ok = clear(hole_line);
    Vec2 at = hole_line.back();
    for (const auto& pass : c.passes) {
      ok = ok && clear(pass) && clear({at, pass.front()});
      at = pass.front();
    }
    c.cusp_pass = hole_line;
    ok = ok && clear({c.passes.back().back(), hole_line.front()});
    if (!ok || !clear({hole_line.back(), end})) continue;
    c.room_mm = median;
    out.push_back(std::move(c));
  }
  return out;
}

double channel_loops_time_s(const ChannelRun& c, const std::vector<KeptMove>& kept,
                            const ChannelFeeds& f) {
  double min = 0.0;
  for (std::size_t r = c.first; r <= c.last; ++r)
    min += kept[r].len / (kept[r].fast ? f.link : f.feed);
  return 60.0 * min;
}

std::vector<ChannelStep> channel_steps(const ChannelRun& c, Vec2 end) {
  using Kind = ChannelStep::Kind;
  std::vector<ChannelStep> out;
  for (const Vec2& h : c.holes)
    out.push_back({Kind::kPlunge, h});
  for (std::size_t j = 0; j < c.passes.size(); ++j) {
    const std::vector<Vec2>& pass = c.passes[j];
    for (const Vec2& v : pass)
      out.push_back({Kind::kCut, v});
    if (j + 1 == c.passes.size()) break;
    for (std::size_t v = pass.size() - 1; v-- > 0;)
      out.push_back({Kind::kLink, pass[v]});
  }
  for (const Vec2& v : c.cusp_pass)
    out.push_back({Kind::kCut, v});
  out.push_back({Kind::kCut, end});
  return out;
}

double channel_plunges_time_s(const ChannelRun& c, Vec2 from, Vec2 to, const ChannelFeeds& f) {
  // Up from the floor, then to each hole, down at the plunge feed, and up again before the
  // next (the last hole's tool stays down).
  double min = f.dive_mm / f.rapid;
  Vec2 at = from;
  bool in_hole = false;
  for (const ChannelStep& s : channel_steps(c, to)) {
    if (s.kind == ChannelStep::Kind::kPlunge) {
      if (in_hole) min += f.dive_mm / f.rapid;
      min += distance(at, s.to) / f.rapid + f.dive_mm / f.plunge;
      in_hole = true;
    } else {
      min += distance(at, s.to) / (s.kind == ChannelStep::Kind::kCut ? f.feed : f.link);
    }
    at = s.to;
  }
  return 60.0 * min;
}

std::vector<ChannelRun> runs_leaving_nothing(const Model& m, PixelStock stock,
                                             const std::vector<Entry>& entries,
                                             const LinkedPath& lp,
                                             const std::vector<std::size_t>& keep,
                                             std::vector<ChannelRun> runs,
                                             const BitImage& left_before) {
  if (runs.empty()) return runs;
  // The path as the emission writes it, cut as the re-simulation cuts (resimulate in
  // adaptive.cpp): straight moves in steps of at most the step length.
  Vec2 at = lp.pts.front();
  auto feed_to = [&](Vec2 to) {
    const int n = std::max(1, static_cast<int>(std::ceil(distance(at, to) / m.step_mm - 1e-9)));
    for (int s = 1; s <= n; ++s) {
      const Vec2 q = at + (to - at) * (static_cast<double>(s) / n);
      stock.cut(at, q);
      at = q;
    }
  };
  cut_entry(stock, m, entries.front());
  std::size_t next = 0;
  for (std::size_t k = 0; k + 1 < lp.pts.size(); ++k) {
    if (next < runs.size() && k == keep[runs[next].first - 1]) {
      // The run as the emission writes it, on to where its loops ended.
      const ChannelRun& c = runs[next++];
      for (const ChannelStep& s : channel_steps(c, lp.pts[keep[c.last]])) {
        if (s.kind == ChannelStep::Kind::kPlunge) {
          stock.stamp(s.to);
          at = s.to;
        } else {
          feed_to(s.to);
        }
      }
      k = keep[c.last] - 1;
      continue;
    }
    const Vec2 b = lp.pts[k + 1];
    if (lp.jump[k] && lp.entry[k] >= 0) {
      cut_entry(stock, m, entries[static_cast<std::size_t>(lp.entry[k])]);
      at = b;
    } else if (lp.jump[k]) {
      stock.stamp(b);
      at = b;
    } else {
      at = lp.pts[k];
      feed_to(b);
    }
  }
  // What is left now that the path cut, each pixel put down to the runs whose loops reach it.
  std::vector<Vec2> newly_left;
  const BitImage& now = stock.material();
  for (int j = 0; j < now.height(); ++j) {
    for (int i = 0; i < now.width(); ++i)
      if (now.get(i, j) && !left_before.get(i, j)) newly_left.push_back(m.grid.to_world(i, j));
  }
  const double reach = m.radius_mm + 2.0 * m.h;
  const int most = static_cast<int>(0.1 / (m.h * m.h));
  std::vector<ChannelRun> out;
  for (ChannelRun& c : runs) {
    int left = 0;
    for (const Vec2& q : newly_left) {
      for (std::size_t s = keep[c.first - 1]; s <= keep[c.last]; ++s) {
        if (distance(q, lp.pts[s]) <= reach) {
          ++left;
          break;
        }
      }
    }
    if (left <= most) out.push_back(std::move(c));
  }
  return out;
}

}  // namespace swarf::pocket
