// seed 001 Tables 2 and 3 on the filleted torus part with a ø8 ball end mill, and the scanning
// program of issue 4 (stepover 0.5 mm, 0.1 mm along the lines) against the exact
// drop-cutter. Run: swarf_bench --benchmark_filter=TriSlice  (figures in RESULTS-trislice.md)
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>
#include <ctime>

#include "swarf/dropcut/dropcut.h"
#include "swarf/mesh/generate.h"
#include "swarf/trislice/envelope.h"
#include "swarf/trislice/surface_paths.h"

namespace swarf {
namespace {

const double kPitches[] = {0.25, 0.125, 0.05, 0.01, 0.005};

const Mesh& torus_part() {
  static const Mesh m = make_filleted_torus_part();
  return m;
}

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}
double cpu() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::size_t model_bytes(const TriSliceModel& m) {
  std::size_t b = 0;
  for (const SliceFamily& f : m.families)
    for (const PolygonSet& s : f.slices)
      for (const Ring& r : s.rings)
        b += r.size() * sizeof(Vec2) + sizeof(Ring);
  return b;
}

// Table 2: slice model (all three families), Table 1 roughing, finishing (stepover 0.25 mm,
// one-way, 0.1 mm along the lines).
void BM_TriSliceTable2(benchmark::State& state) {
  const double pitch = kPitches[state.range(0)];
  const Tool tool = ball_mill(8.0);
  for (auto _ : state) {
    const double t0 = now(), c0 = cpu();
    auto model = build_trislice_families(torus_part(), pitch, {true, true, true});
    const TriSliceTop top = TriSliceTop::build(*model);
    const double t1 = now(), c1 = cpu();
    ScanParams sp;
    sp.direction = Axis::kX;
    RoughingParams rough;  // Table 1
    rough.stock_top_mm = 20.0;
    auto r = scan_roughing(*model, top, tool, sp, rough);
    const double t2 = now(), c2 = cpu();
    sp.stepover_mm = 0.25;
    sp.adaptive = state.range(1) != 0;
    auto lines = scan_cl_lines(top, model->bounds, tool.radius(), 0.0, sp);
    std::size_t points = 0;
    for (const auto& l : *lines)
      points += l.size();
    auto f = scan_finishing_from_lines(*model, top, tool, sp, std::move(lines).value());
    const double t3 = now(), c3 = cpu();
    state.counters["cl_points"] = static_cast<double>(points);
    benchmark::DoNotOptimize(r);
    benchmark::DoNotOptimize(f);
    state.counters["model_s"] = t1 - t0;
    state.counters["rough_s"] = t2 - t1;
    state.counters["finish_s"] = t3 - t2;
    state.counters["total_s"] = t3 - t0;
    state.counters["total_cpu_s"] = c3 - c0;
    state.counters["model_cpu_s"] = c1 - c0;
    state.counters["rough_cpu_s"] = c2 - c1;
    state.counters["finish_cpu_s"] = c3 - c2;
    state.counters["model_MB"] = static_cast<double>(model_bytes(*model)) / 1048576.0;
    state.counters["index_MB"] = static_cast<double>(top.memory_bytes()) / 1048576.0;
    state.counters["slices"] =
        static_cast<double>(model->family(Axis::kX).size() + model->family(Axis::kY).size());
  }
}
// Second argument: 1 = adaptive sampling along the lines (the default), 0 = uniform grid.
BENCHMARK(BM_TriSliceTable2)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {1, 0}})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

// The full tri-slice model (all three families): time and memory against the slice count.
void BM_TriSliceModelAll(benchmark::State& state) {
  const double pitch = kPitches[state.range(0)];
  for (auto _ : state) {
    auto model = build_trislice(torus_part(), pitch);
    std::size_t n = 0;
    for (const SliceFamily& f : model->families)
      n += f.size();
    state.counters["slices"] = static_cast<double>(n);
    state.counters["model_MB"] = static_cast<double>(model_bytes(*model)) / 1048576.0;
  }
}
BENCHMARK(BM_TriSliceModelAll)
    ->DenseRange(0, 4)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

// Table 3: tri-slice CL against the exact drop-cutter on the same mesh, over the grid of the
// scanning program (stepover 0.5 mm, 0.1 mm along the lines).
void BM_TriSliceTable3(benchmark::State& state) {
  const double pitch = kPitches[state.range(0)];
  const Mesh& mesh = torus_part();
  auto dc = DropCutter::build(mesh, CutterShape{4.0, 4.0});
  ClGrid grid{bounds(mesh).xy(), Axis::kX, 0.5, 0.1};
  auto exact = drop_grid(*dc, grid, bounds(mesh).min.z);
  for (auto _ : state) {
    auto model = build_trislice_families(mesh, pitch, {true, true, true});
    const TriSliceTop top = TriSliceTop::build(*model);
    ScanParams sp;
    sp.stepover_mm = 0.5;
    sp.sampling_mm = 0.1;
    sp.adaptive = false;  // compared point by point with the drop-cutter's grid
    auto lines = scan_cl_lines(top, model->bounds, 4.0, 0.0, sp);
    std::size_t k = 0, n1 = 0, n2 = 0, n5 = 0;
    double mx = 0.0;
    for (const auto& line : *lines)
      for (const Vec3& p : line) {
        const double d = std::fabs(p.z - (*exact)[k++].z) * 1e3;
        mx = std::max(mx, d);
        n1 += d <= 1.0;
        n2 += d <= 2.0;
        n5 += d <= 5.0;
      }
    state.counters["points"] = static_cast<double>(k);
    state.counters["max_um"] = mx;
    state.counters["within1_pct"] = 100.0 * static_cast<double>(n1) / static_cast<double>(k);
    state.counters["within2_pct"] = 100.0 * static_cast<double>(n2) / static_cast<double>(k);
    state.counters["within5_pct"] = 100.0 * static_cast<double>(n5) / static_cast<double>(k);
  }
}
BENCHMARK(BM_TriSliceTable3)
    ->DenseRange(0, 4)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

// The scanning program at 0.05 mm: model + CL points, end to end.
void BM_TriSliceScanProgram(benchmark::State& state) {
  for (auto _ : state) {
    const double c0 = cpu();
    auto model = build_trislice_families(torus_part(), 0.05, {true, true, true});
    const TriSliceTop top = TriSliceTop::build(*model);
    ScanParams sp;
    sp.stepover_mm = 0.5;
    sp.sampling_mm = 0.1;
    sp.adaptive = state.range(0) != 0;
    auto lines = scan_cl_lines(top, model->bounds, 4.0, 0.0, sp);
    std::size_t n = 0;
    for (const auto& l : *lines)
      n += l.size();
    state.counters["points"] = static_cast<double>(n);
    state.counters["cpu_s"] = cpu() - c0;
  }
}
BENCHMARK(BM_TriSliceScanProgram)
    ->Arg(0)
    ->Arg(1)
    ->Iterations(3)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

// The exact drop-cutter on the same grid (index build included).
void BM_DropCutterScanProgram(benchmark::State& state) {
  const Mesh& mesh = torus_part();
  for (auto _ : state) {
    const double c0 = cpu();
    auto dc = DropCutter::build(mesh, CutterShape{4.0, 4.0});
    ClGrid grid{bounds(mesh).xy(), Axis::kX, 0.5, 0.1};
    auto cl = drop_grid(*dc, grid, bounds(mesh).min.z);
    state.counters["points"] = static_cast<double>(cl->size());
    state.counters["cpu_s"] = cpu() - c0;
  }
}
BENCHMARK(BM_DropCutterScanProgram)->Iterations(3)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// Table 3 on analytic parts: a sphere (R 10) and a torus (15, 5), ø8 ball, contacts within 60
// degrees of vertical. Tri-slice against the exact drop-cutter on the same mesh, and the
// drop-cutter against the closed form of the ball offset (its gap is the facets' sagitta).
void BM_TriSliceAnalytic(benchmark::State& state) {
  const double pitch = kPitches[state.range(0)];
  const bool sphere = state.range(1) == 0;
  const double r = 4.0;
  const Mesh mesh =
      sphere ? make_sphere({0, 0, 0}, 10.0, 256) : make_torus({0, 0, 0}, 15.0, 5.0, 256, 128);
  auto closed = [&](Vec2 p) {
    if (sphere) return std::sqrt(14.0 * 14.0 - norm_sq(p)) - r;
    const double e = norm(p) - 15.0;
    return std::sqrt(9.0 * 9.0 - e * e) - r;
  };
  auto inside = [&](Vec2 p) {
    const double s60 = std::sin(deg_to_rad(60.0));
    return sphere ? norm(p) < 14.0 * s60 : std::fabs(norm(p) - 15.0) < 9.0 * s60;
  };
  auto dc = DropCutter::build(mesh, CutterShape{r, r});
  for (auto _ : state) {
    auto model = build_trislice(mesh, pitch);
    const TriSliceTop top = TriSliceTop::build(*model);
    const Box2 b = model->bounds.xy();
    std::size_t n = 0, n1 = 0, n2 = 0, n5 = 0;
    double mx = 0.0, mx_closed = 0.0;
    for (double y = b.min.y; y <= b.max.y; y += 0.5) {
      ScanHint hint;
      for (double x = b.min.x; x <= b.max.x; x += 0.1) {
        if (!inside({x, y})) continue;
        const double exact = dc->drop_z({x, y});
        const double tri = top.centre_height({x, y}, r, Axis::kY, &hint) - r;
        const double d = std::fabs(exact - tri) * 1e3;
        mx = std::max(mx, d);
        mx_closed = std::max(mx_closed, std::fabs(exact - closed({x, y})) * 1e3);
        n1 += d <= 1.0;
        n2 += d <= 2.0;
        n5 += d <= 5.0;
        ++n;
      }
    }
    state.counters["points"] = static_cast<double>(n);
    state.counters["max_um"] = mx;
    state.counters["within1_pct"] = 100.0 * static_cast<double>(n1) / static_cast<double>(n);
    state.counters["within2_pct"] = 100.0 * static_cast<double>(n2) / static_cast<double>(n);
    state.counters["within5_pct"] = 100.0 * static_cast<double>(n5) / static_cast<double>(n);
    state.counters["dropcut_vs_closed_max_um"] = mx_closed;
  }
}
BENCHMARK(BM_TriSliceAnalytic)
    ->ArgsProduct({{0, 1, 2, 3, 4}, {0, 1}})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
}  // namespace swarf
