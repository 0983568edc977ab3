// seed 001 section 3.1: scanning paths for a ball end mill from the tri-slice model, and the
// roughing scheme of Table 1 (contour paths: waterline.cpp).
#include "swarf/trislice/surface_paths.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <optional>
#include <string>

#include "swarf/core/parallel.h"
#include "swarf/toolpath/postprocess.h"
#include "trislice/mesh_contacts.h"
#include "trislice/paths_internal.h"

namespace swarf {

namespace trislice_detail {

Status need_ball(const Tool& tool) {
  SWARF_RETURN_IF_ERROR(validate(tool));
  if (tool.kind != ToolKind::kBall)
    return bad_parameter("tri-slice paths need a ball end mill (seed 001 section 4.3), got " +
                         tool.description());
  return {};
}

double clearance_of(double given, const TriSliceModel& model, double extra_top) {
  return std::isfinite(given) ? given : std::max(model.bounds.max.z, extra_top) + 5.0;
}

Toolpath new_toolpath(const Tool& tool, std::string name, double clearance) {
  Toolpath tp;
  tp.name = std::move(name);
  tp.tool_number = tool.number;
  tp.tool_description = tool.description();
  tp.tool_diameter_mm = tool.diameter_mm;
  tp.clearance_z_mm = clearance;
  return tp;
}

}  // namespace trislice_detail

namespace {

using trislice_detail::clearance_of;
using trislice_detail::need_ball;
using trislice_detail::new_toolpath;

constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<double> positions(double from, double to, double step) {
  std::vector<double> out;
  if (!(step > 0.0) || !(to >= from)) return out;
  const auto n = static_cast<std::size_t>(std::floor((to - from) / step + 1e-9));
  for (std::size_t k = 0; k <= n; ++k)
    out.push_back(from + static_cast<double>(k) * step);
  if (out.back() < to - 1e-9) out.push_back(to);
  return out;
}

// One line of CL points as moves: rapid over the start, plunge, feed along, retract. The
// plunge is safe for a 3-axis cutter: the CL point is the lowest safe height over its xy.
void emit_line(Toolpath& tp, const std::vector<Vec3>& pts, double feed, double plunge) {
  if (pts.empty()) return;
  tp.rapid_to({pts.front().x, pts.front().y, tp.clearance_z_mm});
  tp.plunge_to(pts.front().z, plunge);
  for (std::size_t k = 1; k < pts.size(); ++k)
    tp.feed_to(pts[k], feed);
}

// Lines (each in the + direction) to moves, one-way or zig-zag. Points above clip_z are
// lowered to it (a roughing layer above the stock cuts air at the stock top) and a line that
// lies entirely at the clip height is dropped.
Toolpath lines_to_toolpath(std::vector<std::vector<Vec3>> lines, const ScanParams& p, double clip_z,
                           Toolpath tp, const std::function<double(Vec2)>& cl_at, int threads) {
  // Clipping and simplifying are per line, so they run in parallel (each line writes only its
  // own slot); which lines are reversed depends on the lines before, so that is decided in
  // between, serially, and the moves are emitted serially at the end. Same moves as one pass.
  const std::size_t n = lines.size();
  std::vector<char> keep(n, 0);
  parallel_for(n, threads, [&](std::size_t i) {
    bool any = false;
    for (Vec3& q : lines[i]) {
      if (q.z < clip_z - 1e-9) any = true;
      q.z = std::min(q.z, clip_z);
    }
    keep[i] = any && !lines[i].empty();
  });
  std::vector<char> reversed(n, 0);
  for (std::size_t i = 0, kept = 0; i < n; ++i)
    if (keep[i]) reversed[i] = p.zigzag && (kept++ % 2 == 1);
  parallel_for(n, threads, [&](std::size_t i) {
    if (!keep[i]) return;
    std::vector<Vec3>& line = lines[i];
    if (reversed[i]) std::reverse(line.begin(), line.end());
    if (p.tolerance_mm > 0.0) line = simplify_polyline(line, p.tolerance_mm);
  });
  bool linked = false;  // the tool is down at the end of the previous line
  for (std::size_t i = 0; i < n; ++i) {
    if (!keep[i]) {
      if (linked) tp.retract();
      linked = false;
      continue;
    }
    const std::vector<Vec3>& pts = lines[i];
    if (p.zigzag && linked) {
      // Stay down: follow the CL along the region edge from the last point to the next line,
      // so the link never gouges and never lifts more than the surface asks for.
      const Vec3 a = tp.position(), b = pts.front();
      const double len = distance(a.xy(), b.xy());
      const int steps = std::max(1, static_cast<int>(std::ceil(len / p.sampling_mm)));
      for (int k = 1; k < steps; ++k) {
        const Vec2 xy = a.xy() + (b.xy() - a.xy()) * (static_cast<double>(k) / steps);
        tp.feed_to({xy.x, xy.y, std::min(cl_at(xy), clip_z)}, p.feed_mm_min);
      }
      tp.feed_to(b, p.feed_mm_min);
      for (std::size_t k = 1; k < pts.size(); ++k)
        tp.feed_to(pts[k], p.feed_mm_min);
    } else {
      if (linked) tp.retract();
      emit_line(tp, pts, p.feed_mm_min, p.plunge_feed_mm_min);
    }
    linked = p.zigzag;
    if (!p.zigzag) tp.retract();
  }
  if (linked) tp.retract();
  return tp;
}

// Stride of the first adaptive pass: the largest power of two k with k * sampling <= max step.
// At least 8: stretches of four steps or less are evaluated at every lattice point anyway.
std::size_t coarse_stride(const ScanParams& p) {
  std::size_t k = 8;
  while (2.0 * static_cast<double>(k) * p.sampling_mm <= p.adaptive_max_step_mm + 1e-9 && k < 1024)
    k *= 2;
  return k;
}

// Adaptive refinement of one line between lattice indices a and b (a < b), with the points at
// a, b and the midpoint m known. Appends the points after a up to b, in order.
//
// The argument. Along a line the ball centre is the upper envelope of circular arcs, one per
// point of the model under the ball (radius sqrt(R^2 - d^2), d its distance across the line).
// Over a stretch held by one arc, the gap between arc and chord is largest at the midpoint;
// halving the stretch quarters it. Where contacts take over from each other the envelope
// can bend both ways within a stretch (an S-bend at a fillet's edge puts its midpoint on the
// chord and its quarter points off it), so a stretch is accepted only when its midpoint and
// both quarter points lie within tol / 2 of the chord; otherwise each half is refined, its
// midpoint being known already. The half: on a convex part the envelope is concave, and a
// concave curve whose quarter-point chords sit within e of the samples stays within 2 e of
// the path between them; on a faceted convex surface it carries ridges of about
// R (1 - cos(phi / 2)) at the facet edges (1.2 um for the 2.8 deg facets of the Table 2 part),
// which tol / 2 keeps inside tol. A stretch of four lattice steps or less is thereby
// evaluated at every lattice point; only longer ones, on near-straight stretches (the plate,
// gentle slopes), leave lattice points out, and a feature hiding there would have to miss
// all three interior samples. Measured against the uniform grid in
// TriSlicePaths.AdaptiveScan*.
//
// Each sample keeps the scan hint its query ended with, and a new query starts from the hint
// of its nearest known neighbour: the queries are then as quick as along the uniform grid.
struct Sample {
  Vec3 p;
  ScanHint hint;
};

// Returns whether the stretch was accepted whole.
template <class Eval>
bool refine(std::size_t a, const Sample& sa, std::size_t m, const Sample& sm, std::size_t b,
            const Sample& sb, double tol, const Eval& eval, std::vector<Vec3>& out) {
  if (b - a <= 3) {  // every lattice point (m known; a third one at the end of a line)
    ScanHint hint = sa.hint;
    for (std::size_t k = a + 1; k <= b; ++k) {
      const Sample q = k == m ? sm : k == b ? sb : eval(k, hint);
      hint = q.hint;
      out.push_back(q.p);
    }
    return true;
  }
  const std::size_t q1 = a + (m - a) / 2, q3 = m + (b - m) / 2;
  const Sample s1 = eval(q1, sa.hint), s3 = eval(q3, sm.hint);
  const Vec3 &pa = sa.p, &pb = sb.p;
  auto off = [&](const Vec3& q) {
    // Lines run along x or y: one of the two differences is zero.
    const double t = (q.x - pa.x + q.y - pa.y) / (pb.x - pa.x + pb.y - pa.y);
    return std::fabs(q.z - (pa.z + t * (pb.z - pa.z))) > 0.5 * tol;
  };
  if (off(s1.p) || off(sm.p) || off(s3.p)) {
    refine(a, sa, q1, s1, m, sm, tol, eval, out);
    refine(m, sm, q3, s3, b, sb, tol, eval, out);
    return false;
  }
  for (const Sample* q : {&s1, &sm, &s3, &sb})
    out.push_back(q->p);
  return true;
}

// Adaptive lines, second stage: what one line learnt is tried on its neighbours.
//
// Why. A feature just inside the ball's reach from a line holds the ball up over a stretch of
// that line as short as one likes (a point at lateral distance d: 2 sqrt(r^2 - d^2)) and as
// high as the feature, so the samples of one line can step over it and the path between them
// cuts through the feature (found on a gear by bench/surface_stress.sh: 2.6 mm between samples
// 0.4 mm apart; TriSliceStress.AdaptiveScanDoesNotMissANarrowBumpNearTheBallRim). The line
// nearest to such a feature (at most half a stepover from it) sees a wide bump and is
// refined there, and the bump of a line further away lies within that stretch. So each line
// is evaluated at the lattice points where a neighbouring line was refined (points closer to
// a neighbour than a quarter of the first-pass stride, or evaluated here because of an
// earlier round) and where the neighbour's CL rises above this line's chord; a stretch of the line
// in which such a point leaves the chord by more than tol / 2 is evaluated at every lattice point,
// and those points are passed on to the next lines in the next round, until no line changes. Points
// that sit on the chord are kept (they are lattice points like any other) but not passed on.
//
// Rounds read the previous round's lines and each line writes only its own: identical for any
// thread count. Lines are points on the lattice `along`; a point's lattice index is found by
// its coordinate (copied from `along`, so equal to the bit).
template <class EvalAt>
void cross_check_lines(std::vector<std::vector<Vec3>>& lines, const std::vector<double>& along,
                       bool along_x, std::size_t stride, double tol, const EvalAt& eval_at,
                       const Context& ctx) {
  const std::size_t n = lines.size();
  if (n < 2) return;
  struct Pt {
    std::size_t k;  // lattice index
    Vec3 p;
    bool refined;  // passed on to the neighbours
  };
  // The lines as lattice points; passing[i]: line i has points to pass on this round. Each
  // round reads `cur` and writes `add` (line i only its own), then a second pass merges:
  // identical for any thread count. Only lines beside one that passes points on are visited.
  std::vector<std::vector<Pt>> cur(n), add(n);
  std::vector<char> passing(n, 0);
  parallel_for(n, ctx.threads, [&](std::size_t i) {
    const std::vector<Vec3>& line = lines[i];
    std::vector<Pt>& out = cur[i];
    out.reserve(line.size());
    std::size_t k = 0;  // the coordinates rise along the line and are copies of `along`
    for (const Vec3& q : line) {
      const double u = along_x ? q.x : q.y;
      while (k < along.size() && along[k] < u)
        ++k;
      out.push_back({k, q, false});
    }
    // First pass: refined where the spacing fell below the quarter stride.
    const std::size_t quarter = stride / 4;
    for (std::size_t j = 0; j < out.size(); ++j) {
      const bool prev = j > 0 && out[j].k - out[j - 1].k < quarter;
      const bool next = j + 1 < out.size() && out[j + 1].k - out[j].k < quarter;
      out[j].refined = prev || next;
      passing[i] = passing[i] || out[j].refined;
    }
  });
  for (std::size_t round = 0; round < n + 1; ++round) {
    parallel_for(n, ctx.threads, [&](std::size_t i) {
      add[i].clear();
      if (ctx.cancelled()) return;
      if (!((i > 0 && passing[i - 1]) || (i + 1 < n && passing[i + 1]))) return;
      const std::vector<Pt>& own = cur[i];
      // Candidates: refined lattice indices of the neighbours that this line lacks, with the
      // neighbours' (highest) CL there.
      // Each neighbour's points rise in k: the two lists are merged, not sorted.
      std::vector<std::pair<std::size_t, double>> cand;
      {
        static const std::vector<Pt> kNone;
        const std::vector<Pt>& lo = i > 0 ? cur[i - 1] : kNone;
        const std::vector<Pt>& hi = i + 1 < n ? cur[i + 1] : kNone;
        std::size_t u = 0, v = 0;
        auto next_refined = [](const std::vector<Pt>& l, std::size_t& at) {
          while (at < l.size() && !l[at].refined)
            ++at;
          return at < l.size();
        };
        for (;;) {
          const bool has_lo = next_refined(lo, u), has_hi = next_refined(hi, v);
          if (!has_lo && !has_hi) break;
          if (has_lo && has_hi && lo[u].k == hi[v].k) {
            cand.emplace_back(lo[u].k, std::max(lo[u].p.z, hi[v].p.z));
            ++u;
            ++v;
          } else if (has_lo && (!has_hi || lo[u].k < hi[v].k)) {
            cand.emplace_back(lo[u].k, lo[u].p.z);
            ++u;
          } else {
            cand.emplace_back(hi[v].k, hi[v].p.z);
            ++v;
          }
        }
      }
      std::vector<Pt>& added = add[i];
      ScanHint hint;
      std::size_t j = 0;  // own[j - 1].k < c < own[j].k
      for (std::size_t c = 0; c < cand.size();) {
        const std::size_t k = cand[c].first;
        while (j < own.size() && own[j].k < k)
          ++j;
        if (j == 0 || j == own.size() || own[j].k == k) {  // evaluated (both ends always are)
          ++c;
          continue;
        }
        // All candidates inside the stretch own[j - 1] .. own[j]. A bump this line hides from a
        // feature lies lower than the bump the same feature makes in the neighbour nearer to
        // it, so only where a neighbour rises above the chord can this line hide one there.
        const Pt &a = own[j - 1], &b = own[j];
        const auto chord = [&](std::size_t m) {
          const double t = static_cast<double>(m - a.k) / static_cast<double>(b.k - a.k);
          return a.p.z + t * (b.p.z - a.p.z);
        };
        bool off = false;
        std::vector<Pt> got;
        for (; c < cand.size() && cand[c].first < b.k; ++c) {
          const std::size_t m = cand[c].first;
          if (cand[c].second <= chord(m) + 0.5 * tol) continue;
          const auto s = eval_at(i, m, hint);
          hint = s.hint;
          off = off || std::fabs(s.p.z - chord(m)) > 0.5 * tol;
          got.push_back({m, s.p, false});
        }
        if (off) {  // the whole stretch, every lattice point, passed on
          std::size_t g = 0;
          for (std::size_t m = a.k + 1; m < b.k; ++m) {
            if (g < got.size() && got[g].k == m) {
              added.push_back({m, got[g++].p, true});
              continue;
            }
            const auto s = eval_at(i, m, hint);
            hint = s.hint;
            added.push_back({m, s.p, true});
          }
        } else {
          added.insert(added.end(), got.begin(), got.end());
        }
      }
    });
    if (ctx.cancelled()) break;
    // The points passed on this round have been read: the new points join their lines, and
    // only the new points of refined stretches are passed on next round.
    parallel_for(n, ctx.threads, [&](std::size_t i) {
      std::vector<Pt>& own = cur[i];
      if (passing[i])
        for (Pt& q : own)
          q.refined = false;
      passing[i] = 0;
      if (add[i].empty()) return;
      std::vector<Pt> merged;
      merged.reserve(own.size() + add[i].size());
      std::merge(own.begin(), own.end(), add[i].begin(), add[i].end(), std::back_inserter(merged),
                 [](const Pt& x, const Pt& y) { return x.k < y.k; });
      own = std::move(merged);
      for (const Pt& q : add[i])
        passing[i] = passing[i] || q.refined;
    });
    if (std::none_of(passing.begin(), passing.end(), [](char c) { return c; })) break;
  }
  parallel_for(n, ctx.threads, [&](std::size_t i) {
    lines[i].clear();
    for (const Pt& q : cur[i])
      lines[i].push_back(q.p);
  });
}

// CL lines (tool tips) at offset extra above the part, tips clipped to clip_z (roughing layers
// above the stock) before the adaptive test, so the chord test sees the path that is cut.
Result<std::vector<std::vector<Vec3>>> cl_lines(const TriSliceTop& top, const Box3& bounds,
                                                double tool_radius_mm, double extra_mm,
                                                const ScanParams& p, double clip_z, double tol,
                                                const Context& ctx) {
  SWARF_RETURN_IF_ERROR(validate(p));
  if (!(tool_radius_mm > 0.0)) return bad_parameter("tool radius must be positive");
  const Box2 region = p.region.empty() ? bounds.xy() : p.region;
  if (region.empty()) return bad_parameter("scan: empty region");
  const bool along_x = p.direction == Axis::kX;
  const std::vector<double> across = along_x ? positions(region.min.y, region.max.y, p.stepover_mm)
                                             : positions(region.min.x, region.max.x, p.stepover_mm);
  const std::vector<double> along = along_x ? positions(region.min.x, region.max.x, p.sampling_mm)
                                            : positions(region.min.y, region.max.y, p.sampling_mm);
  if (static_cast<double>(across.size()) * static_cast<double>(along.size()) > 2e8)
    return bad_parameter("scan: more than 200 million CL points");
  const double floor_z = std::isfinite(p.floor_z_mm) ? p.floor_z_mm : bounds.min.z;
  const double R = tool_radius_mm + extra_mm;
  // The family whose planes contain the scan lines is asked first: Eq. (1) exactly there.
  const Axis primary = along_x ? Axis::kY : Axis::kX;
  const std::size_t stride = p.adaptive ? coarse_stride(p) : 1;
  std::vector<std::vector<Vec3>> lines(across.size());
  std::optional<trislice_detail::MeshContacts> vertices;
  if (p.vertex_mesh != nullptr) vertices.emplace(*p.vertex_mesh, R);
  auto eval_at = [&](std::size_t i, std::size_t k, const ScanHint& from) {
    const Vec2 xy = along_x ? Vec2{along[k], across[i]} : Vec2{across[i], along[k]};
    Sample out{{}, from};
    if (clip_z < kInf) {
      // Roughing layers above the stock: the hinted edges give a lower bound of the centre
      // height; when it already lifts the tip to the clip height, the point is the clip
      // height whatever the full search would add, so the search is skipped (exact).
      const Axis secondary = along_x ? Axis::kX : Axis::kY;
      const double lb = std::max({top.family(primary).hint_height(xy, R, from.primary),
                                  top.family(secondary).hint_height(xy, R, from.secondary),
                                  top.levels().hint_height(xy, R, from.level)});
      if (lb - tool_radius_mm >= clip_z) {
        out.p = {xy.x, xy.y, clip_z};
        return out;
      }
    }
    double c = top.centre_height(xy, R, primary, &out.hint);
    if (vertices) c = vertices->centre_height(xy, R, c);
    const double z = c > -kInf ? std::max(c - tool_radius_mm, floor_z) : floor_z;
    out.p = {xy.x, xy.y, std::min(z, clip_z)};
    return out;
  };
  parallel_for(across.size(), ctx.threads, [&](std::size_t i) {
    if (ctx.cancelled()) return;
    auto eval = [&](std::size_t k, const ScanHint& from) { return eval_at(i, k, from); };
    std::vector<Vec3>& line = lines[i];
    if (along.empty()) return;
    if (stride <= 1) {
      line.reserve(along.size());
      ScanHint hint;
      for (std::size_t k = 0; k < along.size(); ++k) {
        const Sample q = eval(k, hint);
        hint = q.hint;
        line.push_back(q.p);
      }
      return;
    }
    // Step control: a stretch refined down to the lattice is followed by one half as long
    // (not below four steps), an accepted one by one twice as long (up to the stride), so
    // curved stretches are walked in short steps whose hints come from close by.
    Sample sa = eval(0, ScanHint{});
    line.push_back(sa.p);
    std::size_t h = stride;
    for (std::size_t a = 0; a + 1 < along.size();) {
      const std::size_t b = std::min(a + h, along.size() - 1), m = a + (b - a) / 2;
      const Sample sm = m != a ? eval(m, sa.hint) : sa;
      const Sample sb = eval(b, sm.hint);
      const bool whole = refine(a, sa, m, sm, b, sb, tol, eval, line);
      h = whole ? std::min(2 * h, stride) : std::max<std::size_t>(4, h / 2);
      a = b;
      sa = sb;
    }
  });
  if (ctx.cancelled()) return Status{Error::kCancelled, "scan: cancelled"};
  if (stride > 1) cross_check_lines(lines, along, along_x, stride, tol, eval_at, ctx);
  if (ctx.cancelled()) return Status{Error::kCancelled, "scan: cancelled"};
  if (stride > 1 && p.refine_steep) {
    // Below the lattice where a steep stretch still leaves the CL (postprocess.h).
    auto eval_xy = [&](Vec2 xy, ScanHint& hint) {
      double c = top.centre_height(xy, R, primary, &hint);
      if (vertices) c = vertices->centre_height(xy, R, c);
      const double z = c > -kInf ? std::max(c - tool_radius_mm, floor_z) : floor_z;
      return std::min(z, clip_z);
    };
    parallel_for(lines.size(), ctx.threads, [&](std::size_t i) {
      if (ctx.cancelled()) return;
      ScanHint hint;
      lines[i] = refine_steep_stretches(lines[i], tol, [&](Vec2 xy) { return eval_xy(xy, hint); });
    });
    if (ctx.cancelled()) return Status{Error::kCancelled, "scan: cancelled"};
  }
  return lines;
}

}  // namespace

double trislice_height_error_bound_mm(double pitch_mm, double radius_mm) {
  if (!(pitch_mm > 0.0) || !(radius_mm > 0.0)) return 0.0;
  // offset.h: ds^2 / (8 R sin^2 theta n_z) with sin^2 theta = 2/3 and n_z = 1/sqrt(3).
  return 3.0 * std::sqrt(3.0) * pitch_mm * pitch_mm / (16.0 * radius_mm);
}

double effective_adaptive_tolerance_mm(const ScanParams& p, double pitch_mm, double radius_mm) {
  return std::max(p.adaptive_tolerance_mm,
                  p.adaptive_model_fraction * trislice_height_error_bound_mm(pitch_mm, radius_mm));
}

Status validate(const ScanParams& p) {
  if (p.direction == Axis::kZ) return bad_parameter("scan direction must be x or y");
  if (!(p.stepover_mm > 0.0))
    return bad_parameter("stepover " + std::to_string(p.stepover_mm) + " mm must be positive");
  if (!(p.sampling_mm > 0.0))
    return bad_parameter("sampling " + std::to_string(p.sampling_mm) + " mm must be positive");
  if (!(p.stock_to_leave_mm >= 0.0)) return bad_parameter("stock to leave must be >= 0 mm");
  if (!(p.tolerance_mm >= 0.0)) return bad_parameter("tolerance must be >= 0 mm");
  if (!(p.adaptive_tolerance_mm >= 0.0)) return bad_parameter("adaptive tolerance must be >= 0 mm");
  if (!(p.adaptive_max_step_mm > 0.0)) return bad_parameter("adaptive max step must be positive");
  if (!(p.adaptive_model_fraction >= 0.0) || p.adaptive_model_fraction > 100.0)
    return bad_parameter("adaptive model fraction must be in 0..100");
  if (!(p.feed_mm_min > 0.0) || !(p.plunge_feed_mm_min > 0.0))
    return bad_parameter("feeds must be positive");
  return {};
}

Status validate(const RoughingParams& p) {
  if (p.layers < 1 || p.layers > 1000) return bad_parameter("rough layers must be in 1..1000");
  if (!(p.stepdown_mm > 0.0)) return bad_parameter("roughing stepdown must be positive");
  if (!(p.stepover_mm > 0.0)) return bad_parameter("roughing stepover must be positive");
  if (!(p.margin_mm >= 0.0)) return bad_parameter("roughing margin must be >= 0 mm");
  if (!(p.min_pitch_mm >= 0.0)) return bad_parameter("roughing min pitch must be >= 0 mm");
  if (!(p.sampling_mm >= 0.0)) return bad_parameter("roughing sampling must be >= 0 mm");
  if (!(p.adaptive_tolerance_mm >= 0.0))
    return bad_parameter("roughing adaptive tolerance must be >= 0 mm");
  if (!(p.adaptive_max_step_mm > 0.0))
    return bad_parameter("roughing adaptive max step must be positive");
  return {};
}

Status validate(const ContourParams& p) {
  if (!(p.stepdown_mm > 0.0)) return bad_parameter("contour stepdown must be positive");
  if (!(p.stock_to_leave_mm >= 0.0)) return bad_parameter("stock to leave must be >= 0 mm");
  if (p.radial_passes < 1) return bad_parameter("radial passes must be >= 1");
  if (!(p.radial_step_mm > 0.0)) return bad_parameter("radial step must be positive");
  if (!(p.arc_tolerance_mm > 0.0)) return bad_parameter("arc tolerance must be positive");
  if (!(p.feed_mm_min > 0.0) || !(p.plunge_feed_mm_min > 0.0))
    return bad_parameter("feeds must be positive");
  return {};
}

Result<std::vector<std::vector<Vec3>>> scan_cl_lines(const TriSliceTop& top, const Box3& bounds,
                                                     double tool_radius_mm, double extra_mm,
                                                     const ScanParams& p, const Context& ctx) {
  // Eq. (1) holds a face between two slices only by slices within the ball's reach: from a
  // pitch of 2 R on, a flat top midway is not seen and the ball sinks through it; from R on,
  // the model's bound is a third of R. A silent gouge of that size is worse than an error.
  const double R = tool_radius_mm + extra_mm;
  if (top.pitch_mm() >= R) {
    return bad_parameter("scan: slice pitch " + std::to_string(top.pitch_mm()) +
                         " mm is not smaller than the ball radius " + std::to_string(R) +
                         " mm: faces between slices would be missed or gouged (error bound " +
                         std::to_string(trislice_height_error_bound_mm(top.pitch_mm(), R)) +
                         " mm); use a pitch below a quarter of the radius");
  }
  return cl_lines(top, bounds, tool_radius_mm, extra_mm, p, kInf,
                  effective_adaptive_tolerance_mm(p, top.pitch_mm(), tool_radius_mm + extra_mm),
                  ctx);
}

Result<Toolpath> scan_finishing(const TriSliceModel& model, const TriSliceTop& top,
                                const Tool& tool, const ScanParams& p, const Context& ctx) {
  SWARF_RETURN_IF_ERROR(need_ball(tool));
  auto lines = scan_cl_lines(top, model.bounds, tool.radius(), p.stock_to_leave_mm, p, ctx);
  if (!lines.ok()) return lines.status();
  return scan_finishing_from_lines(model, top, tool, p, std::move(lines).value(), ctx);
}

Result<Toolpath> scan_finishing_from_lines(const TriSliceModel& model, const TriSliceTop& top,
                                           const Tool& tool, const ScanParams& p,
                                           std::vector<std::vector<Vec3>> lines,
                                           const Context& ctx) {
  const double R = tool.radius() + p.stock_to_leave_mm;
  const Axis primary = p.direction == Axis::kX ? Axis::kY : Axis::kX;
  const double floor_z = std::isfinite(p.floor_z_mm) ? p.floor_z_mm : model.bounds.min.z;
  std::optional<trislice_detail::MeshContacts> vertices;
  if (p.vertex_mesh != nullptr) vertices.emplace(*p.vertex_mesh, R);
  auto cl_at = [&](Vec2 xy) {
    double c = top.centre_height(xy, R, primary);
    if (vertices) c = vertices->centre_height(xy, R, c);
    return c > -kInf ? std::max(c - tool.radius(), floor_z) : floor_z;
  };
  return scan_finishing_from_cl(std::move(lines), tool, p,
                                clearance_of(p.clearance_z_mm, model, -kInf),
                                "tri-slice scan finishing", cl_at, ctx);
}

Result<Toolpath> scan_finishing_from_cl(std::vector<std::vector<Vec3>> lines, const Tool& tool,
                                        const ScanParams& p, double clearance_z_mm,
                                        std::string name, const std::function<double(Vec2)>& cl_at,
                                        const Context& ctx) {
  SWARF_RETURN_IF_ERROR(need_ball(tool));
  SWARF_RETURN_IF_ERROR(validate(p));
  Toolpath tp =
      lines_to_toolpath(std::move(lines), p, kInf,
                        new_toolpath(tool, std::move(name), clearance_z_mm), cl_at, ctx.threads);
  if (tp.empty()) return Status{Error::kEmptyResult, "scan finishing: no CL points"};
  return tp;
}

Result<Toolpath> scan_roughing(const TriSliceModel& model, const TriSliceTop& top, const Tool& tool,
                               const ScanParams& params, const RoughingParams& rough,
                               const Context& ctx) {
  SWARF_RETURN_IF_ERROR(need_ball(tool));
  SWARF_RETURN_IF_ERROR(validate(rough));
  ScanParams p = params;
  p.stepover_mm = rough.stepover_mm;
  if (rough.sampling_mm > 0.0) p.sampling_mm = rough.sampling_mm;
  p.adaptive_max_step_mm = rough.adaptive_max_step_mm;
  const double stock_top =
      std::isfinite(rough.stock_top_mm) ? rough.stock_top_mm : model.bounds.max.z;
  Toolpath tp = new_toolpath(tool, "tri-slice scan roughing",
                             clearance_of(p.clearance_z_mm, model, stock_top));
  const Axis primary = p.direction == Axis::kX ? Axis::kY : Axis::kX;
  const double floor_z = std::isfinite(p.floor_z_mm) ? p.floor_z_mm : model.bounds.min.z;
  const int stride =
      std::max(1, static_cast<int>(std::floor(rough.min_pitch_mm / model.pitch_mm + 1e-9)));
  TriSliceTop coarse;
  if (stride > 1) coarse = TriSliceTop::build(model, 0.0, stride, ctx.threads);
  const TriSliceTop& use = stride > 1 ? coarse : top;
  // Table 1: successive inflations, the deepest layer last.
  for (int k = rough.layers - 1; k >= 0; --k) {
    const double extra = rough.margin_mm + k * rough.stepdown_mm;
    auto lines = cl_lines(use, model.bounds, tool.radius(), extra, p, stock_top,
                          rough.adaptive_tolerance_mm, ctx);
    if (!lines.ok()) return lines.status();
    const double R = tool.radius() + extra;
    std::optional<trislice_detail::MeshContacts> vertices;
    if (p.vertex_mesh != nullptr) vertices.emplace(*p.vertex_mesh, R);
    auto cl_at = [&](Vec2 xy) {
      double c = use.centre_height(xy, R, primary);
      if (vertices) c = vertices->centre_height(xy, R, c);
      return c > -kInf ? std::max(c - tool.radius(), floor_z) : floor_z;
    };
    tp = lines_to_toolpath(std::move(lines).value(), p, stock_top, std::move(tp), cl_at,
                           ctx.threads);
  }
  if (tp.empty())
    return Status{Error::kEmptyResult, "scan roughing: every layer lies above the stock top " +
                                           std::to_string(stock_top) + " mm"};
  return tp;
}

}  // namespace swarf
