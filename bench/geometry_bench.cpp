// Timings of the geometry foundation: slicing (seed 001 slices the torus part at pitches down
// to 0.005 mm) and polygon offsets. Figures go to bench/RESULTS-geometry.md.
#include <benchmark/benchmark.h>

#include <vector>

#include "swarf/mesh/generate.h"
#include "swarf/mesh/slice.h"
#include "swarf/polygon/polygon.h"

namespace {

using namespace swarf;  // NOLINT(google-build-using-namespace): bench file, not a header

// The filleted torus part; segments 256 gives about 100k triangles.
const Mesh& torus_part(int segments) {
  static Mesh m128 = make_filleted_torus_part({.segments = 128});
  static Mesh m256 = make_filleted_torus_part({.segments = 256});
  return segments == 128 ? m128 : m256;
}

// Args: segments, number of levels, threads (0 = all).
void BM_SliceTorusPart(benchmark::State& state) {
  const Mesh& m = torus_part(static_cast<int>(state.range(0)));
  const Box3 b = bounds(m);
  const auto n = static_cast<double>(state.range(1));
  const std::vector<double> levels = slice_levels(b.min.y, b.max.y, (b.max.y - b.min.y) / n);
  Context ctx;
  ctx.threads = static_cast<int>(state.range(2));
  std::size_t rings = 0;
  for (auto _ : state) {
    const auto slices = slice_mesh(m, Axis::kY, levels, {}, ctx);
    rings = 0;
    for (const auto& s : slices)
      rings += s.rings.size();
    benchmark::DoNotOptimize(rings);
  }
  state.counters["triangles"] = static_cast<double>(m.size());
  state.counters["levels"] = static_cast<double>(levels.size());
  state.counters["rings"] = static_cast<double>(rings);
}
BENCHMARK(BM_SliceTorusPart)
    ->Args({128, 1000, 1})
    ->Args({256, 1000, 1})
    ->Args({256, 10000, 1})
    ->Args({256, 10000, 0})
    ->Unit(benchmark::kMillisecond);

// Offsets of a torus section (a plate with bumps) by a ball radius, as the convolutional
// 3D offset of seed 001 Eq. (1) does thousands of times.
void BM_OffsetSection(benchmark::State& state) {
  const Mesh& m = torus_part(256);
  const PolygonSet s = slice_mesh(m, Axis::kY, {0.0})[0];
  const double delta = static_cast<double>(state.range(0)) / 10.0;
  std::size_t points = 0;
  for (auto _ : state) {
    const PolygonSet o = offset(s, delta, {.arc_tolerance_mm = 0.001});
    points = 0;
    for (const Ring& r : o.rings)
      points += r.size();
    benchmark::DoNotOptimize(points);
  }
  state.counters["input_points"] = static_cast<double>(s.rings.empty() ? 0 : s.rings[0].size());
  state.counters["output_points"] = static_cast<double>(points);
}
BENCHMARK(BM_OffsetSection)->Arg(40)->Arg(-40)->Unit(benchmark::kMicrosecond);

void BM_UnionOfDisks(benchmark::State& state) {
  // Many overlapping inflated points in one union pass.
  std::vector<Polyline2> pts;
  for (int i = 0; i < state.range(0); ++i)
    pts.push_back({{0.37 * i, 0.11 * (i % 13)}});
  for (auto _ : state) {
    const PolygonSet u = inflate_polylines(pts, 2.0);
    benchmark::DoNotOptimize(u.rings.data());
  }
}
BENCHMARK(BM_UnionOfDisks)->Arg(1000)->Unit(benchmark::kMillisecond);

}  // namespace
