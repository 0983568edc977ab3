// Running a toolpath against a stock (seed 001 section 3.3, Fig. 8): the tool advances in
// steps, cutting-edge points are tested against the stock for engagement (Fig. 10), forces
// follow from Eq. (2)-(5) at every rotation step, and the swept tool is subtracted from the
// stock slices. Also: feed scheduling against a force limit (beyond the paper).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/mesh/mesh.h"
#include "swarf/sim/force.h"
#include "swarf/sim/stock.h"
#include "swarf/tool/tool.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf::sim {

struct SimulationOptions {
  /// Δd: tool advance between engagement evaluations, mm (the paper uses the slice pitch).
  double step_mm = 0.1;
  /// Tool advance collected before one subtraction from the stock, mm. Engagement is tested
  /// against the stock as it was before the batch: exact for the edge points that cut
  /// (they face the feed and lie outside the solid already swept along a straight move).
  double batch_mm = 3.0;
  /// A batch also ends when the path turns by more than this, degrees: on a curve the
  /// pending (not yet subtracted) sweep could count material the tool already passed at its
  /// sides. Measured on a helical pocket: forces change by 0.1% between 5° and 90°, the run
  /// time by 4x; 45° keeps every sharp corner a batch boundary.
  double batch_turn_deg = 45.0;
  /// Spindle speed, rpm; 0 takes the toolpath's.
  double spindle_rpm = 0.0;
  /// Rapid traverse rate for the clock, mm/min.
  double rapid_mm_min = 5000.0;
  bool compute_forces = true;
  EngagementRule engagement = EngagementRule::kMajority;
  ForceModelOptions force;  ///< dz and dθ (Table 4: 0.1 mm, 1°)
  /// Keep every n-th rotation step in the waveform (1 = all).
  int sample_stride = 1;
  /// For the summary: time during which |F| exceeds this, N (0: not counted).
  double force_limit_n = 0.0;
  /// Removed material above this on a rapid counts as a collision, mm^3.
  double collision_volume_mm3 = 1e-3;
};

/// One sample of the force waveform (forces on the tool, machine axes).
struct ForceSample {
  double t_s = 0.0;
  Vec3 force_n;
  std::uint32_t move = 0;
};

struct MoveResult {
  double t_start_s = 0.0, t_end_s = 0.0;
  double removed_mm3 = 0.0;      ///< median of the three families
  double peak_force_n = 0.0;     ///< largest |F| during the move
  double mean_force_n = 0.0;     ///< mean |F| over the move's rotation steps
  double engaged_arc_deg = 0.0;  ///< largest engaged arc of any axial level
  /// At the peak: the part of F proportional to the chip thickness and the edge part
  /// (for feed scheduling: F(s f) = s C + E when the feed is scaled by s).
  Vec3 peak_cutting_n, peak_edge_n;
  bool collision = false;  ///< a rapid that removed material
};

struct SimulationResult {
  std::vector<MoveResult> moves;  ///< one per toolpath move
  std::vector<ForceSample> samples;
  /// The input with force_n (peak, N) and engagement_deg (largest engaged arc) annotated.
  Toolpath annotated;
  std::array<double, 3> removed_by_family_mm3{};
  double removed_mm3 = 0.0;
  std::vector<std::string> collisions;  ///< "move 12: rapid removed 3.2 mm^3 at (x, y, z)"
  double machining_time_s = 0.0;
  double peak_force_n = 0.0;
  Vec3 peak_abs_n;            ///< largest |Fx|, |Fy|, |Fz| seen
  double mean_force_n = 0.0;  ///< mean |F| over cutting time (samples with F != 0)
  double time_above_limit_s = 0.0;
  double cutting_time_s = 0.0;  ///< time with any engaged edge
};

/// Runs `path` against `stock` (modified in place). Moves start where the previous one
/// ended; the first move is taken as positioning to its end (from above the stock).
Result<SimulationResult> simulate(Stock& stock, const Toolpath& path, const Tool& tool,
                                  const CuttingCoefficients& k, const SimulationOptions& options,
                                  const Context& ctx = default_context());

struct FeedScheduleOptions {
  double max_force_n = 300.0;  ///< peak |F| allowed
  double min_feed_mm_min = 1.0;
  /// Largest factor a feed may be raised by (1: only slow down).
  double max_increase = 2.0;
  /// Never above this feed, mm/min (0: no cap).
  double max_feed_mm_min = 0.0;
  /// Chip-load limit, mm per tooth (0: none): no feed above max_chip x rpm x flutes.
  double max_chip_mm = 0.0;
  double spindle_rpm = 0.0;  ///< for the chip-load limit
  int flutes = 2;            ///< for the chip-load limit
};

struct FeedSchedule {
  Toolpath path;                                   ///< feeds rescaled
  double time_before_s = 0.0, time_after_s = 0.0;  ///< feed moves at their feeds
  std::size_t slowed = 0, raised = 0;
};

/// Rescales the feed of each cutting move so that the predicted peak |F| meets the limit:
/// with the feed scaled by s the peak becomes |s C + E| (C the chip-thickness part, E the
/// edge part at the peak), solved for s per move; moves in air may be raised up to
/// max_increase. Rapids are kept.
FeedSchedule schedule_feed(const Toolpath& path, const SimulationResult& sim,
                           const FeedScheduleOptions& options);

/// Output helpers.
std::string forces_csv(const SimulationResult& r);  ///< t_s,fx_n,fy_n,fz_n,f_n,move
std::string moves_csv(const SimulationResult& r);   ///< per-move volume, peak, mean, ...
/// Fx, Fy, Fz against time (at most max_points per series, by peak-preserving decimation).
std::string forces_svg(const SimulationResult& r, const std::string& title,
                       std::size_t max_points = 4000);
/// Top view of the height map as a PNG (blue low, red high; no material white).
Status write_height_map_png(const std::string& path, const HeightMap& map, int pixels_per_cell = 2);
/// The height map as CSV rows x_mm,y_mm,z_mm.
std::string height_map_csv(const HeightMap& map);
/// The height map as a closed solid between `floor_z` and the top surface through the cell
/// centres (cells without material at floor_z): the machined stock as a mesh for STL.
Mesh height_map_mesh(const HeightMap& map, double floor_z);

}  // namespace swarf::sim
