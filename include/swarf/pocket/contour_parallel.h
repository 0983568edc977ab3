// The contour-parallel pocket (seed 000 Fig. 1 left): rings offset from the walls inwards,
// the first at tool radius + wall stock, then one radial stepover apart, cut inside-out
// (or outside-in), with a helix entry. The baseline the adaptive pocket is measured against.
#pragma once

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/pocket/pocket_input.h"
#include "swarf/tool/tool.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf {

struct ContourParallelParams {
  double stepover_mm = 0.0;  ///< radial stepover between rings; 0 = 10 % of the diameter
  bool inside_out = true;    ///< innermost ring first (false: from the wall inwards)
  bool climb = true;         ///< material on the right of the feed direction (M3)
  double depth_mm = 6.0;     ///< pocket depth below top_z_mm
  double stepdown_mm = 0.0;  ///< per layer; 0 = whole depth
  double floor_stock_mm = 0.0;
  double wall_stock_mm = 0.0;
  double top_z_mm = 0.0;
  double clearance_z_mm = 5.0;
  double feed_mm_min = 1000.0;
  double ramp_feed_mm_min = 0.0;    ///< helix and ramp feed along the path; 0 = feed_mm_min
  double ramp_angle_deg = 3.0;      ///< helix and ramp descent angle
  double arc_tolerance_mm = 0.005;  ///< of the offset rings' round joins
};

Status validate(const ContourParallelParams& params, const Tool& tool);

struct ContourParallelResult {
  Toolpath toolpath;
  int rings = 0;               ///< per layer
  int retracts_per_layer = 0;  ///< links that had to lift (they would have gouged or slotted)
};

/// kToolTooLarge when the tool fits nowhere, kNoEntryFound when no helix fits anywhere.
Result<ContourParallelResult> contour_parallel_pocket(const Pocket& pocket, const Tool& tool,
                                                      const ContourParallelParams& params,
                                                      const Context& ctx = default_context());

}  // namespace swarf
