// Seed 003 timings: voxel sizes 5, 2 and 1 mm on a 100 x 100 x 100 mm freeform part and on
// the 500 x 500 x 100 mm block with four bosses. Stage times are reported as counters
// (seconds): voxelize, preprocess (offset + projection), segment, sequence (TSP + links).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "swarf/mesh/generate.h"
#include "swarf/voxel/rough.h"

namespace {

// The paper's Part 2 stand-in: a closed heightfield solid, 100 x 100 mm, 10 to 100 mm
// high, with several peaks and valleys; 200 x 200 quads on top.
swarf::Mesh freeform_part() {
  const int n = 200;
  swarf::Mesh m;
  auto f = [](double x, double y) {
    return 55.0 + 25.0 * std::sin(x / 11.0) * std::cos(y / 13.0) +
           15.0 * std::exp(-((x - 65) * (x - 65) + (y - 35) * (y - 35)) / 200.0) -
           10.0 * std::cos((x + y) / 17.0);
  };
  const auto nn = static_cast<std::uint32_t>(n + 1);
  for (int layer = 0; layer < 2; ++layer) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i) {
        const double x = 100.0 * i / n, y = 100.0 * j / n;
        m.vertices.push_back({x, y, layer == 0 ? f(x, y) : 0.0});
      }
    }
  }
  auto top = [&](std::uint32_t i, std::uint32_t j) { return j * nn + i; };
  auto bot = [&](std::uint32_t i, std::uint32_t j) { return nn * nn + j * nn + i; };
  for (std::uint32_t j = 0; j + 1 < nn; ++j) {
    for (std::uint32_t i = 0; i + 1 < nn; ++i) {
      m.triangles.push_back({top(i, j), top(i + 1, j), top(i + 1, j + 1)});
      m.triangles.push_back({top(i, j), top(i + 1, j + 1), top(i, j + 1)});
      m.triangles.push_back({bot(i, j), bot(i + 1, j + 1), bot(i + 1, j)});
      m.triangles.push_back({bot(i, j), bot(i, j + 1), bot(i + 1, j + 1)});
    }
  }
  const std::uint32_t e = nn - 1;
  for (std::uint32_t k = 0; k + 1 < nn; ++k) {
    auto wall = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
      m.triangles.push_back({a, c, d});
      m.triangles.push_back({a, d, b});
    };
    wall(top(k + 1, 0), top(k, 0), bot(k + 1, 0), bot(k, 0));
    wall(top(k, e), top(k + 1, e), bot(k, e), bot(k + 1, e));
    wall(top(0, k), top(0, k + 1), bot(0, k), bot(0, k + 1));
    wall(top(e, k + 1), top(e, k), bot(e, k + 1), bot(e, k));
  }
  return m;
}

void run(benchmark::State& state, const swarf::Mesh& part, double voxel_mm) {
  swarf::RoughParams p;
  p.tool_diameter_mm = 10.0;
  p.stepover_mm = voxel_mm;
  p.stepdown_mm = voxel_mm;
  p.stock_to_leave_mm = 1.0;
  swarf::RoughTimings t;
  swarf::RoughMetrics m;
  swarf::Context ctx;
  ctx.threads = static_cast<int>(state.range(1));
  for (auto _ : state) {
    auto r = swarf::rough(part, p, ctx);
    if (!r.ok()) {
      state.SkipWithError(r.status().to_string().c_str());
      return;
    }
    t = r->timings;
    m = r->metrics;
    benchmark::DoNotOptimize(r->toolpath.moves.data());
  }
  state.counters["voxelize_s"] = t.voxelize_s;
  state.counters["preprocess_s"] = t.preprocess_s;
  state.counters["segment_s"] = t.segment_s;
  state.counters["sequence_s"] = t.sequence_s;
  state.counters["total_s"] = t.total_s;
  state.counters["regions"] = static_cast<double>(m.regions);
  state.counters["lift_offs"] = static_cast<double>(m.lift_offs);
  state.counters["air_m"] = m.air_length_mm / 1000.0;
  state.counters["total_m"] = m.total_length_mm / 1000.0;
}

void BM_RoughFreeform(benchmark::State& state) {
  static const swarf::Mesh part = freeform_part();
  run(state, part, static_cast<double>(state.range(0)));
}
// Arguments: voxel size in mm, threads (1 = the figure that does not depend on the machine's
// load; 0 = every core).
BENCHMARK(BM_RoughFreeform)
    ->ArgsProduct({{5, 2, 1}, {1, 0}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_RoughBlockWithBosses(benchmark::State& state) {
  static const swarf::Mesh part = swarf::make_block_with_bosses({500, 500, 100}, 100, 20);
  run(state, part, static_cast<double>(state.range(0)));
}
BENCHMARK(BM_RoughBlockWithBosses)
    ->ArgsProduct({{5, 2, 1}, {1, 0}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
