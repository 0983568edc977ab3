// seed 001 section 4.2's validation cut: ø8 ball end mill, helix 30°, 2 flutes, 3600 rpm,
// 200 mm/min, Table 4 coefficients, slice pitch 0.1 mm, axial resolution 0.1 mm, radial
// resolution 1°. A steady 2 mm deep cut, 10 mm long (3 s of machining). The counter
// "x_realtime" is seconds of machining simulated per second of computation.
#include <benchmark/benchmark.h>

#include "swarf/sim/simulate.h"

namespace {

using namespace swarf;

Toolpath validation_cut() {
  Toolpath p;
  p.spindle_rpm = 3600.0;
  p.rapid_to({-5, 15, 25});
  p.rapid_to({-5, 15, 18});
  p.feed_to({1, 15, 18}, 200.0);   // entry, then steady engagement
  p.feed_to({11, 15, 18}, 200.0);  // the measured part
  return p;
}

void run(benchmark::State& state, int threads, bool forces) {
  Tool tool = ball_mill(8.0);
  tool.flutes = 2;
  tool.helix_angle_deg = 30.0;
  sim::SimulationOptions opt;  // pitch-sized steps, dz 0.1 mm, dθ 1°
  opt.compute_forces = forces;
  Context ctx;
  ctx.threads = threads;
  double machining = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    sim::Stock stock = std::move(sim::Stock::block({{0, 0, 0}, {50, 30, 20}}, 0.1)).value();
    state.ResumeTiming();
    const auto r =
        sim::simulate(stock, validation_cut(), tool, sim::CuttingCoefficients{}, opt, ctx);
    if (!r.ok()) state.SkipWithError(r.status().to_string().c_str());
    machining = r->machining_time_s;
    benchmark::DoNotOptimize(r->peak_force_n);
  }
  state.counters["x_realtime"] =
      benchmark::Counter(machining, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_SimValidationCut_1Thread(benchmark::State& s) {
  run(s, 1, true);
}
void BM_SimValidationCut_AllCores(benchmark::State& s) {
  run(s, 0, true);
}
void BM_SimRemovalOnly_1Thread(benchmark::State& s) {
  run(s, 1, false);
}

BENCHMARK(BM_SimValidationCut_1Thread)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();
BENCHMARK(BM_SimValidationCut_AllCores)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SimRemovalOnly_1Thread)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime();

}  // namespace
