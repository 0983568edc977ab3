// Voxel zig-zag roughing with region sequencing (seed 003): voxel model, offset and
// projection (2.3), Trapped Area segmentation (2.4.1), feed-line clustering (2.4.2),
// sequencing of the regions (2.4.3) and the layer-by-layer toolpath with its metrics
// (Tables 1-2), and the part-orientation study (3.1.1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/mesh/mesh.h"
#include "swarf/sequence/two_ends_tsp.h"
#include "swarf/toolpath/toolpath.h"
#include "swarf/voxel/voxel.h"

namespace swarf {

/// How the part is grown by the tool radius plus the allowance (section 2.3.1).
enum class OffsetRule {
  /// A true disk of radius D/2 + allowance around every tool position, measured to the
  /// closed cell squares (whose exact part tops are known) and, for moves between cells, to
  /// the whole swept stadium. The paper's rule differs in two ways: its n0-cell square
  /// reaches sqrt(2) times farther along the diagonals than along the axes, so convex part
  /// corners keep up to 41% more stock than the allowance asks (and the next finishing
  /// pass meets uneven stock); and it is applied to centre-ray voxels, so part material
  /// between two column centres is invisible to it. The disk blocks exactly the centres
  /// that would bring the tool closer than the allowance, in every direction.
  kDisk,
  /// Seed 003 Eq. (3.1): n0 = ceil((2 s + D - w) / (2 w)) rounds of 8-neighbour dilation
  /// of the centre-ray voxels. Kept for comparison; it can gouge where part features fall
  /// between column centres.
  kPaperSquare,
};

enum class RoughSequence {
  /// Baseline: a plain zig-zag over each layer, row after row, no segmentation; links are
  /// straight or lift-offs (never routed around an obstacle).
  kZigzag,
  kTrappedArea,  ///< Trapped Area regions in the order they are found (the paper's "TA")
  kGa,           ///< Trapped Area regions sequenced by the GA plus local search ("GA")
};
std::string_view rough_sequence_name(RoughSequence s);
Result<RoughSequence> parse_rough_sequence(std::string_view name);

struct RoughParams {
  double tool_diameter_mm = 10.0;
  double stepover_mm = 6.6;        ///< Δx = Δy of the voxels (section 3.1 uses 6.6 mm)
  double stepdown_mm = 2.0;        ///< Δz
  double stock_to_leave_mm = 3.0;  ///< finishing allowance, sideways and on floors
  double margin_mm = 0.0;          ///< stock = part box grown by this sideways...
  double top_margin_mm = 0.0;      ///< ...and this on top (ignored with an explicit stock)
  Box3 stock;                      ///< explicit stock box; empty = from the part
  double clearance_mm = 5.0;       ///< clearance plane above the stock top
  double feed_mm_min = 1000.0;
  double plunge_feed_mm_min = 300.0;
  /// Extra price of a lift-off, mm of path, in the sequencing and when choosing between a
  /// lift and a stay-down link routed through cut cells (a retract costs its vertical
  /// travel anyway). High values favour few lift-offs (the paper's first figure of merit)
  /// over a short air path; 0 minimises the air path alone.
  double lift_penalty_mm = 300.0;
  /// Feed lines run at this angle to the x axis (seed 003 3.1.1): part and stock stay
  /// where they are and the toolpath comes out in the part's frame.
  double zigzag_angle_deg = 0.0;
  OffsetRule offset = OffsetRule::kDisk;
  RoughSequence sequence = RoughSequence::kGa;
  /// GA settings (seed included). Fewer kicks than the stand-alone default: the layer's
  /// order is refined on the true emitted cost afterwards anyway.
  SequenceOptions ga = [] {
    SequenceOptions o;
    o.kicks = 30;
    return o;
  }();
  bool repair_open_mesh = false;  ///< see VoxelizeOptions::repair_open
};

Status validate(const RoughParams& params);

/// Tables 1-2 of the paper, plus what else a machinist compares.
struct RoughMetrics {
  std::size_t lift_offs = 0;   ///< retracts to the clearance plane (final one excluded)
  double air_length_mm = 0.0;  ///< rapids plus feed moves through already cut space
  double cutting_length_mm = 0.0;
  double total_length_mm = 0.0;  ///< air + cutting (the first positioning rapid excluded)
  std::size_t regions = 0;       ///< machining regions (runs for the zig-zag), all layers
  std::size_t layers = 0;
  std::size_t machinable_cells = 0;  ///< tool positions summed over the layers
};

struct RoughTimings {
  double voxelize_s = 0.0;
  double preprocess_s = 0.0;  ///< offset and projection
  double segment_s = 0.0;     ///< regions and feed lines
  double sequence_s = 0.0;    ///< TSP and linking
  double total_s = 0.0;
};

struct RoughResult {
  Toolpath toolpath;
  RoughMetrics metrics;
  RoughTimings timings;
  double rotation_deg = 0.0;  ///< the part was rotated by this about z (frame of the path)
  std::vector<std::string> warnings;
};

/// One roughing run on `part` in its own frame.
Result<RoughResult> rough(const Mesh& part, const RoughParams& params,
                          const Context& ctx = default_context());

/// Seed 003 section 3.1.1: the paper turns the part on the table; turning the feed
/// direction instead (RoughParams::zigzag_angle_deg) gives the same toolpaths relative to
/// the part while part, stock and program stay in the part's frame.
struct OrientationResult {
  std::vector<double> angles_deg;
  std::vector<RoughMetrics> metrics;  ///< per angle
  std::size_t best = 0;               ///< index of the shortest total path (first if tied)
  RoughResult best_result;
};
Result<OrientationResult> rough_orientations(const Mesh& part, const RoughParams& params,
                                             const std::vector<double>& angles_deg,
                                             const Context& ctx = default_context());

}  // namespace swarf
