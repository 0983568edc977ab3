// Driver of the adaptive pocket strategy: parameters, plunge candidates, re-simulation of
// the final path (seed 000 6.6), layers and the Toolpath, summary figures.
#include "swarf/pocket/adaptive.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "pocket/adaptive_internal.h"
#include "pocket/distance_transform.h"
#include "pocket/geometry.h"
#include "swarf/core/parallel.h"
#include "swarf/polygon/polygon.h"

namespace swarf {

double engagement_angle_deg(double stepover_mm, double tool_radius_mm) {
  return rad_to_deg(std::acos(std::clamp(1.0 - stepover_mm / tool_radius_mm, -1.0, 1.0)));
}
double stepover_for_angle_mm(double engagement_deg, double tool_radius_mm) {
  return tool_radius_mm * (1.0 - std::cos(deg_to_rad(engagement_deg)));
}

Status validate(const AdaptiveParams& p, const Tool& tool) {
  auto bad = [](const std::string& m) { return bad_parameter(m); };
  const double d = tool.diameter_mm;
  if (!(d > 0.0)) return bad("tool diameter must be positive");
  if (p.engagement_deg < 0.0 || p.engagement_deg > 90.0)
    return bad("engagement_deg must be in (0, 90] degrees (0 = use stepover_mm)");
  if (p.stepover_mm < 0.0 || p.stepover_mm > 0.5 * d)
    return bad("stepover_mm must be in (0, tool radius] (0 = 10 % of the diameter)");
  if (!(p.tolerance_pct > 0.0 && p.tolerance_pct <= 50.0))
    return bad("tolerance_pct must be in (0, 50] percent");
  if (p.step_mm < 0.0 || p.step_mm > 0.5 * d)
    return bad("step_mm must be in (0, tool radius] mm (0 = stepover / 4 within [D / 40, D / 20])");
  if (!(p.max_deviation_deg >= 5.0 && p.max_deviation_deg <= 120.0))
    return bad("max_deviation_deg must be in [5, 120] degrees");
  if (p.resolution_mm < 0.0 || (p.resolution_mm > 0.0 && p.resolution_mm > 0.1 * d))
    return bad("resolution_mm must be in (0, diameter / 10] mm (0 = automatic)");
  if (!(p.max_pixels >= 1e4 && p.max_pixels <= 1e9))
    return bad("max_pixels must be in [10000, 1e9]");
  if (!(p.depth_mm > 0.0)) return bad("depth_mm must be positive");
  if (p.stepdown_mm < 0.0) return bad("stepdown_mm must not be negative (0 = full depth)");
  if (p.stepdown_mm > tool.flute_length_mm ||
      (p.stepdown_mm == 0.0 && p.depth_mm > tool.flute_length_mm))
    return bad("stepdown exceeds the flute length of the tool");
  if (p.floor_stock_mm < 0.0 || p.floor_stock_mm >= p.depth_mm)
    return bad("floor_stock_mm must be in [0, depth_mm)");
  if (p.wall_stock_mm < 0.0) return bad("wall_stock_mm must not be negative");
  if (!(p.link_feed_mm_min >= 0.0))
    return bad("link_feed_mm_min must be >= 0 (0 = the rapid rate)");
  if (!(p.ramp_feed_mm_min >= 0.0))
    return bad("ramp_feed_mm_min must be >= 0 (0 = the cutting feed)");
  if (!(p.feed_mm_min > 0.0 && p.plunge_feed_mm_min > 0.0 && p.rapid_mm_min > 0.0))
    return bad("feeds must be positive mm/min");
  if (!(p.ramp_angle_deg > 0.0 && p.ramp_angle_deg <= 45.0))
    return bad("ramp_angle_deg must be in (0, 45] degrees");
  if (p.helix_radius_mm < 0.0) return bad("helix_radius_mm must not be negative");
  if (p.plunge_candidates < 1 || p.plunge_candidates > 16)
    return bad("plunge_candidates must be in [1, 16]");
  if (p.smoothing_iterations < 0 || p.smoothing_iterations > 6)
    return bad("smoothing_iterations must be in [0, 6]");
  if (p.simplify_tolerance_mm < 0.0) return bad("simplify_tolerance_mm must not be negative");
  if (p.wall_scallop_mm < 0.0) return bad("wall_scallop_mm must not be negative");
  if (p.clearance_z_mm <= p.top_z_mm) return bad("clearance_z_mm must be above top_z_mm");
  return {};
}

namespace {

using pocket::Entry;
using pocket::KeptMove;
using pocket::kWallClearanceMm;
using pocket::LinkedPath;
using pocket::Model;
using pocket::NeckRun;

struct Recorder {
  std::vector<std::uint32_t>* cells;
  int width;
  std::uint32_t tag;
};
void record(void* user, int i, int j) {
  auto* r = static_cast<Recorder*>(user);
  (*r->cells)[static_cast<std::size_t>(j) * r->width + i] = r->tag;
}

double angle_of(const Model& m, int px, double len) {
  if (len <= 0.0 || px <= 0) return 0.0;
  const double stepover = px * m.h * m.h / len;
  return engagement_angle_deg(std::min(stepover, 2.0 * m.radius_mm), m.radius_mm);
}

// A tool position whose disk reaches past a wall or into an island, by exact geometry (the
// pixel test would flag the snapped passes, which keep 2 um off the wall, not half a pixel).
bool gouges_exactly(const Model& m, Vec2 c) {
  const double reach = m.radius_mm + m.wall_stock_mm;
  // Most steps lie far from every wall by the pixels, which need no exact query.
  if (pocket::far_from_walls(m, c, c, reach)) return false;
  return !m.walls.inside(c) || m.walls.distance(c) < reach - 1e-6;
}

// The stock a re-simulation of lp starts from: what the free pixel centres reach, and what
// lp's points beyond them (tip visits, scallop rides' dabs) reach.
pocket::PixelStock starting_stock(const Model& m, const LinkedPath& lp) {
  pocket::BitImage material = m.material;
  if (!lp.beyond_free.empty()) {
    pocket::PixelStock whole(m.grid, m.pocket, m.forbidden, m.radius_mm, &m.clearance_sq);
    const pocket::CutVisitor add = [](void* u, int i, int j) {
      static_cast<pocket::BitImage*>(u)->set(i, j, true);
    };
    for (const Vec2& v : lp.beyond_free)
      whole.stamp(v, add, &material);
  }
  return pocket::PixelStock(m.grid, material, m.forbidden, m.radius_mm, &m.clearance_sq);
}

// Re-simulation of the final path on a fresh stock (seed 000 6.6): engagement per step,
// gouges, the cut map, the material left.
void resimulate(const Model& m, const std::vector<Entry>& entries, const LinkedPath& lp,
                bool want_map, AdaptiveResult& res,
                std::optional<pocket::PixelStock>* stock_out = nullptr) {
  const Entry& e = entries.front();
  // The material: what the free pixel centres reach, and what the tip visits and the scallop
  // rides' dabs reach beyond them (the pocket pixels their disks cover, as the stock's own
  // disks cover them). Without the latter a visit's last move into a wedge read as cutting
  // nothing and went at the link feed, while the sweep saw it take up to 0.35 mm^2 in 0.1 mm
  // (random pocket 951, ø6), and a dab into a corner rounded 0.2 mm wider than a ø20 took
  // 1.8 mm^2 in 0.7 mm at the link feed (part-like pocket 2312). Only these points: stamping
  // every point near the walls (the passes snapped onto the walls' offsets reach beyond the
  // free centres too) added the pixels between a pass's sampled disks, which later links
  // along the wall then read as cut, at the cutting feed: +1-4 % of machining time on the
  // benchmark pockets for no change in what the sweep sees links remove.
  pocket::PixelStock stock = starting_stock(m, lp);
  // The cut map, when asked for (AdaptiveParams::cut_map): without it the cuts tag nothing.
  CutMap& map = res.cut_map;
  map = CutMap{};
  if (want_map) {
    map.origin = m.grid.origin;
    map.pixel_mm = m.h;
    map.width = m.grid.width;
    map.height = m.grid.height;
    map.cells.assign(static_cast<std::size_t>(map.width) * map.height, 0u);
    for (int j = 0; j < map.height; ++j) {
      for (int i = 0; i < map.width; ++i)
        if (m.pocket.get(i, j)) map.cells[m.grid.index(i, j)] = 1u;
    }
  }
  Recorder rec{&map.cells, map.width, 2u};
  const pocket::CutVisitor tag = want_map ? record : nullptr;
  pocket::cut_entry(stock, m, e, tag, &rec);
  res.steps.clear();
  res.gouge_steps = 0;
  Vec2 prev_dir{0, 0};
  for (std::size_t k = 0; k + 1 < lp.pts.size(); ++k) {
    const Vec2 a = lp.pts[k], b = lp.pts[k + 1];
    rec.tag = static_cast<std::uint32_t>(2 + res.steps.size() + 1);
    int removed = 0;
    if (lp.jump[k] && lp.entry[k] >= 0) {
      // A later entry's hole is an entry's in the picture too, not a cut of no engagement
      // (its step removes nothing by its own count; it showed blue before).
      rec.tag = 2u;
      pocket::cut_entry(stock, m, entries[static_cast<std::size_t>(lp.entry[k])], tag, &rec);
    } else if (lp.jump[k]) {
      removed = stock.stamp(b, tag, &rec);
      if (gouges_exactly(m, b)) ++res.gouge_steps;
    } else {
      const double len = distance(a, b);
      const int n = std::max(1, static_cast<int>(std::ceil(len / m.step_mm - 1e-9)));
      Vec2 p = a;
      for (int s = 1; s <= n; ++s) {
        const Vec2 q = a + (b - a) * (static_cast<double>(s) / n);
        if (gouges_exactly(m, q)) ++res.gouge_steps;
        removed += want_map ? stock.cut_tagging(p, q, map.cells.data(), map.width, rec.tag)
                            : stock.cut(p, q);
        p = q;
      }
    }
    AdaptiveStep st;
    st.position = b;
    st.kind = lp.kind[k];
    st.engagement_px = removed;
    st.length_mm = lp.jump[k] ? 0.0 : distance(a, b);
    st.engagement_deg = angle_of(m, removed, st.length_mm);
    const Vec2 d = normalized(b - a);
    if (k > 0 && !lp.jump[k] && !lp.jump[k - 1] && norm_sq(prev_dir) > 0)
      st.deviation_deg = rad_to_deg(std::atan2(std::abs(cross(prev_dir, d)), dot(prev_dir, d)));
    prev_dir = d;
    res.steps.push_back(st);
  }
  // Material is initialised to what the tool can reach, so whatever is left was missed.
  const std::size_t left = stock.material().count_all();
  res.material_left_mm2 = static_cast<double>(left) * m.h * m.h;
  if (stock_out != nullptr) stock_out->emplace(std::move(stock));
}

// The link costs of the output (path_postprocess.cpp weighs links against retracts with
// them, and the plunge candidates are timed with them).
pocket::LinkCosts link_costs(const AdaptiveParams& p) {
  pocket::LinkCosts c;
  c.feed_mm_min = p.feed_mm_min;
  c.link_feed_mm_min = pocket::link_feed_mm_min(p);
  c.rapid_mm_min = p.rapid_mm_min;
  c.lift_mm = p.clearance_z_mm - (p.top_z_mm - p.depth_mm);
  // A retract comes down at the plunge feed from 1 mm above the previous layer's floor.
  c.descent_mm = 1.0 + (p.stepdown_mm > 0.0 ? std::min(p.stepdown_mm, p.depth_mm)
                                            : p.depth_mm - p.floor_stock_mm);
  c.plunge_feed_mm_min = p.plunge_feed_mm_min;
  c.smoothing_iterations = p.smoothing_iterations;
  return c;
}

// The time of a linked path as the output will run it (links at the link feed, retracts
// with their descent at the plunge feed), for choosing among plunge candidates.
double path_time_s(const LinkedPath& lp, const pocket::LinkCosts& c) {
  double t = 0.0;
  for (std::size_t k = 0; k + 1 < lp.pts.size(); ++k) {
    const double l = distance(lp.pts[k], lp.pts[k + 1]);
    if (lp.jump[k]) {
      t += pocket::retract_minutes(c, l) * 60.0;
    } else {
      t += l / (lp.kind[k] == StepKind::kLink ? c.link_feed_mm_min : c.feed_mm_min) * 60.0;
    }
  }
  return t;
}

// Entry moves of one layer from z_from down to z_to.
// Below the first layer the entry's hole or slot is cut down to the previous layer's floor
// (the path is the same on every layer), so the descent goes straight down through it at the
// plunge feed to `z_clear` and the helix or ramp starts there: 1 mm of helix in the air at
// 3 degrees was 3.8 s a layer at the default feeds. On the first layer z_clear is z_from
// (the stock's top may stand higher than said: the helix starts above it).
void entry_moves(Toolpath& tp, const Entry& e, const AdaptiveParams& p, double z_from,
                 double z_clear, double z_to) {
  const double tan_a = std::tan(deg_to_rad(p.ramp_angle_deg));
  const double ramp_feed = p.ramp_feed_mm_min > 0.0 ? p.ramp_feed_mm_min : p.feed_mm_min;
  auto down_through_the_cut = [&](Vec2 at) {
    if (z_clear < z_from - 1e-9) {
      tp.moves.push_back(
          make_move(MoveKind::kPlunge, to_vec3(at, z_clear), p.plunge_feed_mm_min, false));
    }
    z_from = std::min(z_from, z_clear);
  };
  if (e.plunge) {
    tp.moves.push_back(make_move(MoveKind::kRapid, to_vec3(e.start, p.clearance_z_mm), 0, false));
    tp.moves.push_back(make_move(MoveKind::kRapid, to_vec3(e.start, z_from), 0, false));
    tp.moves.push_back(
        make_move(MoveKind::kPlunge, to_vec3(e.start, z_to), p.plunge_feed_mm_min, true));
    return;
  }
  if (e.helix_radius_mm > 0.0) {
    const Vec2 s = e.start;
    tp.moves.push_back(make_move(MoveKind::kRapid, to_vec3(s, p.clearance_z_mm), 0, false));
    tp.moves.push_back(make_move(MoveKind::kRapid, to_vec3(s, z_from), 0, false));
    down_through_the_cut(s);
    // Half turns, counter-clockwise for climb (the material ends up on the right).
    const double half_drop = kPi * e.helix_radius_mm * tan_a;
    double z = z_from;
    bool at_start = true;
    while (z > z_to + 1e-9) {
      z = std::max(z_to, z - half_drop);
      at_start = !at_start;
      const Vec2 to = at_start ? s : e.centre * 2.0 - s;
      Move mv = make_move(MoveKind::kHelix, to_vec3(to, z), ramp_feed, true);
      mv.center = to_vec3(e.centre, z);
      mv.clockwise = !p.climb;
      tp.moves.push_back(mv);
    }
    // A last full turn at depth clears the hole's floor.
    for (int k = 0; k < 2; ++k) {
      at_start = !at_start;
      const Vec2 to = at_start ? s : e.centre * 2.0 - s;
      Move mv = make_move(MoveKind::kArc, to_vec3(to, z_to), ramp_feed, true);
      mv.center = to_vec3(e.centre, z_to);
      mv.clockwise = !p.climb;
      tp.moves.push_back(mv);
    }
    return;
  }
  // Ramp: back and forth along the slot from a to b, an even number of descents (each at
  // most the ramp angle, all alike) so that the last ends at a at depth, then one pass at
  // depth back to b. That pass takes the wedge the last descent left on the floor: part of
  // the entry (the material is the ramp's own, one descent thick), not a cut at full depth.
  // Before, a ramp whose last descent ended at b left the wedge for the path to meet: on
  // random pocket 996 (ø20) a link-feed move crossed it, 4.3 mm of radial depth at the
  // floor by the sweep.
  const double len = distance(e.ramp_a, e.ramp_b);
  tp.moves.push_back(make_move(MoveKind::kRapid, to_vec3(e.ramp_a, p.clearance_z_mm), 0, false));
  tp.moves.push_back(make_move(MoveKind::kRapid, to_vec3(e.ramp_a, z_from), 0, false));
  down_through_the_cut(e.ramp_a);
  const double drop = z_from - z_to;
  // (A ramp is at least a pixel long; the cap only guards the division.)
  const double legs_needed = drop / std::max(len * tan_a, 1e-6);
  int legs = std::max(2, static_cast<int>(std::ceil(std::min(legs_needed, 1e6) - 1e-9)));
  legs += legs % 2;
  for (int k = 1; k <= legs; ++k) {
    const double z = k == legs ? z_to : z_from - drop * k / legs;
    tp.moves.push_back(
        make_move(MoveKind::kRamp, to_vec3(k % 2 == 0 ? e.ramp_a : e.ramp_b, z), ramp_feed, true));
  }
  tp.moves.push_back(make_move(MoveKind::kRamp, to_vec3(e.ramp_b, z_to), ramp_feed, true));
}

// A link-feed move's ends that run at the cutting feed: `head` after a cutting move,
// `tail` before one, of its `length` (the polyline through its wall-keeping points).
struct FeedMargin {
  double head = 0.0, tail = 0.0, length = 0.0;
};

// The link feed keeps `margin` (two pixels) off the cutting moves on either side. The
// model's material edge is where pixel centres are, up to a pixel off the true one, so a
// link's last move into the material the next cut takes, or its first after a cut, may take
// some: the sweep found the densest link-feed moves of three batches of random pockets
// there (part-like pocket 2445, ø20 with 0.25 mm pixels: 0.6 mm^2 in the last 0.5 mm of a
// link, 1.2 mm of radial depth at five times the feed). Jumps and necks end the margins.
std::vector<FeedMargin> cutting_feed_margins(const LinkedPath& lp,
                                             const std::vector<std::size_t>& keep,
                                             const std::vector<KeptMove>& kept,
                                             const std::vector<std::vector<Vec2>>& via,
                                             const std::vector<NeckRun>& necks, double margin) {
  std::vector<FeedMargin> out(keep.size());
  std::vector<bool> in_neck(keep.size(), false);
  for (const NeckRun& n : necks) {
    for (std::size_t q = n.first; q <= n.last; ++q)
      in_neck[q] = true;
  }
  auto apart = [&](std::size_t q) { return lp.jump[keep[q - 1]] || in_neck[q]; };
  for (std::size_t q = 1; q < keep.size(); ++q) {
    Vec2 at = lp.pts[keep[q - 1]];
    for (const Vec2& v : via[q]) {
      out[q].length += distance(at, v);
      at = v;
    }
    out[q].length += distance(at, lp.pts[keep[q]]);
  }
  double left = 0.0;  // margin still to give after the last cutting move
  for (std::size_t q = 1; q < keep.size(); ++q) {
    if (apart(q)) {
      left = 0.0;
    } else if (!kept[q].fast) {
      left = margin;
    } else {
      out[q].head = std::min(out[q].length, left);
      left -= out[q].head;
    }
  }
  left = 0.0;  // margin still to give before the next cutting move
  for (std::size_t q = keep.size(); q-- > 1;) {
    if (apart(q)) {
      left = 0.0;
    } else if (!kept[q].fast) {
      left = margin;
    } else {
      out[q].tail = std::min(out[q].length, left);
      left -= out[q].tail;
    }
  }
  return out;
}

}  // namespace

Result<AdaptiveResult> adaptive_pocket(const Pocket& pocket, const Tool& tool,
                                       const AdaptiveParams& params, const Context& ctx) {
  SWARF_RETURN_IF_ERROR(validate(params, tool));
  if (pocket.region.rings.empty()) return bad_input(pocket.source + ": empty pocket");
  auto model = pocket::make_model(pocket, tool, params);
  if (!model) return model.status();
  const Model& m = model.value();
  // Candidates for the start, and spare entries for parts of the pocket behind necks
  // narrower than the tool.
  auto entries = pocket::find_entries(m, std::max(params.plunge_candidates, 16));
  if (!entries) return entries.status();
  const pocket::LinkCosts costs = link_costs(params);
  // seed 000 4.1: several plunge points; keep the fastest path (engagement is held to the
  // same target by construction, so time decides). Each candidate is a simulation of its own
  // on its own stock, so they run in parallel; the choice (least time, the first candidate on
  // a tie) and every path are the same for any thread count.
  const std::size_t candidates =
      std::min(entries->size(), static_cast<std::size_t>(params.plunge_candidates));
  std::vector<LinkedPath> paths(candidates);
  std::vector<std::vector<Entry>> orders(candidates);
  std::vector<double> times(candidates, 0.0);
  std::vector<Status> failed(candidates);
  Context worker;  // cancellation only: progress callbacks need not be thread-safe
  worker.cancel = ctx.cancel;
  worker.threads = 1;
  ctx.report("adaptive pocket", 0.0);
  parallel_for(candidates, ctx.threads, [&](std::size_t k) {
    std::vector<Entry>& order = orders[k];
    order.push_back((*entries)[k]);
    for (std::size_t q = 0; q < entries->size(); ++q)
      if (q != k) order.push_back((*entries)[q]);
    pocket::PixelStock stock = pocket::fresh_stock(m);
    pocket::cut_entry(stock, m, order.front());
    auto raw = pocket::generate_raw_path(m, stock, order, worker);
    if (!raw) {
      failed[k] = raw.status();
      return;
    }
    paths[k] = pocket::postprocess(m, order, raw.value(), costs);
    snap_to_wall_offset(m, paths[k]);
    reach_into_tips(m, paths[k]);
    drop_spurs(m, paths[k]);
    keep_chords_off_walls(m, paths[k]);
    times[k] = path_time_s(paths[k], costs);
  });
  std::size_t best = 0;
  for (std::size_t k = 0; k < candidates; ++k) {
    if (!failed[k].ok()) return failed[k];
    if (times[k] < times[best]) best = k;
  }
  ctx.report("adaptive pocket", 1.0);
  const std::vector<Entry>& order = orders[best];
  const Entry& e = order.front();
  LinkedPath& lp = paths[best];
  AdaptiveResult res;
  res.resolution_mm = m.h;
  res.rule_resolution_mm = m.rule_h;
  res.step_mm = m.step_mm;
  res.target_engagement_deg = m.target_deg;
  res.target_engagement_px = m.target_px;
  res.plunge_point = e.centre;
  for (std::size_t k = 0; k < candidates; ++k)
    res.candidate_plunge_points.push_back(orders[k].front().centre);
  res.candidate_time_s = times;
  res.chosen_candidate = static_cast<int>(best);
  res.helix_radius_mm = e.helix_radius_mm;
  res.trochoid_groups = lp.trochoid_groups;
  res.boundary_groups = lp.boundary_groups;
  std::optional<pocket::PixelStock> after;
  resimulate(m, order, lp, params.cut_map, res, &after);
  if (pocket::ride_walls_over_scallops(m, *after, params.wall_scallop_mm, lp))
    resimulate(m, order, lp, params.cut_map, res, &after);

  // Output simplification: runs between kind changes and jumps, Douglas-Peucker. A chord may
  // pass up to the tolerance inside the curve it replaces, i.e. towards an island the path
  // goes round or into a concave wall (the sweep measured 20 um at the default 0.25 pixel):
  // a chord is kept only if it stays the tool radius (plus wall stock) off the walls by exact
  // geometry; otherwise the run is split further.
  const double tol = params.simplify_tolerance_mm > 0.0 ? params.simplify_tolerance_mm : 0.25 * m.h;
  const double reach = m.radius_mm + m.wall_stock_mm;
  auto chord_ok = [&](std::size_t a, std::size_t b) {
    return pocket::keeps_off_walls(m, lp.pts[a], lp.pts[b], reach - 1e-7);
  };
  // Runs also break where a step's engagement crosses the neck plunges' thresholds
  // (kNeckTightDeg and kNeckSlotDeg, neck_runs): an output move is judged by what its steps remove
  // on average, and a 14.4 mm straight pass down a channel 0.05 mm wider than a ø10, a full slot
  // over its first 6 mm and lighter after, read 96 degrees as one move, so its slot was cut (168
  // degrees by the sweep) instead of plunged through.
  auto load_class = [&](std::size_t s) {
    if (s >= res.steps.size() || lp.kind[s] == StepKind::kLink) return 0;
    const double deg = res.steps[s].engagement_deg;
    return deg >= pocket::kNeckSlotDeg ? 2 : deg >= pocket::kNeckTightDeg ? 1 : 0;
  };
  std::vector<std::size_t> keep;
  std::size_t run = 0;
  for (std::size_t k = 1; k <= lp.kind.size(); ++k) {
    const bool brk = k == lp.kind.size() || lp.jump[k] || lp.jump[k - 1] ||
                     (lp.kind[k] == StepKind::kLink) != (lp.kind[k - 1] == StepKind::kLink) ||
                     load_class(k) != load_class(k - 1);
    if (!brk) continue;
    std::vector<std::size_t> part;
    pocket::simplify_indices(lp.pts, run, k, tol, part, chord_ok);
    if (!keep.empty() && keep.back() == part.front()) part.erase(part.begin());
    keep.insert(keep.end(), part.begin(), part.end());
    run = k;
  }
  if (keep.empty()) keep.push_back(0);

  Toolpath& tp = res.toolpath;
  tp.name = "adaptive pocket";
  tp.tool_number = tool.number;
  char desc[96];
  if (tool.kind == ToolKind::kBull) {
    std::snprintf(desc, sizeof desc, "%g mm bull-nose end mill R%g", tool.diameter_mm,
                  tool.corner_radius_mm);
  } else {
    std::snprintf(desc, sizeof desc, "%g mm %s end mill", tool.diameter_mm,
                  tool.kind == ToolKind::kBall ? "ball" : "flat");
  }
  tp.tool_description = desc;
  tp.tool_diameter_mm = tool.diameter_mm;
  tp.clearance_z_mm = params.clearance_z_mm;
  const double bottom = params.top_z_mm - params.depth_mm + params.floor_stock_mm;
  const double total = params.top_z_mm - bottom;
  const double sd = params.stepdown_mm > 0.0 ? params.stepdown_mm : total;
  const int layers = std::max(1, static_cast<int>(std::ceil(total / sd - 1e-9)));
  res.layers = layers;
  // Whether the path's step k is a new entry that goes straight down (no helix or ramp fits).
  auto straight_entry_at = [&](std::size_t k) {
    return lp.jump[k] && lp.entry[k] >= 0 && order[static_cast<std::size_t>(lp.entry[k])].solid;
  };
  res.straight_plunges = e.solid ? 1 : 0;
  for (std::size_t k = 0; k < lp.entry.size(); ++k) {
    if (straight_entry_at(k)) ++res.straight_plunges;
  }
  // The link feed where the re-simulation finds a move removing at most graze_px a step.
  // The chip of a cut of small radial depth ae thins as sqrt(ae / D): at the link feed, k
  // times the cutting feed, a step removing 1 / k^2 of a target step makes the chip of a
  // target step at the cutting feed (the default 5x: 4 %, which is cut_px, the threshold
  // below which a step counts as a link at all).
  const double graze_px =
      std::min(m.cut_px, m.target_px * std::pow(params.feed_mm_min / costs.link_feed_mm_min, 2));
  // What each kept move (keep[q - 1] -> keep[q]) removes in the re-simulation.
  std::vector<KeptMove> kept(keep.size());
  for (std::size_t q = 1; q < keep.size(); ++q) {
    KeptMove& k = kept[q];
    for (std::size_t s = keep[q - 1]; s < keep[q]; ++s) {
      k.px += res.steps[s].engagement_px;
      k.len += res.steps[s].length_mm;
      k.link = k.link && res.steps[s].engagement_px <= m.cut_px;
      // graze_px is per full step: a shorter step may remove its share of it. (Before, a
      // 0.17 mm move of a ø20 taking a pixel went at the link feed: 0.38 mm of radial
      // depth by the sweep against a graze of 0.16, random pocket 957.)
      k.fast = k.fast && res.steps[s].engagement_px <=
                             graze_px * std::min(1.0, res.steps[s].length_mm / m.step_mm);
    }
    // A move shorter than a pixel may reach material between the pixel centres that its
    // removal reads as none: it runs at the cutting feed (random pocket 3057, ø20: a tip
    // visit's last 0.08 mm move took 0.45 mm^2 at the link feed by the sweep, 5.6 mm of
    // radial depth per mm; such moves cost a few milliseconds each at the cutting feed).
    if (k.len < m.h) k.fast = false;
    // A move that reads as cutting anything at all where it comes within two pixels of a
    // wall's offset runs at the cutting feed: there the material the pixels see is the
    // least like what is there (free centres stop up to half a pixel short of the offset,
    // and the slivers earlier passes left against the wall are thinner than a pixel), and
    // the sweep found such moves taking two to three times the graze they read (random
    // pockets 2445 and 3057, ø20 at 40 %: 0.61 and 0.67 mm of radial depth at the link feed;
    // 955, ø16 at 10 %: 0.31 mm, a 0.15 mm move onto the offset). A link that reads nothing
    // keeps the link feed, so the links along the walls over cleared floor stay fast.
    if (k.fast && k.px > 0) {
      for (std::size_t s = keep[q - 1]; s <= keep[q] && k.fast; ++s)
        k.fast = m.walls.distance(lp.pts[s]) >= m.radius_mm + m.wall_stock_mm + 2.0 * m.h;
    }
    k.deg = angle_of(m, static_cast<int>(k.px), k.len);
  }
  // The first moves out of straight plunges' holes (neck_runs plunges them through where they
  // cut heavily): after the first entry's, and after each new entry's.
  if (e.solid && keep.size() > 1) kept[1].out_of_hole = true;
  for (std::size_t q = 1; q + 1 < keep.size(); ++q) {
    if (straight_entry_at(keep[q - 1])) kept[q + 1].out_of_hole = true;
  }
  // The scallop rides' and dabs' cuts and the tip visits' moves into the tips run at the
  // cutting feed: they take wall slivers a pixel or two thick, which the pixels read as less
  // than they are (part-like pockets 2409, 2422, 2444, ø16-ø20 with 0.2-0.25 mm pixels: dabs
  // took 0.41-0.47 mm of radial depth at the link feed by the sweep, against the 0.24-0.26
  // mm a link-feed move may graze).
  if (!lp.design_cut_ends.empty()) {
    auto before = [](Vec2 u, Vec2 v) { return u.x < v.x || (u.x == v.x && u.y < v.y); };
    std::vector<Vec2> cuts = lp.design_cut_ends;
    std::sort(cuts.begin(), cuts.end(), before);
    for (std::size_t q = 1; q < keep.size(); ++q) {
      for (std::size_t s = keep[q - 1] + 1; s <= keep[q] && kept[q].fast; ++s) {
        if (std::binary_search(cuts.begin(), cuts.end(), lp.pts[s], before)) kept[q].fast = false;
      }
    }
  }
  // A straight move between two points of a pass round an island's vertex cuts in by its
  // sagitta (4 um between points 0.4 mm apart, measured by the sweep): it goes through its
  // middle pushed off the wall to the same kWallClearanceMm as the wall passes. The same on
  // every layer, so found once.
  std::vector<std::vector<Vec2>> via(keep.size());
  for (std::size_t q = 1; q < keep.size(); ++q) {
    if (lp.jump[keep[q - 1]] ||
        pocket::far_from_walls(m, lp.pts[keep[q - 1]], lp.pts[keep[q]], reach))
      continue;
    pocket::keep_off_walls(m.walls, reach, kWallClearanceMm, lp.pts[keep[q - 1]], lp.pts[keep[q]],
                           via[q]);
  }
  // Necks: the way through each (its moves with their middle points) and the plunges on it.
  const std::vector<NeckRun> necks =
      params.straight_plunge ? pocket::neck_runs(m, lp, keep, kept) : std::vector<NeckRun>{};
  std::vector<std::vector<Vec2>> neck_way(necks.size());
  std::vector<std::vector<pocket::NeckPlunge>> neck_holes(necks.size());
  for (std::size_t i = 0; i < necks.size(); ++i) {
    std::vector<Vec2>& way = neck_way[i];
    way.push_back(lp.pts[keep[necks[i].first - 1]]);
    for (std::size_t r = necks[i].first; r <= necks[i].last; ++r) {
      way.insert(way.end(), via[r].begin(), via[r].end());
      way.push_back(lp.pts[keep[r]]);
    }
    neck_holes[i] = pocket::neck_plunge_points(way, 0.5 * m.radius_mm);
    res.neck_plunges += static_cast<int>(neck_holes[i].size());
    for (std::size_t s = keep[necks[i].first - 1]; s < keep[necks[i].last]; ++s)
      res.steps[s].plunged = true;
  }
  // Channels a little wider than the tool where the path loops: plunged along a wall and
  // side-milled instead (channel_plunges.cpp).
  // Each where that is no slower at the feeds than its loops (plunging a small tool deep at
  // the plunge feed can cost more than the loops do: random pocket 715, ø4 6 mm deep), and
  // leaves nothing the loops took (random pocket 2440, ø20: a run whose loops went round
  // into the corridor at the channel's end, 1.4 mm^2 there left by the sweep).
  std::vector<pocket::ChannelRun> channels;
  if (params.straight_plunge && params.channel_plunge) {
    const pocket::ChannelFeeds feeds{params.feed_mm_min, costs.link_feed_mm_min,
                                     params.plunge_feed_mm_min, params.rapid_mm_min,
                                     std::min(sd, total) + 1.0};
    std::vector<pocket::ChannelRun> faster;
    for (pocket::ChannelRun& c : pocket::channel_runs(m, lp, keep, kept, via, necks)) {
      const Vec2 from = lp.pts[keep[c.first - 1]], to = lp.pts[keep[c.last]];
      if (pocket::channel_plunges_time_s(c, from, to, feeds) <=
          pocket::channel_loops_time_s(c, kept, feeds))
        faster.push_back(std::move(c));
    }
    channels = pocket::runs_leaving_nothing(m, starting_stock(m, lp), order, lp, keep,
                                            std::move(faster), after->material());
  }
  std::vector<NeckRun> replaced = necks;  // the runs whose moves the emission replaces
  for (const pocket::ChannelRun& c : channels) {
    ++res.channels;
    res.channel_plunges += static_cast<int>(c.holes.size());
    for (std::size_t s = keep[c.first - 1]; s < keep[c.last]; ++s)
      res.steps[s].plunged = true;
    replaced.push_back({c.first, c.last, 0.0});
  }
  const std::vector<FeedMargin> margins =
      cutting_feed_margins(lp, keep, kept, via, replaced, 2.0 * m.h);
  int retracts = 0;
  for (int layer = 1; layer <= layers; ++layer) {
    const double z = layer == layers ? bottom : params.top_z_mm - sd * layer;
    const double z_prev = layer == 1 ? params.top_z_mm : params.top_z_mm - sd * (layer - 1);
    const double z_clear = layer == 1 ? z_prev + 1.0 : z_prev;
    entry_moves(tp, e, params, z_prev + 1.0, z_clear, z);
    Vec2 at = e.helix_radius_mm > 0.0 || e.plunge ? e.start : e.ramp_b;
    if (distance(at, lp.pts.front()) > 1e-9) {
      tp.moves.push_back(
          make_move(MoveKind::kFeed, to_vec3(lp.pts.front(), z), params.feed_mm_min, true));
    }
    std::size_t next_neck = 0, next_channel = 0;
    // Necks and channels: plunges from z_safe, rapids between them.
    const double z_safe = z_prev + 1.0;
    auto rapid = [&](Vec2 v, double zz) {
      tp.moves.push_back(make_move(MoveKind::kRapid, to_vec3(v, zz), 0, false));
    };
    for (std::size_t q = 1; q < keep.size(); ++q) {
      const std::size_t a = keep[q - 1], b = keep[q];
      const Vec3 end = to_vec3(lp.pts[b], z);
      // A retract goes straight up from where the tool is: after a straight plunge the
      // path's point there may have been snapped to a wall offset a few hundredths away, and
      // a rapid towards it would move sideways at the floor.
      const auto retract_here = [&] {
        const Vec3 here = tp.moves.back().end;
        tp.moves.push_back(
            make_move(MoveKind::kRapid, {here.x, here.y, params.clearance_z_mm}, 0, false));
      };
      if (lp.jump[a] && lp.entry[a] >= 0) {
        ++retracts;
        retract_here();
        const Entry& ne = order[static_cast<std::size_t>(lp.entry[a])];
        entry_moves(tp, ne, params, z_prev + 1.0, z_clear, z);
        continue;
      }
      if (lp.jump[a]) {
        ++retracts;
        retract_here();
        tp.moves.push_back(
            make_move(MoveKind::kRapid, to_vec3(lp.pts[b], params.clearance_z_mm), 0, false));
        tp.moves.push_back(make_move(MoveKind::kRapid, to_vec3(lp.pts[b], z_prev + 1.0), 0, false));
        tp.moves.push_back(make_move(MoveKind::kPlunge, end, params.plunge_feed_mm_min, false));
        continue;
      }
      if (next_neck < necks.size() && necks[next_neck].first == q) {
        // A neck barely wider than the tool, where every way through is a full slot: plunged
        // through instead (neck_runs), then the passes between the plunges' holes are taken
        // backwards, and the moves go through in the air at the link feed.
        const NeckRun& n = necks[next_neck];
        const std::vector<Vec2>& neck = neck_way[next_neck];
        const std::vector<pocket::NeckPlunge>& holes = neck_holes[next_neck];
        ++next_neck;
        rapid(tp.moves.back().end.xy(), z_safe);  // straight up from where the tool is
        std::size_t v = 0;
        for (const pocket::NeckPlunge& h : holes) {
          for (; v < h.after; ++v)
            rapid(neck[v + 1], z_safe);
          if (distance(h.at, neck[v]) > 1e-9) rapid(h.at, z_safe);
          tp.moves.push_back(
              make_move(MoveKind::kPlunge, to_vec3(h.at, z), params.plunge_feed_mm_min, true));
          if (&h != &holes.back()) rapid(h.at, z_safe);
        }
        for (std::size_t k = neck.size() - 1; k-- > 0;) {
          tp.moves.push_back(
              make_move(MoveKind::kFeed, to_vec3(neck[k], z), params.feed_mm_min, true));
        }
        for (std::size_t k = 1; k < neck.size(); ++k) {
          tp.moves.push_back(
              make_move(MoveKind::kFeed, to_vec3(neck[k], z), costs.link_feed_mm_min, false));
        }
        q = n.last;
        continue;
      }
      if (next_channel < channels.size() && channels[next_channel].first == q) {
        // A channel a little wider than the tool: plunged along one wall, then the strip
        // left along the other taken by side passes from its end back to its start (between
        // two, the way back through the cleared channel at the link feed), then the cusps
        // between the holes by a pass from the start along their wall to the run's end.
        const pocket::ChannelRun& c = channels[next_channel++];
        rapid(tp.moves.back().end.xy(), z_safe);  // straight up from where the tool is
        std::optional<Vec2> hole;                 // the hole the tool is down in
        for (const pocket::ChannelStep& s : pocket::channel_steps(c, lp.pts[keep[c.last]])) {
          if (s.kind == pocket::ChannelStep::Kind::kPlunge) {
            if (hole) rapid(*hole, z_safe);
            rapid(s.to, z_safe);
            tp.moves.push_back(
                make_move(MoveKind::kPlunge, to_vec3(s.to, z), params.plunge_feed_mm_min, true));
            hole = s.to;
          } else {
            const bool cutting = s.kind == pocket::ChannelStep::Kind::kCut;
            tp.moves.push_back(make_move(MoveKind::kFeed, to_vec3(s.to, z),
                                         cutting ? params.feed_mm_min : costs.link_feed_mm_min,
                                         cutting));
          }
        }
        q = c.last;
        continue;
      }
      const KeptMove& k = kept[q];
      Move mv = make_move(MoveKind::kFeed, end,
                          k.fast ? costs.link_feed_mm_min : params.feed_mm_min, !k.link);
      mv.engagement_deg = static_cast<float>(k.deg);
      // The pieces, split where the link feed starts and ends: a link-feed move's margins
      // next to cutting moves run at the cutting feed.
      std::vector<Vec2> pts = via[q];
      pts.push_back(lp.pts[b]);
      const double fast_from = margins[q].head, fast_to = margins[q].length - margins[q].tail;
      std::vector<std::pair<double, Vec2>> stops;  // (length along the move, point)
      double along = 0.0;
      for (std::size_t i = 0; i < pts.size(); ++i) {
        const Vec2 from = i == 0 ? lp.pts[a] : pts[i - 1];
        const double len = distance(from, pts[i]);
        if (k.fast && fast_to > fast_from) {
          for (const double split : {fast_from, fast_to}) {
            if (split > along + 1e-9 && split < along + len - 1e-9)
              stops.push_back({split, from + (pts[i] - from) * ((split - along) / len)});
          }
        }
        along += len;
        stops.push_back({along, pts[i]});
      }
      double prev = 0.0;
      for (const auto& [stop, v] : stops) {
        Move piece = mv;
        const bool fast = k.fast && prev >= fast_from - 1e-9 && stop <= fast_to + 1e-9;
        piece.feed_mm_min = fast ? costs.link_feed_mm_min : params.feed_mm_min;
        piece.end = to_vec3(v, z);
        tp.moves.push_back(piece);
        prev = stop;
      }
    }
    tp.moves.push_back(
        make_move(MoveKind::kRapid,
                  {tp.moves.back().end.x, tp.moves.back().end.y, params.clearance_z_mm}, 0, false));
  }
  res.retracts_per_layer = retracts / layers;
  if (params.smooth_corners)
    pocket::smooth_cutting_corners(m, tp, std::clamp(0.15 * m.target_deg, 2.0, 6.0));
  return res;
}

}  // namespace swarf
