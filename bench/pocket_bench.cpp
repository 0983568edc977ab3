// Adaptive pocket (seed 000) against the contour-parallel baseline on the pockets.
// Time is the generator alone (single-threaded: the method is sequential); the quality
// figures come from the independent sweep of tests/pocket/sweep_checker.cpp on the final
// G-code-level toolpath (0.05 mm pixels), reported as counters.
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "../tests/pocket/sweep_checker.cpp"  // the independent checker, shared with the tests
#include "swarf/pocket/adaptive.h"
#include "swarf/pocket/contour_parallel.h"
#include "swarf/toolpath/metrics.h"

namespace {

using namespace swarf;

Pocket load(const std::string& name) {
  return read_pocket(std::string(SWARF_SOURCE_DIR) + "/tests/data/pocket/" + name).value();
}

Pocket star_pocket() {
  Ring r;
  for (int k = 0; k < 10; ++k) {
    const double a = kPi * k / 5 + kPi / 2, rad = k % 2 == 0 ? 50.0 : 24.0;
    r.push_back({rad * std::cos(a), rad * std::sin(a)});
  }
  return make_pocket(r, {}, "star").value();
}

Pocket pocket_by_index(int i) {
  switch (i) {
    case 0:
      return load("l_pocket_islands.json");
    case 1:
      return load("kirimoto_pocket.json");
    case 2:
      return star_pocket();
    default:
      return load("pcbvicebar_slice.json");
  }
}

void quality(benchmark::State& state, const Pocket& p, const Toolpath& tp, double r,
             double target) {
  const auto s = testing::sweep_check(p.region, r, tp, target, 0.05, 0.2);
  MetricsOptions mo;
  const ToolpathMetrics m = compute_metrics(tp, mo);
  state.counters["cut_mm"] = m.cutting_length_mm;
  state.counters["air_mm"] = m.air_length_mm;
  state.counters["time_s"] = m.machining_time_s;
  state.counters["lifts"] = static_cast<double>(m.lift_offs);
  state.counters["gouge_mm"] = s.max_gouge_mm;
  state.counters["residual_mm2"] = s.residual_mm2;
  state.counters["within20_pct"] = 100.0 * s.within_20pct;
  state.counters["within20_rm_pct"] = 100.0 * s.within_20pct_removal;
  state.counters["within20_any_pct"] = 100.0 * s.within_20pct_any_material;
  state.counters["max_eng_deg"] = s.max_engagement_deg;
  state.counters["slot_mm"] = s.slot_length_mm;
}

// Arguments: pocket index (0 L with islands, 1 Kiri:Moto 40x40, 2 star, 3 PCB-vice bar).
void BM_AdaptivePocket(benchmark::State& state) {
  const Pocket p = pocket_by_index(static_cast<int>(state.range(0)));
  Tool t;
  t.diameter_mm = state.range(0) == 3 ? 6.0 : 10.0;
  AdaptiveParams ap;
  ap.stepover_mm = 0.1 * t.diameter_mm;
  ap.depth_mm = 6.0;
  Result<AdaptiveResult> r = bad_input("not run");
  for (auto _ : state) {
    r = adaptive_pocket(p, t, ap);
    benchmark::DoNotOptimize(r);
  }
  if (!r.ok()) {
    state.SkipWithError(r.status().to_string().c_str());
    return;
  }
  state.counters["pixel_mm"] = r->resolution_mm;
  quality(state, p, r->toolpath, t.radius(), r->target_engagement_deg);
}
BENCHMARK(BM_AdaptivePocket)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_ContourParallelPocket(benchmark::State& state) {
  const Pocket p = pocket_by_index(static_cast<int>(state.range(0)));
  Tool t;
  t.diameter_mm = state.range(0) == 3 ? 6.0 : 10.0;
  ContourParallelParams cp;
  cp.stepover_mm = 0.1 * t.diameter_mm;
  cp.depth_mm = 6.0;
  Result<ContourParallelResult> r = bad_input("not run");
  for (auto _ : state) {
    r = contour_parallel_pocket(p, t, cp);
    benchmark::DoNotOptimize(r);
  }
  if (!r.ok()) {
    state.SkipWithError(r.status().to_string().c_str());
    return;
  }
  quality(state, p, r->toolpath, t.radius(), engagement_angle_deg(cp.stepover_mm, t.radius()));
}
BENCHMARK(BM_ContourParallelPocket)->DenseRange(0, 3)->Unit(benchmark::kMillisecond)->Iterations(3);

}  // namespace
