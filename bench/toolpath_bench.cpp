// Post-processing, G-code and machine-time throughput on 10^5-point paths.
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "swarf/gcode/gcode.h"
#include "swarf/toolpath/metrics.h"
#include "swarf/toolpath/postprocess.h"

namespace swarf {
namespace {

constexpr int kPoints = 100000;

/// An Archimedean spiral with 0.005 mm of noise: what a pocketing strategy emits.
std::vector<Vec2> noisy_spiral() {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> noise(-0.005, 0.005);
  std::vector<Vec2> pts;
  pts.reserve(kPoints);
  for (int i = 0; i < kPoints; ++i) {
    const double a = 0.01 * i;
    const double r = 1.0 + 0.5 * a / (2.0 * kPi);
    pts.push_back({r * std::cos(a) + noise(rng), r * std::sin(a) + noise(rng)});
  }
  return pts;
}

/// Concentric circles from r = 7 mm, polygonised with 0.5 mm chords (sagitta below the
/// 0.005 mm fitting tolerance for r >= 7 mm), joined by short feeds: arc fitting's best case.
Toolpath polygon_circles() {
  Toolpath p;
  p.rapid_to({2.0, 0.0, -1.0});
  int circle = 0;
  while (static_cast<int>(p.moves.size()) < kPoints) {
    const double r = 7.0 + 1.0 * circle++;
    p.feed_to({r, 0.0, -1.0}, 1000.0);
    const int n = static_cast<int>(std::ceil(2.0 * kPi * r / 0.5));
    for (int i = 1; i <= n; ++i) {
      const double a = 2.0 * kPi * i / n;
      p.feed_to({r * std::cos(a), r * std::sin(a), -1.0}, 1000.0);
    }
  }
  return p;
}

void BM_DouglasPeucker(benchmark::State& state) {
  const auto pts = noisy_spiral();
  std::size_t kept = 0;
  for (auto _ : state) {
    const auto out = simplify_polyline(pts, 0.01);
    kept = out.size();
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(state.iterations() * kPoints);
  state.counters["kept"] = static_cast<double>(kept);
}
BENCHMARK(BM_DouglasPeucker)->Unit(benchmark::kMillisecond);

void BM_FitArcs(benchmark::State& state) {
  const Toolpath p = polygon_circles();
  std::size_t moves = 0;
  for (auto _ : state) {
    const Toolpath out = fit_arcs(p);
    moves = out.moves.size();
    benchmark::DoNotOptimize(out.moves.data());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(p.moves.size()));
  state.counters["moves_in"] = static_cast<double>(p.moves.size());
  state.counters["moves_out"] = static_cast<double>(moves);
}
BENCHMARK(BM_FitArcs)->Unit(benchmark::kMillisecond);

void BM_WriteGcode(benchmark::State& state) {
  const Toolpath p = polygon_circles();
  GcodeOptions o;
  o.dialect = static_cast<Dialect>(state.range(0));
  std::size_t bytes = 0;
  for (auto _ : state) {
    const std::string g = write_gcode(p, o);
    bytes = g.size();
    benchmark::DoNotOptimize(g.data());
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(bytes));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(p.moves.size()));
  state.SetLabel(std::string(dialect_name(o.dialect)));
}
BENCHMARK(BM_WriteGcode)->Arg(0)->Arg(1)->Arg(2)->Arg(3)->Unit(benchmark::kMillisecond);

void BM_ParseGcode(benchmark::State& state) {
  const std::string g = write_gcode(polygon_circles(), GcodeOptions{});
  for (auto _ : state) {
    auto r = parse_gcode(g, "bench.nc");
    benchmark::DoNotOptimize(r.ok());
  }
  state.SetBytesProcessed(state.iterations() * static_cast<std::int64_t>(g.size()));
}
BENCHMARK(BM_ParseGcode)->Unit(benchmark::kMillisecond);

// The acceleration-limited time of 10^5 moves (polygonised circles: a junction every 0.5 mm).
void BM_MachineTime(benchmark::State& state) {
  const Toolpath p = polygon_circles();
  double seconds = 0.0;
  for (auto _ : state) {
    seconds = machine_time_s(p);
    benchmark::DoNotOptimize(seconds);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(p.moves.size()));
  state.counters["machine_s"] = seconds;
  state.counters["feed_s"] = compute_metrics(p, {}).machining_time_s;
}
BENCHMARK(BM_MachineTime)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace swarf
