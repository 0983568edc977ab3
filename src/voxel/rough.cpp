// Seed 003 end to end: voxels (2.2), offset and projection (2.3), regions and feed lines
// (2.4.1-2.4.2), region sequencing (2.4.3) and the layered toolpath (2.6), with the
// metrics of Tables 1-2 and the orientation study of 3.1.1.
#include "swarf/voxel/rough.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <memory>
#include <string>
#include <utility>

#include "swarf/core/parallel.h"
#include "voxel/links.h"
#include "voxel/machinable.h"
#include "voxel/regions.h"

namespace swarf {

using voxel_detail::CellPath;
using voxel_detail::compared_heights;
using voxel_detail::Reach;

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Rapids stop this far above the layer they plunge into (the previous layer's floor is
// clear there, or the stock top for the first layer).
constexpr double kApproachMm = 1.0;
// Largest side of the squares the exact part tops are kept on (up to 4 per cell side).
constexpr double kTopSquareMm = 2.0;
// Cell visits the true-cost refinement may spend per layer (some 5 ms) and in all.
constexpr double kDryRunCellBudget = 2e6;
constexpr double kDryRunTotalBudget = 1.5e7;

struct Layer {
  int k = 0;
  std::vector<std::uint8_t> flags;
  std::vector<CellPath> regions;
  std::size_t free_cells = 0;
};

class Builder : public voxel_detail::LinkSearch {
 public:
  Builder(const VoxelModel& m, const Reach& reach, const RoughParams& p, Toolpath& tp,
          RoughMetrics& metrics, voxel_detail::LinkScratch& scratch)
      : LinkSearch(m, reach, scratch), p_(p), tp_(&tp), metrics_(&metrics) {
    clear_z_ = m.stock.max.z + p.clearance_mm;
  }

  Vec2 at(voxel_detail::CellPoint c) const { return m_.centre(c.i, c.j); }

  bool routing() const { return p_.sequence != RoughSequence::kZigzag; }

  static double polyline_length(Vec2 p, const std::vector<Vec2>& pts) {
    double len = 0.0;
    for (const Vec2& q : pts) {
      len += distance(p, q);
      p = q;
    }
    return len;
  }

  double lift_cost(int k, Vec2 p, Vec2 q) const {
    return 2.0 * (clear_z_ - m_.layer_z(k)) + distance(p, q) + p_.lift_penalty_mm;
  }

  // Seed 003 2.4.3: the sequence of this layer's regions.
  // Seed 003 2.4.3 with one of two models of the links, neither exact (which cells are cut
  // when a link is used depends on the order): optimistic = every machinable cell of the
  // layer is cut already; pessimistic = only the region just finished (and the region
  // ends). The emitter then checks the real state.
  TwoEndsInstance link_costs(const Layer& L, bool pessimistic) const {
    const int n = static_cast<int>(L.regions.size());
    std::vector<Vec2> ends(static_cast<std::size_t>(2 * n));
    for (int r = 0; r < n; ++r) {
      ends[static_cast<std::size_t>(2 * r)] =
          at(L.regions[static_cast<std::size_t>(r)].pts.front());
      ends[static_cast<std::size_t>(2 * r + 1)] =
          at(L.regions[static_cast<std::size_t>(r)].pts.back());
    }
    std::vector<int> owner;
    if (pessimistic) {
      owner.assign(L.flags.size(), -1);
      for (int r = 0; r < n; ++r) {
        const CellPath& path = L.regions[static_cast<std::size_t>(r)];
        for (std::size_t t = 0; t + 1 < path.pts.size(); ++t) {
          for_cells(path.pts[t], path.pts[t + 1], [&](std::size_t c) { owner[c] = r; });
        }
        if (path.pts.size() == 1) owner[m_.column(path.pts[0].i, path.pts[0].j)] = r;
      }
      for (const Vec2& e : ends)
        owner[cell_at(e)] = n;  // ends are passable for all
    }
    auto free_now = [&](std::size_t c) { return (L.flags[c] & voxel_detail::kFree) != 0; };
    // Where the straight link is blocked, the tool may still stay down along a path through
    // cut cells (its 4-connected length bounds the pulled route).
    std::vector<std::size_t> end_cells;
    for (const Vec2& e : ends)
      end_cells.push_back(cell_at(e));
    // steps[a * 2n + b]: 4-connected steps from end a to end b, -1 when not connected.
    std::vector<int> steps(ends.size() * ends.size(), -1);
    for (std::size_t a = 0; a < ends.size(); ++a) {
      const int ra = static_cast<int>(a / 2);
      if (pessimistic) {
        bfs(
            L.flags, end_cells[a], [&](std::size_t c) { return owner[c] == ra || owner[c] == n; },
            end_cells);
      } else {
        bfs(L.flags, end_cells[a], free_now, end_cells);
      }
      for (std::size_t b = 0; b < ends.size(); ++b)
        steps[a * ends.size() + b] = steps_to(end_cells[b]);
    }
    std::vector<double> cost(static_cast<std::size_t>(4 * n * n), 0.0);
    for (int a = 0; a < 2 * n; ++a) {
      for (int b = a + 1; b < 2 * n; ++b) {
        if (a / 2 == b / 2) continue;
        const Vec2 pa = ends[static_cast<std::size_t>(a)], pb = ends[static_cast<std::size_t>(b)];
        double c = distance(pa, pb);
        const int ra = a / 2;
        const bool straight =
            pessimistic ? link_clear(L.k, pa, pb,
                                     [&](std::size_t q) { return owner[q] == ra || owner[q] == n; })
                        : link_clear(L.k, pa, pb, free_now);
        if (!straight) {
          c = lift_cost(L.k, pa, pb);
          const int st =
              steps[static_cast<std::size_t>(a) * ends.size() + static_cast<std::size_t>(b)];
          if (st >= 0) c = std::min(c, st * m_.cell_mm);
        }
        cost[static_cast<std::size_t>(a * 2 * n + b)] = c;
        cost[static_cast<std::size_t>(b * 2 * n + a)] = c;
      }
    }
    TwoEndsInstance in;
    in.regions = n;
    in.cost = std::move(cost);
    return in;
  }

  // Seed 003 2.5: the GA plus local search on an instance, with start costs from where
  // the tool is now.
  TwoEndsTour solve(const Layer& L, TwoEndsInstance& in) const {
    in.start_cost.clear();
    if (has_pos_) {
      for (int q = 0; q < 2 * in.regions; ++q) {
        const CellPath& path = L.regions[static_cast<std::size_t>(q / 2)];
        const Vec2 e = at(q % 2 == 0 ? path.pts.front() : path.pts.back());
        in.start_cost.push_back(layer_change_clear(e) ? distance(pos_, e)
                                                      : lift_cost(L.k, pos_, e));
      }
    }
    SequenceOptions opt = p_.ga;
    opt.seed = p_.ga.seed + static_cast<std::uint64_t>(L.k) * 0x9e3779b97f4a7c15ULL;
    auto solved = solve_two_ends_ga(in, opt);
    if (solved.ok()) return std::move(solved).value();
    TwoEndsTour tour;
    for (int r = 0; r < in.regions; ++r)
      tour.order.push_back(r);
    tour.flipped.assign(static_cast<std::size_t>(in.regions), 0);
    return tour;
  }

  // From the end of the previous layer at its height, straight over to q, then down.
  bool layer_change_clear(Vec2 q) const {
    const std::vector<std::uint8_t>& prev = prev_flags();
    return link_clear(prev_k_, pos_, q,
                      [&](std::size_t c) { return (prev[c] & voxel_detail::kFree) != 0; });
  }

  void emit_layer(const Layer& L) {
    // Routes stay valid for the next layer when it has the same cells (so the same regions)
    // and no height its link tests compare with lies between the two layers' thresholds
    // (so every such test answers the same): the many equal layers of a prismatic part
    // route their links once. Layer changes depend on the previous layer: never kept.
    if (routing()) {
      if (heights_.empty()) heights_ = compared_heights(reach_);
      const double thr = voxel_detail::layer_threshold(m_, reach_, L.k);
      const auto cls = static_cast<std::size_t>(
          std::lower_bound(heights_.begin(), heights_.end(), thr) - heights_.begin());
      if (cls != route_class_ || L.flags != route_flags_) {
        scratch_->routes.clear();
        route_class_ = cls;
        route_flags_ = L.flags;
      } else {
        for (auto it = scratch_->routes.begin(); it != scratch_->routes.end();)
          it = (*it).first[2] != 0 ? scratch_->routes.erase(it) : std::next(it);
      }
    }
    own_start_.resize(L.flags.size());
    for (std::size_t c = 0; c < L.flags.size(); ++c)
      own_start_[c] = (L.flags[c] & voxel_detail::kStock) ? 0 : 1;
    layer_start_ = &own_start_;
    TwoEndsTour tour;
    for (int r = 0; r < static_cast<int>(L.regions.size()); ++r)
      tour.order.push_back(r);
    tour.flipped.assign(L.regions.size(), 0);
    if (p_.sequence == RoughSequence::kGa && L.regions.size() >= 2) {
      // The GA's link costs cannot know which cells are cut when a link is used (that
      // depends on the order). So several orders - the GA's under an optimistic and under a
      // pessimistic link model, the Trapped Area discovery order, and for a layer with the
      // same cells as the last one planned its order both ways round - are refined on the
      // true cost (dry runs of the emitter: air path plus lift penalties) and the best is
      // emitted: sequencing never makes a layer worse than the discovery order. Link costs
      // cost O(cells x regions) to find, so a layer with the same cells reuses them.
      const bool same = L.flags == plan_flags_;
      if (!same) {
        plan_flags_ = L.flags;
        plan_optimistic_ = link_costs(L, false);
        plan_pessimistic_ = link_costs(L, true);
      }
      std::vector<TwoEndsTour> candidates{solve(L, plan_optimistic_), solve(L, plan_pessimistic_),
                                          tour};
      if (same) {
        TwoEndsTour back = plan_tour_;
        std::reverse(back.order.begin(), back.order.end());
        for (auto& f : back.flipped)
          f ^= 1;
        candidates.push_back(plan_tour_);
        candidates.push_back(std::move(back));
      }
      double best = std::numeric_limits<double>::infinity();
      snap_.cost = std::numeric_limits<double>::infinity();
      dry_run_budget_ = std::min(kDryRunCellBudget, total_budget_);
      const double per_run =
          static_cast<double>(L.flags.size()) * static_cast<double>(L.regions.size());
      for (std::size_t ci = 0; ci < candidates.size(); ++ci) {
        TwoEndsTour& cand = candidates[ci];
        // A tour equal to an earlier candidate costs the same and would not replace it.
        bool seen = false;
        for (std::size_t cj = 0; cj < ci && !seen; ++cj)
          seen = candidates[cj].order == cand.order && candidates[cj].flipped == cand.flipped;
        if (seen) continue;
        // When refine() cannot afford a move, only whether this tour beats `best` matters:
        // its dry run may stop as soon as it cannot (the cost only grows while emitting).
        const double bound =
            dry_run_budget_ >= per_run ? std::numeric_limits<double>::infinity() : best;
        const double c = refine(L, cand, dry_run(L, cand, bound));
        if (c < best) {
          best = c;
          tour = cand;
        }
      }
      total_budget_ -= std::min(kDryRunCellBudget, total_budget_) - dry_run_budget_;
      plan_tour_ = tour;
      if (snap_.cost < std::numeric_limits<double>::infinity() && snap_.tour.order == tour.order &&
          snap_.tour.flipped == tour.flipped) {
        tp_->moves.insert(tp_->moves.end(), snap_.moves.begin(), snap_.moves.end());
        metrics_->lift_offs += snap_.lift_offs;
        air_ += snap_.air;
        pos_ = snap_.pos;
        has_pos_ = snap_.has_pos;
        last_ = snap_.last;
        has_last_ = snap_.has_last;
        started_layer_ = snap_.started_layer;
        tour.order.clear();  // emitted
      }
    }
    if (!tour.order.empty()) emit_tour(L, tour);
    prev_flags_ = L.flags;
    prev_k_ = L.k;
  }

  // Or-opt on the true cost: move one region elsewhere in the order, either way round,
  // while a dry run says it helps. A dry run costs about (cells x regions) of the layer;
  // each layer may spend kDryRunCellBudget on them, the whole run kDryRunTotalBudget.
  double refine(const Layer& L, TwoEndsTour& tour, double best) {
    const std::size_t n = tour.order.size();
    const double per_run = static_cast<double>(L.flags.size()) * static_cast<double>(n);
    bool improved = true;
    auto affordable = [&] { return dry_run_budget_ >= per_run; };
    while (improved && affordable()) {
      improved = false;
      for (std::size_t i = 0; i < n && !improved && affordable(); ++i) {
        for (std::size_t k = 0; k < n && !improved && affordable(); ++k) {
          for (int flip = 0; flip < 2 && !improved && affordable(); ++flip) {
            if (k == i && flip == 0) continue;
            TwoEndsTour cand = tour;
            const int r = cand.order[i];
            cand.order.erase(cand.order.begin() + static_cast<std::ptrdiff_t>(i));
            cand.order.insert(cand.order.begin() + static_cast<std::ptrdiff_t>(k), r);
            if (flip) cand.flipped[static_cast<std::size_t>(r)] ^= 1;
            dry_run_budget_ -= per_run;
            const double c = dry_run(L, cand, best - 1e-9);
            if (c < best - 1e-9) {
              best = c;
              tour = std::move(cand);
              improved = true;
            }
          }
        }
      }
    }
    return best;
  }

  // Air path plus lift penalties of emitting this layer with `tour`, without emitting it.
  // Stops early, returning infinity, once the cost reaches `bound` (the caller only asks
  // whether the tour costs less than that).
  double dry_run(const Layer& L, const TwoEndsTour& tour,
                 double bound = std::numeric_limits<double>::infinity()) {
    // A copy of the emitter state a tour reads and writes; the planning state (plan_*) and
    // the layer-sized buffers are not copied: cleared_ is rebuilt from the layer's start
    // state, prev_flags_ is only read, so the copy borrows this builder's buffers.
    dry_tp_.moves.clear();
    dry_metrics_ = RoughMetrics{};
    if (!dry_sim_)
      dry_sim_ = std::make_unique<Builder>(m_, reach_, p_, dry_tp_, dry_metrics_, *scratch_);
    Builder& sim = *dry_sim_;
    sim.clear_z_ = clear_z_;
    sim.pos_ = pos_;
    sim.has_pos_ = has_pos_;
    sim.last_ = last_;
    sim.has_last_ = has_last_;
    sim.prev_k_ = prev_k_;
    sim.started_layer_ = started_layer_;
    sim.air_ = 0.0;
    sim.borrowed_prev_ = &prev_flags_;
    sim.layer_start_ = layer_start_;
    sim.abort_at_ = bound;
    sim.emit_tour(L, tour);
    if (sim.aborted_) return std::numeric_limits<double>::infinity();
    const double cost = sim.air_ + static_cast<double>(dry_metrics_.lift_offs) * p_.lift_penalty_mm;
    // Keep the cheapest complete dry run of the layer: when its tour is the one chosen,
    // emitting it again would give the same moves (same start state, same tour).
    if (cost < snap_.cost) {
      snap_.cost = cost;
      snap_.tour = tour;
      std::swap(snap_.moves, dry_tp_.moves);
      snap_.lift_offs = dry_metrics_.lift_offs;
      snap_.air = sim.air_;
      snap_.pos = sim.pos_;
      snap_.has_pos = sim.has_pos_;
      snap_.last = sim.last_;
      snap_.has_last = sim.has_last_;
      snap_.started_layer = sim.started_layer_;
    }
    return cost;
  }

  void emit_tour(const Layer& L, const TwoEndsTour& tour) {
    // Cells without stock hold nothing to cut: links may cross them from the start. The
    // start state is built once per layer and copied for every (dry) run.
    aborted_ = false;
    cleared_ = *layer_start_;
    done_.assign((L.regions.size() + 63) / 64, 0);
    for (int r : tour.order) {
      if (air_ + static_cast<double>(metrics_->lift_offs) * p_.lift_penalty_mm >= abort_at_) {
        aborted_ = true;
        return;
      }
      const CellPath& path = L.regions[static_cast<std::size_t>(r)];
      const bool rev = tour.flipped[static_cast<std::size_t>(r)] != 0;
      const std::size_t n = path.pts.size();
      auto pt = [&](std::size_t t) { return path.pts[rev ? n - 1 - t : t]; };
      auto cut = [&](std::size_t s) { return path.cutting[rev ? n - 2 - s : s] != 0; };
      go_to(L, at(pt(0)));
      if (aborted_) return;
      mark(pt(0), pt(0));
      for (std::size_t s = 0; s + 1 < n; ++s) {
        feed(to_vec3(at(pt(s + 1)), m_.layer_z(L.k)), p_.feed_mm_min, cut(s));
        mark(pt(s), pt(s + 1));
      }
      pos_ = at(pt(n - 1));
      done_[static_cast<std::size_t>(r) / 64] |= std::uint64_t{1}
                                                 << (static_cast<unsigned>(r) % 64);
    }
  }

  void finish() {
    if (has_pos_) rapid(to_vec3(pos_, clear_z_));
  }

 private:
  void go_to(const Layer& L, Vec2 q) {
    // Every way to q adds at least the straight distance to the air path: a dry run that
    // cannot stay under its bound stops before routing (margin for rounding).
    if (has_pos_ && abort_at_ < std::numeric_limits<double>::infinity() &&
        air_ + static_cast<double>(metrics_->lift_offs) * p_.lift_penalty_mm +
                distance(pos_, q) * (1.0 - 1e-9) >=
            abort_at_) {
      aborted_ = true;
      return;
    }
    const double z = m_.layer_z(L.k);
    const bool same_layer = started_layer_ == L.k;
    started_layer_ = L.k;
    if (same_layer) {
      // Stay down only over cells already cut in this layer (2.4.3 links are air moves).
      // The cell where the next cut starts may hold material: the link ends there.
      const std::size_t target = cell_at(q);
      auto cut = [&](std::size_t c) { return cleared_[c] != 0 || c == target; };
      if (link_clear(L.k, pos_, q, cut)) {
        feed(to_vec3(q, z), p_.feed_mm_min, false);
        return;
      }
      // Not straight: around the obstacle through what this layer has cut, when that is
      // cheaper than going up and over (not for the plain zig-zag baseline, which links
      // straight or lifts, as a CAM system without segmentation does).
      const std::vector<Vec2> way =
          routing()
              ? cached_route(false, pos_, q, [&] { return route(L.k, L.flags, pos_, q, cut); })
              : std::vector<Vec2>{};
      if (!way.empty() && polyline_length(pos_, way) < lift_cost(L.k, pos_, q)) {
        for (const Vec2& w : way)
          feed(to_vec3(w, z), p_.feed_mm_min, false);
        return;
      }
    } else if (has_pos_) {
      const double zp = m_.layer_z(prev_k_);
      if (layer_change_clear(q)) {
        feed(to_vec3(q, zp), p_.feed_mm_min, false);
        plunge(z);
        return;
      }
      const std::vector<Vec2> way =
          routing()
              ? cached_route(true, pos_, q,
                             [&] {
                               return route(prev_k_, prev_flags(), pos_, q, [&](std::size_t c) {
                                 return (prev_flags()[c] & voxel_detail::kFree) != 0;
                               });
                             })
              : std::vector<Vec2>{};
      if (!way.empty() && polyline_length(pos_, way) < lift_cost(L.k, pos_, q)) {
        for (const Vec2& w : way)
          feed(to_vec3(w, zp), p_.feed_mm_min, false);
        plunge(z);
        return;
      }
    }
    if (has_pos_) {
      rapid(to_vec3(pos_, clear_z_));
      ++metrics_->lift_offs;
    }
    rapid(to_vec3(q, clear_z_));
    rapid(to_vec3(q, m_.layer_top(L.k) + kApproachMm));
    plunge(z);
  }

  template <class F>
  const std::vector<Vec2>& cached_route(bool layer_change, Vec2 p, Vec2 q, F&& compute) {
    std::vector<std::uint64_t>& key = route_key_;
    key.assign({cell_at(p), cell_at(q), layer_change ? 1u : 0u});
    if (!layer_change) key.insert(key.end(), done_.begin(), done_.end());
    auto& routes = scratch_->routes;
    auto it = routes.find(key);
    if (it == routes.end()) it = routes.emplace(key, compute()).first;
    return it->second;
  }

  void mark(voxel_detail::CellPoint a, voxel_detail::CellPoint b) {
    for_cells(a, b, [&](std::size_t c) { cleared_[c] = 1; });
  }

  void rapid(Vec3 p) { add(make_move(MoveKind::kRapid, p, 0.0, false)); }
  void feed(Vec3 p, double f, bool cutting) { add(make_move(MoveKind::kFeed, p, f, cutting)); }
  void plunge(double z) {
    add(make_move(MoveKind::kPlunge, to_vec3(pos_, z), p_.plunge_feed_mm_min, true));
  }
  void add(Move mv) {
    if (has_last_ && mv.end == last_) return;
    if (has_last_ && (mv.kind == MoveKind::kRapid || !mv.cutting)) air_ += distance(last_, mv.end);
    tp_->moves.push_back(mv);
    last_ = mv.end;
    has_last_ = true;
    pos_ = mv.end.xy();
    has_pos_ = true;
  }

  const RoughParams& p_;
  Toolpath* tp_;
  RoughMetrics* metrics_;
  double air_ = 0.0;  // air length emitted so far (what the candidates are compared by)
  double dry_run_budget_ = kDryRunCellBudget;
  double total_budget_ = kDryRunTotalBudget;
  std::vector<std::uint8_t> plan_flags_;                // the last layer planned from scratch...
  TwoEndsTour plan_tour_;                               // ...and the order it got
  TwoEndsInstance plan_optimistic_, plan_pessimistic_;  // its link costs
  double clear_z_ = 0.0;
  Vec2 pos_;
  bool has_pos_ = false;
  Vec3 last_;
  bool has_last_ = false;
  int prev_k_ = -1, started_layer_ = -1;
  std::vector<std::uint8_t> prev_flags_, cleared_;
  // Dry runs: the previous layer's flags and the layer's start state are borrowed from the
  // builder that runs them; the simulating builder and its output are reused.
  const std::vector<std::uint8_t>* borrowed_prev_ = nullptr;
  std::vector<std::uint8_t> own_start_;
  const std::vector<std::uint8_t>* layer_start_ = &own_start_;
  double abort_at_ = std::numeric_limits<double>::infinity();
  bool aborted_ = false;
  std::unique_ptr<Builder> dry_sim_;
  std::vector<double> heights_;                  // compared_heights(reach_), when first needed
  std::size_t route_class_ = SIZE_MAX;           // heights below the threshold of the routes' layer
  std::vector<std::uint8_t> route_flags_;        // cells of the routes' layer
  std::vector<std::uint64_t> done_, route_key_;  // regions finished in this layer; a route key
  struct Snapshot {  // the cheapest complete dry run of the layer and its end state
    double cost = std::numeric_limits<double>::infinity();
    TwoEndsTour tour;
    std::vector<Move> moves;
    std::size_t lift_offs = 0;
    double air = 0.0;
    Vec2 pos;
    bool has_pos = false;
    Vec3 last;
    bool has_last = false;
    int started_layer = -1;
  } snap_;
  Toolpath dry_tp_;
  RoughMetrics dry_metrics_;

  const std::vector<std::uint8_t>& prev_flags() const {
    return borrowed_prev_ != nullptr ? *borrowed_prev_ : prev_flags_;
  }
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

// Cells whose square meets the convex stock outline (empty outline: every cell).
std::vector<std::uint8_t> stock_mask(const VoxelModel& m, const std::vector<Vec2>& outline) {
  if (outline.empty()) return {};
  std::vector<std::uint8_t> mask(static_cast<std::size_t>(m.nx) * static_cast<std::size_t>(m.ny));
  const double h = 0.5 * m.cell_mm;
  for (int j = 0; j < m.ny; ++j) {
    for (int i = 0; i < m.nx; ++i) {
      const Vec2 c = m.centre(i, j);
      const Vec2 corners[4] = {c + Vec2{-h, -h}, c + Vec2{h, -h}, c + Vec2{h, h}, c + Vec2{-h, h}};
      // Separating axes: the outline's edge normals (the square's axes are covered by the
      // grid spanning the outline's box).
      bool meets = true;
      for (std::size_t e = 0; e < outline.size() && meets; ++e) {
        const Vec2 a = outline[e], b = outline[(e + 1) % outline.size()];
        bool all_outside = true;
        for (const Vec2& q : corners)
          all_outside = all_outside && cross(b - a, q - a) < 0.0;
        if (all_outside) meets = false;
      }
      mask[m.column(i, j)] = meets ? 1 : 0;
    }
  }
  return mask;
}

}  // namespace

Result<RoughResult> rough(const Mesh& part, const RoughParams& p, const Context& ctx) {
  SWARF_RETURN_IF_ERROR(validate(p));
  const auto t0 = Clock::now();
  RoughResult res;
  res.rotation_deg = p.zigzag_angle_deg;
  VoxelizeOptions vo;
  vo.cell_mm = p.stepover_mm;
  vo.layer_mm = p.stepdown_mm;
  vo.stock = p.stock;
  vo.margin_mm = p.margin_mm;
  vo.top_margin_mm = p.top_margin_mm;
  vo.repair_open = p.repair_open_mesh;
  // Part tops on squares of about 2 mm or less: the offset is then conservative by that
  // much instead of by a whole stepover (more machinable cells near walls).
  vo.top_subdivisions = std::clamp(static_cast<int>(std::ceil(p.stepover_mm / kTopSquareMm)), 1, 4);
  // Seed 003 3.1.1 without re-clamping the part: part and stock are turned by -angle so
  // that the grid's x axis runs along the wanted feed direction, and the toolpath is turned
  // back at the end. Cells outside the turned stock hold nothing to cut.
  const double angle = p.zigzag_angle_deg;
  Mesh turned;
  std::vector<Vec2> outline;
  if (angle != 0.0) {
    Box3 stock = p.stock;
    if (stock.empty()) {
      for (const Vec3& v : part.vertices)
        stock.add(v);
      stock = Box3{
          {stock.min.x - p.margin_mm, stock.min.y - p.margin_mm, stock.min.z},
          {stock.max.x + p.margin_mm, stock.max.y + p.margin_mm, stock.max.z + p.top_margin_mm}};
    }
    turned = rotate_about_z(part, -angle);
    Box3 grid = stock;
    grid.min.x = grid.min.y = std::numeric_limits<double>::infinity();
    grid.max.x = grid.max.y = -std::numeric_limits<double>::infinity();
    for (Vec2 c : {stock.min.xy(), Vec2{stock.max.x, stock.min.y}, stock.max.xy(),
                   Vec2{stock.min.x, stock.max.y}}) {
      outline.push_back(rotated(c, deg_to_rad(-angle)));
      grid.min.x = std::min(grid.min.x, outline.back().x);
      grid.min.y = std::min(grid.min.y, outline.back().y);
      grid.max.x = std::max(grid.max.x, outline.back().x);
      grid.max.y = std::max(grid.max.y, outline.back().y);
    }
    vo.stock = grid;
  }
  auto vox = voxelize(angle != 0.0 ? turned : part, vo, ctx);
  if (!vox.ok()) return vox.status();
  const VoxelModel& m = *vox;
  res.warnings = m.warnings;
  res.timings.voxelize_s = seconds_since(t0);
  ctx.report("rough: voxelized", 0.2);

  auto t1 = Clock::now();
  const Reach reach = voxel_detail::compute_reach(m, 0.5 * p.tool_diameter_mm, p.stock_to_leave_mm,
                                                  p.offset, ctx.threads);
  const std::vector<std::uint8_t> stock_cells = stock_mask(m, outline);
  std::vector<Layer> layers(static_cast<std::size_t>(m.layers));
  parallel_for(layers.size(), ctx.threads, [&](std::size_t k) {
    layers[k].k = static_cast<int>(k);
    layers[k].flags = voxel_detail::layer_flags(m, reach, static_cast<int>(k), stock_cells);
  });
  res.timings.preprocess_s = seconds_since(t1);
  if (ctx.cancelled()) return Status{Error::kCancelled, "rough: cancelled"};

  t1 = Clock::now();
  parallel_for(layers.size(), ctx.threads, [&](std::size_t k) {
    Layer& L = layers[k];
    if (L.flags.empty()) return;  // no room for the tool in this layer
    constexpr std::uint8_t kCut = voxel_detail::kFree | voxel_detail::kStock;
    for (std::uint8_t f : L.flags)
      L.free_cells += (f & kCut) == kCut ? 1 : 0;
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
  voxel_detail::LinkScratch scratch;
  Builder b(m, reach, p, tp, res.metrics, scratch);
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
  if (angle != 0.0) {
    for (Move& mv : tp.moves)
      mv.end = to_vec3(rotated(mv.end.xy(), deg_to_rad(angle)), mv.end.z);
  }
  measure(tp, res.metrics);
  res.timings.total_s = seconds_since(t0);
  return res;
}

}  // namespace swarf
