// Figures a machinist compares toolpaths by.
#pragma once

#include <cstddef>

#include "swarf/toolpath/toolpath.h"

namespace swarf {

struct MetricsOptions {
  /// Rapid traverse rate of the machine, mm/min.
  double rapid_mm_min = 5000.0;
};

struct ToolpathMetrics {
  double cutting_length_mm = 0.0;  ///< feed moves flagged cutting (plunges, ramps, arcs too)
  double air_length_mm = 0.0;      ///< rapids plus feed moves flagged not cutting
  double rapid_length_mm = 0.0;    ///< rapids alone
  /// Times the tool leaves the work to the clearance plane between cuts (the final
  /// retract at the program's end is not counted).
  std::size_t lift_offs = 0;
  double machining_time_s = 0.0;  ///< feeds at their feed rates plus rapids at rapid_mm_min
  std::size_t moves = 0;
};

/// The first move's length is not counted (its start is the machine's unknown position).
ToolpathMetrics compute_metrics(const Toolpath& path, const MetricsOptions& options = {});

}  // namespace swarf
