// An independent check of a pocket toolpath, sharing no code with the generator: a fine
// bitmap of the pocket, the tool disk stamped brute force along the final floor pass
// sampled densely, exact point-to-edge distances for gouges, and the engagement read off
// the stamped bitmap as the arc of the tool's front half touching uncut material that the
// program removes at some point (and also by removal, see SweepReport).
#pragma once

#include <vector>

#include "swarf/polygon/polygon.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf::testing {

struct SweepReport {
  double max_gouge_mm = 0.0;        ///< deepest the disk reaches past a wall or into an island
  double residual_mm2 = 0.0;        ///< reachable material left, farther than tol from walls
  double unreachable_mm2 = 0.0;     ///< pocket minus its opening by the tool disk
  double cutting_length_mm = 0.0;   ///< floor-pass length with engagement > 2 deg (no entry)
  double within_20pct = 0.0;        ///< fraction of it within +-20 % of the target angle
  double max_engagement_deg = 0.0;  ///< outside the entry
  double slot_length_mm = 0.0;      ///< length engaged >= 170 deg (a full slot), outside entry
  /// The same figure by removal (seed 000's definition of engagement): the area the swept
  /// disk removes over each window of path, as the stepover of a straight cut of that
  /// width, as an angle. Unlike the arc, it does not see material the tool never removes
  /// (the skin of half a generator pixel left on the walls lies just outside the arc's
  /// circle of R + pixel/2, so every pass along a wall reads a few degrees there).
  double removal_cutting_length_mm = 0.0;
  double within_20pct_removal = 0.0;
  /// The arc counting any uncut pocket material on its ring, also what no pass ever
  /// removes (session 1's measure; it reads a few degrees wherever a pass runs within half a
  /// checker pixel of a hair it leaves, and the full corner arc where the tool sits tangent
  /// to both walls of a corner).
  double within_20pct_any_material = 0.0;
  /// Milling side: of the cutting length whose contact lies mostly (two thirds or more of
  /// the arc) on one side of the motion, the share with the material on the right, which is
  /// climb milling for a clockwise (M3) spindle. Slot-like contact, even on both sides, is
  /// in neither. 1 when nothing is one-sided.
  double climb_share = 1.0;
  /// Sharp turns of the floor pass, cutting or not: places where its heading turns by more
  /// than 135 degrees within 1 mm of path (the machine stops there and goes back). One turn
  /// counts once.
  int reversals = 0;
  double floor_length_mm = 0.0;  ///< the floor pass's length, links at the floor included
};

/// One floor-pass sample of the sweep, for diagnosis (where the engagement leaves its band).
struct SweepSample {
  Vec2 position;
  double length_mm = 0.0;         ///< path length this sample stands for
  double engagement_deg = 0.0;    ///< -1 for entry samples (helix, ramp)
  double wall_distance_mm = 0.0;  ///< from the tool centre to the nearest wall or island
  std::size_t move = 0;           ///< index of its move in the toolpath
  double removed_mm2 = 0.0;       ///< material the disk removes here
};

/// region: outer ring then islands (or several such parts; even-odd). The floor pass is the moves
/// at the lowest z of the program; helix, ramp and plunge moves and the arcs at the bottom of a
/// helix are the entry. pixel_mm: checker resolution; residual_tol_mm: material this close to a
/// wall is not counted as residual. residual_out: the centres of the residual's pixels (diagnosis).
SweepReport sweep_check(const PolygonSet& region, double tool_radius_mm, const Toolpath& path,
                        double target_engagement_deg, double pixel_mm, double residual_tol_mm,
                        std::vector<SweepSample>* samples = nullptr, double removal_window_mm = 0.5,
                        std::vector<Vec2>* residual_out = nullptr);

}  // namespace swarf::testing
