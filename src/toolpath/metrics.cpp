// Toolpath metrics: lengths, lift-offs and machining time.
#include "swarf/toolpath/metrics.h"

namespace swarf {

ToolpathMetrics compute_metrics(const Toolpath& path, const MetricsOptions& options) {
  ToolpathMetrics m;
  m.moves = path.moves.size();
  if (path.moves.empty()) return m;
  // A move reaching the clearance plane counts as a lift-off only once a cut has happened
  // before it and another cut follows it, so the approach from the machine's start and the
  // final retract are not counted. The tolerance absorbs rounding of read-back G-code.
  constexpr double kClearanceTolMm = 1e-6;
  const double clearance = path.clearance_z_mm - kClearanceTolMm;
  bool cut_before = false;
  bool lifted = false;
  Vec3 pos = path.moves.front().end;
  for (std::size_t i = 0; i < path.moves.size(); ++i) {
    const Move& move = path.moves[i];
    const Vec3 start = pos;
    pos = move.end;
    const bool is_cut = move.kind != MoveKind::kRapid && move.cutting;
    if (is_cut) {
      if (lifted) ++m.lift_offs;
      lifted = false;
      cut_before = true;
    } else if (cut_before && start.z < clearance && move.end.z >= clearance) {
      lifted = true;
    }
    if (i == 0) continue;  // starts from the machine's unknown position
    const double len = move_length(start, move);
    if (move.kind == MoveKind::kRapid) {
      m.rapid_length_mm += len;
      m.air_length_mm += len;
      if (options.rapid_mm_min > 0.0) m.machining_time_s += len / options.rapid_mm_min * 60.0;
    } else {
      (move.cutting ? m.cutting_length_mm : m.air_length_mm) += len;
      // A feed of zero has no defined time; it is left out rather than made infinite.
      if (move.feed_mm_min > 0.0) m.machining_time_s += len / move.feed_mm_min * 60.0;
    }
  }
  m.machine_time_s = machine_time_s(path, options);
  return m;
}

}  // namespace swarf
