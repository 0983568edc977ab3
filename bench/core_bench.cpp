#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "swarf/core/parallel.h"

static void BM_ParallelForOverhead(benchmark::State& state) {
  std::vector<double> out(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    swarf::parallel_for(out.size(), 0, [&](std::size_t i) { out[i] = std::sqrt(double(i)); });
    benchmark::DoNotOptimize(out.data());
  }
}
BENCHMARK(BM_ParallelForOverhead)->Arg(1000)->Arg(100000);
