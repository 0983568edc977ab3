// seed 001 section 3.3, Fig. 8: the simulation loop. Per move: positions every Δd, the
// engagement of every cutting-edge element against the stock (Fig. 10b), the forces at every
// rotation step (Eq. 2-5), and the subtraction of the swept tool from the stock.
#include "swarf/sim/simulate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace swarf::sim {

namespace {

struct Polyline3 {
  std::vector<Vec3> pts;
  std::vector<double> cum;  // arc length at each point

  explicit Polyline3(std::vector<Vec3> p) : pts(std::move(p)) {
    cum.assign(pts.size(), 0.0);
    for (std::size_t i = 1; i < pts.size(); ++i)
      cum[i] = cum[i - 1] + distance(pts[i - 1], pts[i]);
  }
  double length() const { return cum.back(); }
  std::size_t segment_at(double s) const {
    const auto it = std::upper_bound(cum.begin(), cum.end(), s);
    const std::size_t i = static_cast<std::size_t>(it - cum.begin());
    return std::clamp<std::size_t>(i == 0 ? 0 : i - 1, 0, pts.size() - 2);
  }
  Vec3 at(double s) const {
    const std::size_t i = segment_at(s);
    const double len = cum[i + 1] - cum[i];
    const double t = len > 0.0 ? std::clamp((s - cum[i]) / len, 0.0, 1.0) : 0.0;
    return pts[i] + (pts[i + 1] - pts[i]) * t;
  }
  Vec3 direction_at(double s) const {
    const std::size_t i = segment_at(s);
    return normalized(pts[i + 1] - pts[i]);
  }
  /// The sub-polyline between arc lengths a < b, with its end points.
  std::vector<Vec3> between(double a, double b) const {
    std::vector<Vec3> out{at(a)};
    for (std::size_t i = 0; i < pts.size(); ++i) {
      if (cum[i] > a && cum[i] < b) out.push_back(pts[i]);
    }
    out.push_back(at(b));
    return out;
  }
};

Status validate(const SimulationOptions& o) {
  if (!(o.step_mm > 0.0)) return bad_parameter("simulate: step must be positive");
  if (!(o.batch_mm >= o.step_mm)) return bad_parameter("simulate: batch must be at least the step");
  if (o.sample_stride < 1) return bad_parameter("simulate: sample stride must be at least 1");
  if (!(o.rapid_mm_min > 0.0)) return bad_parameter("simulate: rapid rate must be positive");
  return {};
}

}  // namespace

Result<SimulationResult> simulate(Stock& stock, const Toolpath& path, const Tool& tool,
                                  const CuttingCoefficients& k, const SimulationOptions& opt,
                                  const Context& ctx) {
  SWARF_RETURN_IF_ERROR(validate(opt));
  SWARF_RETURN_IF_ERROR(validate(tool));
  const double rpm = opt.spindle_rpm > 0.0 ? opt.spindle_rpm : path.spindle_rpm;
  if (!(rpm > 0.0)) return bad_parameter("simulate: no spindle speed (give --rpm or an S word)");
  Result<ForceModel> model_r = ForceModel::create(cutter_from_tool(tool), k, opt.force);
  if (!model_r.ok()) return model_r.status();
  const ForceModel& model = *model_r;
  const ToolSolid solid = tool_solid(tool);
  const int flutes = tool.flutes;
  const double steps_per_rev = model.steps_per_rev();
  const double dt = 60.0 / (rpm * steps_per_rev);  // seconds per rotation step
  const double stock_top = stock.bounds().max.z;

  SimulationResult res;
  res.annotated = path;
  res.moves.resize(path.moves.size());
  if (path.moves.empty()) return res;

  Vec3 pos = path.moves[0].end;
  pos.z = std::max(pos.z, stock_top + 1.0);
  double t = 0.0;
  double force_sum = 0.0;
  std::size_t force_count = 0;

  // Removal is deferred into a pending polyline and done in one subtraction per slice when
  // it reaches batch_mm, turns by more than batch_turn_deg (engagement is tested against the
  // stock before the pending part: exact for the cutting elements on a straight run),
  // switches between rapid and feed, or a move longer than a step ends. Runs of tiny moves (a
  // finishing contour in 0.01 mm blocks) share batches; their volume is split by length.
  struct Pending {
    std::vector<Vec3> pts;
    double len = 0.0;
    Vec3 dir;
    bool rapid = false;
    std::vector<std::pair<std::size_t, double>> owners;  // move index, length in the batch
  } pend;
  const double cos_turn = std::cos(deg_to_rad(opt.batch_turn_deg));
  auto flush = [&]() {
    if (pend.pts.size() >= 2) {
      const Removal rm = stock.remove(solid, pend.pts, ctx);
      for (int a = 0; a < 3; ++a)
        res.removed_by_family_mm3[a] += rm.by_family_mm3[a];
      for (const auto& [m, l] : pend.owners) {
        res.moves[m].removed_mm3 += rm.volume_mm3 * (pend.len > 0.0 ? l / pend.len : 0.0);
      }
    }
    pend = Pending{};
  };
  auto append = [&](const std::vector<Vec3>& piece, std::size_t mi, bool rapid) {
    for (std::size_t i = 0; i + 1 < piece.size(); ++i) {
      const Vec3 a = piece[i], b = piece[i + 1];
      const double l = distance(a, b);
      if (!(l > 0.0)) continue;
      const Vec3 d = (b - a) / l;
      if (!pend.pts.empty() &&
          (pend.rapid != rapid || pend.len >= opt.batch_mm || dot(d, pend.dir) < cos_turn)) {
        flush();
      }
      if (pend.pts.empty()) {
        pend.pts.push_back(a);
        pend.dir = d;
        pend.rapid = rapid;
      }
      // Collinear pieces extend the last segment: one straight segment per slice is one
      // convex section instead of many to unite.
      const std::size_t np = pend.pts.size();
      if (np >= 2 && dot(normalized(pend.pts[np - 1] - pend.pts[np - 2]), d) > 1.0 - 1e-12) {
        pend.pts.back() = b;
      } else {
        pend.pts.push_back(b);
      }
      pend.len += l;
      if (pend.owners.empty() || pend.owners.back().first != mi) pend.owners.push_back({mi, 0.0});
      pend.owners.back().second += l;
    }
  };

  for (std::size_t mi = 0; mi < path.moves.size(); ++mi) {
    if (ctx.cancelled()) return Status{Error::kCancelled, "simulate: cancelled"};
    ctx.report("simulate", static_cast<double>(mi) / static_cast<double>(path.moves.size()));
    const Move& mv = path.moves[mi];
    MoveResult& mr = res.moves[mi];
    mr.t_start_s = t;
    std::vector<Vec3> pts{pos};
    for (const Vec3& p : sample_move(pos, mv, opt.step_mm))
      pts.push_back(p);
    const Polyline3 line(std::move(pts));
    const double len = line.length();
    const bool rapid = mv.kind == MoveKind::kRapid;
    if (!rapid && !(mv.feed_mm_min > 0.0) && len > 0.0) {
      return bad_input("simulate: move " + std::to_string(mi + 1) + " has no feed rate");
    }
    const double speed = rapid ? opt.rapid_mm_min : mv.feed_mm_min;  // mm/min
    const double ft = rapid ? 0.0 : mv.feed_mm_min / (rpm * flutes);
    double peak = 0.0, sum = 0.0;
    std::size_t count = 0;
    if (len > 0.0 && rapid) {
      append(line.pts, mi, true);
    } else if (len > 0.0) {
      const auto n_ref = static_cast<std::size_t>(std::ceil(len / opt.step_mm - 1e-9));
      for (std::size_t r = 0; r < n_ref; ++r) {
        const double ra = len * static_cast<double>(r) / static_cast<double>(n_ref);
        const double rb = len * static_cast<double>(r + 1) / static_cast<double>(n_ref);
        if (opt.compute_forces) {
          // seed 001 Fig. 10b: engagement at the middle of the step, against the stock before
          // the pending removal.
          const Vec3 mid = line.at(0.5 * (ra + rb));
          const Vec3 dir = line.direction_at(0.5 * (ra + rb));
          std::size_t used = 0;
          while (used < model.levels().size() &&
                 mid.z + model.levels()[used].z_mm <= stock_top + stock.pitch_mm()) {
            ++used;
          }
          const ElementTable table = element_table(
              model, ft, dir,
              [&](std::size_t, Vec3 p) { return stock.inside(mid + p, opt.engagement); }, used,
              ctx.threads);
          for (std::size_t lv = 0; lv < table.levels_used; ++lv) {
            mr.engaged_arc_deg = std::max(mr.engaged_arc_deg, engaged_arc_deg(model, table, lv));
          }
          // seed 001 Eq. (5) at every rotation step whose time falls in this step.
          const double ta = t + ra / speed * 60.0, tb = t + rb / speed * 60.0;
          const auto i0 = static_cast<long>(std::ceil(ta / dt - 1e-9));
          const auto i1 = static_cast<long>(std::ceil(tb / dt - 1e-9));
          for (long i = i0; i < i1; ++i) {
            Vec3 c, e;
            total_force_parts(model, table, i, c, e);
            const Vec3 f = c + e;
            const double mag = norm(f);
            if (mag > peak) {
              peak = mag;
              mr.peak_cutting_n = c;
              mr.peak_edge_n = e;
            }
            sum += mag;
            ++count;
            if (mag > 0.0) {
              res.cutting_time_s += dt;
              force_sum += mag;
              ++force_count;
            }
            if (opt.force_limit_n > 0.0 && mag > opt.force_limit_n) res.time_above_limit_s += dt;
            res.peak_abs_n = {std::max(res.peak_abs_n.x, std::abs(f.x)),
                              std::max(res.peak_abs_n.y, std::abs(f.y)),
                              std::max(res.peak_abs_n.z, std::abs(f.z))};
            if (i % opt.sample_stride == 0) {
              res.samples.push_back(
                  {static_cast<double>(i) * dt, f, static_cast<std::uint32_t>(mi)});
            }
          }
        }
        append(line.between(ra, rb), mi, false);
      }
    }
    if (rapid || len >= opt.step_mm) flush();
    if (rapid && mr.removed_mm3 > opt.collision_volume_mm3) {
      mr.collision = true;
      char buf[160];
      std::snprintf(buf, sizeof buf,
                    "move %zu: rapid removed %.3f mm^3 ending at (%.3f, %.3f, %.3f)", mi + 1,
                    mr.removed_mm3, mv.end.x, mv.end.y, mv.end.z);
      res.collisions.emplace_back(buf);
    }
    mr.peak_force_n = peak;
    mr.mean_force_n = count > 0 ? sum / static_cast<double>(count) : 0.0;
    res.peak_force_n = std::max(res.peak_force_n, peak);
    t += len / speed * 60.0;
    mr.t_end_s = t;
    Move& am = res.annotated.moves[mi];
    if (!rapid && opt.compute_forces) {
      am.force_n = static_cast<float>(peak);
      am.engagement_deg = static_cast<float>(mr.engaged_arc_deg);
    }
    pos = mv.end;
  }
  flush();
  for (const MoveResult& m : res.moves)
    res.removed_mm3 += m.removed_mm3;
  res.machining_time_s = t;
  res.mean_force_n = force_count > 0 ? force_sum / static_cast<double>(force_count) : 0.0;
  return res;
}

FeedSchedule schedule_feed(const Toolpath& path, const SimulationResult& sim,
                           const FeedScheduleOptions& o) {
  FeedSchedule out;
  out.path = path;
  Vec3 pos = path.moves.empty() ? Vec3{} : path.moves[0].end;
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    const Move& mv = path.moves[i];
    Move& nm = out.path.moves[i];
    const double len = move_length(pos, mv);
    pos = mv.end;
    if (mv.kind == MoveKind::kRapid || !(mv.feed_mm_min > 0.0) || i >= sim.moves.size()) continue;
    const MoveResult& mr = sim.moves[i];
    double s = o.max_increase;
    if (mr.peak_force_n > 0.0) {
      // |s C + E| = F_max: a quadratic in s (forces are linear in the chip thickness, which
      // is linear in the feed, plus the feed-independent edge part).
      const Vec3 c = mr.peak_cutting_n, e = mr.peak_edge_n;
      const double a = norm_sq(c), b = 2.0 * dot(c, e),
                   cc = norm_sq(e) - o.max_force_n * o.max_force_n;
      if (cc >= 0.0 || a <= 0.0) {
        s = 0.0;  // the edge forces alone reach the limit: slowest feed
      } else {
        s = (-b + std::sqrt(b * b - 4.0 * a * cc)) / (2.0 * a);
      }
      s = std::min(s, o.max_increase);
    }
    double feed = mv.feed_mm_min * s;
    if (o.max_feed_mm_min > 0.0 && feed > mv.feed_mm_min) {
      feed = std::max(mv.feed_mm_min, std::min(feed, o.max_feed_mm_min));  // caps raises only
    }
    if (o.max_chip_mm > 0.0 && o.spindle_rpm > 0.0) {
      feed = std::min(feed, o.max_chip_mm * o.spindle_rpm * o.flutes);
    }
    feed = std::max(feed, o.min_feed_mm_min);
    nm.feed_mm_min = feed;
    if (feed < mv.feed_mm_min * (1.0 - 1e-9)) ++out.slowed;
    if (feed > mv.feed_mm_min * (1.0 + 1e-9)) ++out.raised;
    out.time_before_s += len / mv.feed_mm_min * 60.0;
    out.time_after_s += len / feed * 60.0;
  }
  return out;
}

}  // namespace swarf::sim
