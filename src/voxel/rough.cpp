// Seed 003 end to end: voxels (2.2), offset and projection (2.3), regions and feed lines
// (2.4.1-2.4.2), region sequencing (2.4.3) and the layered toolpath (2.6), with the
// metrics of Tables 1-2 and the orientation study of 3.1.1.
#include "swarf/voxel/rough.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "swarf/core/parallel.h"
#include "voxel/machinable.h"
#include "voxel/regions.h"

namespace swarf {

using voxel_detail::CellPath;
using voxel_detail::Reach;

std::string_view rough_sequence_name(RoughSequence s) {
  switch (s) {
    case RoughSequence::kZigzag:
      return "zigzag";
    case RoughSequence::kTrappedArea:
      return "none";
    case RoughSequence::kGa:
      return "ga";
  }
  return "?";
}

Result<RoughSequence> parse_rough_sequence(std::string_view name) {
  if (name == "zigzag") return RoughSequence::kZigzag;
  if (name == "none" || name == "ta") return RoughSequence::kTrappedArea;
  if (name == "ga") return RoughSequence::kGa;
  return bad_parameter("unknown sequence '" + std::string(name) + "' (zigzag, none or ga)");
}

Status validate(const RoughParams& p) {
  if (!(p.tool_diameter_mm > 0.0)) return bad_parameter("tool diameter must be > 0 mm");
  if (!(p.stepover_mm > 0.0) || p.stepover_mm > p.tool_diameter_mm) {
    return bad_parameter("stepover " + std::to_string(p.stepover_mm) +
                         " mm must be in (0, tool diameter " + std::to_string(p.tool_diameter_mm) +
                         " mm]: wider lines leave ridges");
  }
  if (!(p.stepdown_mm > 0.0)) return bad_parameter("stepdown must be > 0 mm");
  if (!(p.stock_to_leave_mm >= 0.0)) return bad_parameter("stock to leave must be >= 0 mm");
  if (!(p.margin_mm >= 0.0) || !(p.top_margin_mm >= 0.0)) {
    return bad_parameter("stock margins must be >= 0 mm");
  }
  if (!(p.clearance_mm > 0.0)) return bad_parameter("clearance must be > 0 mm");
  if (!(p.feed_mm_min > 0.0) || !(p.plunge_feed_mm_min > 0.0)) {
    return bad_parameter("feed rates must be > 0 mm/min");
  }
  if (!(p.lift_penalty_mm >= 0.0)) return bad_parameter("lift penalty must be >= 0 mm");
  return validate(p.ga);
}

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Rapids stop this far above the layer they plunge into (the previous layer's floor is
// clear there, or the stock top for the first layer).
constexpr double kApproachMm = 1.0;

struct Layer {
  int k = 0;
  std::vector<std::uint8_t> flags;
  std::vector<CellPath> regions;
  std::size_t free_cells = 0;
};

class Builder {
 public:
  Builder(const VoxelModel& m, const Reach& reach, const RoughParams& p, Toolpath& tp,
          RoughMetrics& metrics)
      : m_(m), reach_(reach), p_(p), tp_(tp), metrics_(metrics) {
    clear_z_ = m.stock.max.z + p.clearance_mm;
  }

  Vec2 at(voxel_detail::CellPoint c) const { return m_.centre(c.i, c.j); }

  // Cells whose squares the segment passes over (sampled at a quarter cell).
  template <class F>
  bool all_cells_along(Vec2 p, Vec2 q, F&& ok) const {
    const double c = m_.cell_mm;
    const int steps = std::max(1, static_cast<int>(std::ceil(distance(p, q) / (0.25 * c))));
    for (int s = 0; s <= steps; ++s) {
      const Vec2 a = p + (q - p) * (static_cast<double>(s) / steps);
      const int i = static_cast<int>(std::floor((a.x - m_.origin.x) / c + 0.5));
      const int j = static_cast<int>(std::floor((a.y - m_.origin.y) / c + 0.5));
      if (i < 0 || j < 0 || i >= m_.nx || j >= m_.ny || !ok(m_.column(i, j))) return false;
    }
    return true;
  }

  // A straight link at layer k's height may stay down when it keeps the tool off the part
  // and passes only over cells that `ok` says hold no material any more.
  template <class F>
  bool link_clear(int k, Vec2 p, Vec2 q, F&& ok) const {
    return all_cells_along(p, q, ok) && voxel_detail::straight_move_clear(m_, reach_, k, p, q);
  }

  double lift_cost(int k, Vec2 p, Vec2 q) const {
    return 2.0 * (clear_z_ - m_.layer_z(k)) + distance(p, q) + p_.lift_penalty_mm;
  }

  // Seed 003 2.4.3: the sequence of this layer's regions.
  TwoEndsTour sequence(const Layer& L) {
    const int n = static_cast<int>(L.regions.size());
    TwoEndsTour tour;
    tour.order.resize(static_cast<std::size_t>(n));
    for (int r = 0; r < n; ++r)
      tour.order[static_cast<std::size_t>(r)] = r;
    tour.flipped.assign(static_cast<std::size_t>(n), 0);
    if (p_.sequence != RoughSequence::kGa || n < 2) return tour;
    std::vector<Vec2> ends(static_cast<std::size_t>(2 * n));
    for (int r = 0; r < n; ++r) {
      ends[static_cast<std::size_t>(2 * r)] =
          at(L.regions[static_cast<std::size_t>(r)].pts.front());
      ends[static_cast<std::size_t>(2 * r + 1)] =
          at(L.regions[static_cast<std::size_t>(r)].pts.back());
    }
    // Planning assumes every machinable cell of the layer is cut by the time a link is
    // used; the emitter checks the real state and retracts where that was optimistic.
    auto free_now = [&](std::size_t c) { return (L.flags[c] & voxel_detail::kFree) != 0; };
    std::vector<double> cost(static_cast<std::size_t>(4 * n * n), 0.0);
    for (int a = 0; a < 2 * n; ++a) {
      for (int b = a + 1; b < 2 * n; ++b) {
        if (a / 2 == b / 2) continue;
        const Vec2 pa = ends[static_cast<std::size_t>(a)], pb = ends[static_cast<std::size_t>(b)];
        const double c =
            link_clear(L.k, pa, pb, free_now) ? distance(pa, pb) : lift_cost(L.k, pa, pb);
        cost[static_cast<std::size_t>(a * 2 * n + b)] = c;
        cost[static_cast<std::size_t>(b * 2 * n + a)] = c;
      }
    }
    TwoEndsInstance in;
    in.regions = n;
    in.cost = std::move(cost);
    if (has_pos_) {
      in.start_cost.reserve(ends.size());
      for (const Vec2& e : ends) {
        in.start_cost.push_back(layer_change_clear(e) ? distance(pos_, e)
                                                      : lift_cost(L.k, pos_, e));
      }
    }
    SequenceOptions opt = p_.ga;
    opt.seed = p_.ga.seed + static_cast<std::uint64_t>(L.k) * 0x9e3779b97f4a7c15ULL;
    auto solved = solve_two_ends_ga(in, opt);
    return solved.ok() ? std::move(solved).value() : tour;
  }

  // From the end of the previous layer at its height, straight over to q, then down.
  bool layer_change_clear(Vec2 q) const {
    const std::vector<std::uint8_t>& prev = prev_flags_;
    return link_clear(prev_k_, pos_, q,
                      [&](std::size_t c) { return (prev[c] & voxel_detail::kFree) != 0; });
  }

  void emit_layer(const Layer& L) {
    const TwoEndsTour tour = sequence(L);
    cleared_.assign(L.flags.size(), 0);
    for (int r : tour.order) {
      const CellPath& path = L.regions[static_cast<std::size_t>(r)];
      const bool rev = tour.flipped[static_cast<std::size_t>(r)] != 0;
      const std::size_t n = path.pts.size();
      auto pt = [&](std::size_t t) { return path.pts[rev ? n - 1 - t : t]; };
      auto cut = [&](std::size_t s) { return path.cutting[rev ? n - 2 - s : s] != 0; };
      go_to(L, at(pt(0)));
      mark(pt(0), pt(0));
      for (std::size_t s = 0; s + 1 < n; ++s) {
        feed(to_vec3(at(pt(s + 1)), m_.layer_z(L.k)), p_.feed_mm_min, cut(s));
        mark(pt(s), pt(s + 1));
      }
      pos_ = at(pt(n - 1));
    }
    prev_flags_ = L.flags;
    prev_k_ = L.k;
  }

  void finish() {
    if (has_pos_) rapid(to_vec3(pos_, clear_z_));
  }

 private:
  void go_to(const Layer& L, Vec2 q) {
    const double z = m_.layer_z(L.k);
    const bool same_layer = started_layer_ == L.k;
    started_layer_ = L.k;
    if (same_layer) {
      // Stay down only over cells already cut in this layer (2.4.3 links are air moves).
      if (link_clear(L.k, pos_, q, [&](std::size_t c) { return cleared_[c] != 0; })) {
        feed(to_vec3(q, z), p_.feed_mm_min, false);
        return;
      }
    } else if (has_pos_ && layer_change_clear(q)) {
      feed(to_vec3(q, m_.layer_z(prev_k_)), p_.feed_mm_min, false);
      plunge(z);
      return;
    }
    if (has_pos_) {
      rapid(to_vec3(pos_, clear_z_));
      ++metrics_.lift_offs;
    }
    rapid(to_vec3(q, clear_z_));
    rapid(to_vec3(q, m_.layer_top(L.k) + kApproachMm));
    plunge(z);
  }

  void mark(voxel_detail::CellPoint a, voxel_detail::CellPoint b) {
    const int di = (b.i > a.i) - (b.i < a.i), dj = (b.j > a.j) - (b.j < a.j);
    for (voxel_detail::CellPoint c = a;; c.i += di, c.j += dj) {
      cleared_[m_.column(c.i, c.j)] = 1;
      if (c == b) break;
    }
  }

  static Move make(MoveKind kind, Vec3 end, double feed, bool cutting) {
    Move mv;
    mv.kind = kind;
    mv.end = end;
    mv.feed_mm_min = feed;
    mv.cutting = cutting;
    return mv;
  }
  void rapid(Vec3 p) { add(make(MoveKind::kRapid, p, 0.0, false)); }
  void feed(Vec3 p, double f, bool cutting) { add(make(MoveKind::kFeed, p, f, cutting)); }
  void plunge(double z) {
    add(make(MoveKind::kPlunge, to_vec3(pos_, z), p_.plunge_feed_mm_min, true));
  }
  void add(Move mv) {
    if (has_last_ && mv.end == last_) return;
    tp_.moves.push_back(mv);
    last_ = mv.end;
    has_last_ = true;
    pos_ = mv.end.xy();
    has_pos_ = true;
  }

  const VoxelModel& m_;
  const Reach& reach_;
  const RoughParams& p_;
  Toolpath& tp_;
  RoughMetrics& metrics_;
  double clear_z_ = 0.0;
  Vec2 pos_;
  bool has_pos_ = false;
  Vec3 last_;
  bool has_last_ = false;
  int prev_k_ = -1, started_layer_ = -1;
  std::vector<std::uint8_t> prev_flags_, cleared_;
};

void measure(const Toolpath& tp, RoughMetrics& m) {
  Vec3 at;
  for (std::size_t i = 0; i < tp.moves.size(); ++i) {
    const Move& mv = tp.moves[i];
    if (i > 0) {  // the first move starts at the machine's unknown position
      const double len = distance(at, mv.end);
      m.total_length_mm += len;
      if (mv.kind == MoveKind::kRapid || !mv.cutting) {
        m.air_length_mm += len;
      } else {
        m.cutting_length_mm += len;
      }
    }
    at = mv.end;
  }
}

}  // namespace

Result<RoughResult> rough(const Mesh& part, const RoughParams& p, const Context& ctx) {
  SWARF_RETURN_IF_ERROR(validate(p));
  const auto t0 = Clock::now();
  RoughResult res;
  VoxelizeOptions vo;
  vo.cell_mm = p.stepover_mm;
  vo.layer_mm = p.stepdown_mm;
  vo.stock = p.stock;
  vo.margin_mm = p.margin_mm;
  vo.top_margin_mm = p.top_margin_mm;
  vo.repair_open = p.repair_open_mesh;
  auto vox = voxelize(part, vo, ctx);
  if (!vox.ok()) return vox.status();
  const VoxelModel& m = *vox;
  res.warnings = m.warnings;
  res.timings.voxelize_s = seconds_since(t0);
  ctx.report("rough: voxelized", 0.2);

  auto t1 = Clock::now();
  const Reach reach = voxel_detail::compute_reach(m, 0.5 * p.tool_diameter_mm, p.stock_to_leave_mm,
                                                  p.offset, ctx.threads);
  std::vector<Layer> layers(static_cast<std::size_t>(m.layers));
  parallel_for(layers.size(), ctx.threads, [&](std::size_t k) {
    layers[k].k = static_cast<int>(k);
    layers[k].flags = voxel_detail::layer_flags(m, reach, static_cast<int>(k));
  });
  res.timings.preprocess_s = seconds_since(t1);
  if (ctx.cancelled()) return Status{Error::kCancelled, "rough: cancelled"};

  t1 = Clock::now();
  parallel_for(layers.size(), ctx.threads, [&](std::size_t k) {
    Layer& L = layers[k];
    for (std::uint8_t f : L.flags)
      L.free_cells += (f & voxel_detail::kFree) ? 1 : 0;
    L.regions = p.sequence == RoughSequence::kZigzag
                    ? voxel_detail::zigzag_runs(L.flags, m.nx, m.ny)
                    : voxel_detail::trapped_area_regions(L.flags, m.nx, m.ny);
  });
  res.timings.segment_s = seconds_since(t1);
  ctx.report("rough: segmented", 0.5);

  t1 = Clock::now();
  Toolpath& tp = res.toolpath;
  tp.name = "rough";
  tp.tool_diameter_mm = p.tool_diameter_mm;
  char desc[64];
  std::snprintf(desc, sizeof desc, "D%g flat end mill", p.tool_diameter_mm);
  tp.tool_description = desc;
  tp.clearance_z_mm = m.stock.max.z + p.clearance_mm;
  Builder b(m, reach, p, tp, res.metrics);
  for (const Layer& L : layers) {
    if (ctx.cancelled()) return Status{Error::kCancelled, "rough: cancelled"};
    if (L.regions.empty()) continue;
    ++res.metrics.layers;
    res.metrics.regions += L.regions.size();
    res.metrics.machinable_cells += L.free_cells;
    b.emit_layer(L);
  }
  b.finish();
  res.timings.sequence_s = seconds_since(t1);
  if (tp.moves.empty()) {
    return Status{Error::kEmptyResult,
                  "rough: no layer has room for the tool (stock too small for the tool "
                  "plus the allowance?)"};
  }
  measure(tp, res.metrics);
  res.timings.total_s = seconds_since(t0);
  return res;
}

Result<OrientationResult> rough_orientations(const Mesh& part, const RoughParams& p,
                                             const std::vector<double>& angles_deg,
                                             const Context& ctx) {
  if (angles_deg.empty()) return bad_parameter("orientation study: no angle given");
  OrientationResult out;
  for (double a : angles_deg) {
    if (!std::isfinite(a)) return bad_parameter("orientation study: angle is not finite");
    auto r = rough(a == 0.0 ? part : rotate_about_z(part, a), p, ctx);
    if (!r.ok()) return r.status().with_context("rotation " + std::to_string(a) + " deg");
    out.angles_deg.push_back(a);
    out.metrics.push_back(r->metrics);
    const bool better = out.metrics.size() == 1 ||
                        r->metrics.total_length_mm < out.metrics[out.best].total_length_mm;
    if (better) {
      out.best = out.metrics.size() - 1;
      out.best_result = std::move(r).value();
      out.best_result.rotation_deg = a;
    }
  }
  return out;
}

}  // namespace swarf
