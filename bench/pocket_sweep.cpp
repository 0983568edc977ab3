// Judges any pocket G-code with the independent sweep of tests/pocket/sweep_checker.cpp:
//   swarf_pocket_sweep [--wall-stock S] [--pixel H] [--accel MM_S2] [--junction-deviation MM]
//                      POCKET.json TOOL_DIAMETER TARGET_ENGAGEMENT_DEG PROGRAM.nc
//                      [SAMPLES.csv [RESIDUAL.csv]]
// With --wall-stock the pocket is judged shrunk by S mm (Clipper offset, round joins): the
// tool must keep S off the walls and clear up to there.
// Prints one line of figures (gouge, residual, cutting length, engagement within +-20 % of
// the target by contact arc and by removal, largest engagement, full-slot length, machining
// time (at the feeds, and on a machine: by default 1000 mm/s^2 and 0.01 mm of junction
// deviation), lifts, the most one move at the link feed removes and the most one removes per
// mm). Used by bench/compare_freecad.sh to put Swarf's adaptive pocket beside FreeCAD's.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "../tests/pocket/sweep_checker.cpp"
#include "swarf/gcode/gcode.h"
#include "swarf/pocket/adaptive.h"
#include "swarf/pocket/pocket_input.h"
#include "swarf/polygon/polygon.h"
#include "swarf/toolpath/metrics.h"

int main(int argc, char** argv) {
  using namespace swarf;
  double wall_stock = 0.0, pixel = 0.0;
  MetricsOptions machine;
  while (argc >= 3) {
    const std::string flag = argv[1];
    double* value = flag == "--wall-stock"           ? &wall_stock
                    : flag == "--pixel"              ? &pixel
                    : flag == "--accel"              ? &machine.accel_mm_s2
                    : flag == "--junction-deviation" ? &machine.junction_deviation_mm
                                                     : nullptr;
    if (value == nullptr) break;
    *value = std::atof(argv[2]);
    argv += 2;
    argc -= 2;
  }
  if (argc < 5 || argc > 7) {
    std::fprintf(stderr,
                 "usage: swarf_pocket_sweep [--wall-stock S] [--pixel H] [--accel MM_S2] "
                 "[--junction-deviation MM] POCKET.json TOOL_DIAMETER TARGET_DEG PROGRAM.nc "
                 "[SAMPLES.csv [RESIDUAL.csv]]\n");
    return 2;
  }
  auto pocket = read_pocket(argv[1]);
  if (!pocket.ok()) {
    std::fprintf(stderr, "%s\n", pocket.status().to_string().c_str());
    return 2;
  }
  auto program = read_gcode(argv[4]);
  if (!program.ok()) {
    std::fprintf(stderr, "%s\n", program.status().to_string().c_str());
    return 2;
  }
  const double d = std::atof(argv[2]), target = std::atof(argv[3]);
  // The checker's pixel: 0.05 mm, or a twentieth of the target's stepover where that is
  // finer. The arc is read on a ring half a pixel outside the tool, which adds about
  // pixel / 4 to the stepover it sees: at 0.05 mm a ø3 at 5 % (0.15 mm) read 28-30 degrees
  // for a straight pass at exactly its 25.8 (random pocket 2419: 65 % within +-20 % at
  // 0.05 mm, 87 % at 0.025, 93 % at 0.0125, 95 % at 0.00625, where it settles).
  if (pixel <= 0.0) pixel = std::min(0.05, stepover_for_angle_mm(target, 0.5 * d) / 20.0);
  std::vector<testing::SweepSample> samples;
  std::vector<Vec2> residual;
  const PolygonSet region = wall_stock > 0.0 ? offset(pocket->region, -wall_stock) : pocket->region;
  const auto s =
      testing::sweep_check(region, 0.5 * d, *program, target, pixel, 0.2, &samples, 0.5, &residual);
  auto open_csv = [](const char* path) {
    std::FILE* f = std::fopen(path, "w");
    if (f == nullptr) std::fprintf(stderr, "%s: cannot write\n", path);
    return f;
  };
  if (argc >= 6) {
    // x, y, path length, arc engagement (deg, -1 in the entry), distance to the walls, the
    // index of the sample's move in the program and that move's feed (mm/min).
    std::FILE* f = open_csv(argv[5]);
    if (f == nullptr) return 2;
    std::fprintf(f, "x,y,ds,eng,wall,move,feed\n");
    for (const auto& q : samples) {
      const auto& mv = program->moves;
      const double feed = q.move < mv.size() ? mv[q.move].feed_mm_min : 0.0;
      std::fprintf(f, "%.3f,%.3f,%.4f,%.1f,%.3f,%zu,%.0f\n", q.position.x, q.position.y,
                   q.length_mm, q.engagement_deg, q.wall_distance_mm, q.move, feed);
    }
    std::fclose(f);
  }
  if (argc == 7) {
    // x, y of each residual pixel's centre (material the tool reaches and the program left).
    std::FILE* f = open_csv(argv[6]);
    if (f == nullptr) return 2;
    std::fprintf(f, "x,y\n");
    for (const Vec2& q : residual)
      std::fprintf(f, "%.3f,%.3f\n", q.x, q.y);
    std::fclose(f);
  }
  const ToolpathMetrics m = compute_metrics(*program, machine);
  // The most one feed move at 5000 mm/min or more (Swarf's link feed, the rapid rate of the
  // time estimates) removes: links over cleared floor should take crumbs of these finer
  // pixels at most.
  std::vector<double> per_move(program->moves.size(), 0.0), move_len(program->moves.size(), 0.0);
  double link_cut = 0.0, link_len = 0.0;
  for (const auto& q : samples) {
    const Move& mv = program->moves[q.move];
    if (mv.kind != MoveKind::kFeed || mv.feed_mm_min < 5000.0 - 1e-9) continue;
    move_len[q.move] += q.length_mm;
    if ((per_move[q.move] += q.removed_mm2) > link_cut) {
      link_cut = per_move[q.move];
      link_len = move_len[q.move];
    }
  }
  // And the densest: removal per mm of path, as a radial depth (moves of 0.05 mm or more).
  double densest = 0.0;
  std::size_t dense_move = 0;
  for (std::size_t k = 0; k < per_move.size(); ++k) {
    if (move_len[k] >= 0.05 && per_move[k] / move_len[k] > densest) {
      densest = per_move[k] / move_len[k];
      dense_move = k;
    }
  }
  const Vec3 dense_at = program->moves.empty() ? Vec3{} : program->moves[dense_move].end;
  std::printf(
      "gouge %.3f mm, residual %.2f mm2, cutting %.0f mm, within20 %.1f %% (removal %.1f %%) "
      "(anymaterial %.1f %%), max engagement %.0f deg, slot %.1f mm, machining %.0f s, "
      "machine %.0f s, lifts %d, "
      "linkcut %.3f mm2 over %.2f mm, densest %.3f mm (%.2f mm to %.3f, %.3f), climb %.1f %%, "
      "reversals %d (%.1f per m), pixel %.4f mm\n",
      s.max_gouge_mm, s.residual_mm2, s.cutting_length_mm, 100 * s.within_20pct,
      100 * s.within_20pct_removal, 100 * s.within_20pct_any_material, s.max_engagement_deg,
      s.slot_length_mm, m.machining_time_s, m.machine_time_s, static_cast<int>(m.lift_offs),
      link_cut, link_len, densest, move_len[dense_move], dense_at.x, dense_at.y,
      100 * s.climb_share, s.reversals,
      s.floor_length_mm > 0 ? 1000.0 * s.reversals / s.floor_length_mm : 0.0, pixel);
  return 0;
}
