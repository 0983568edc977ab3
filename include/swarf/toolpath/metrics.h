// Figures a machinist compares toolpaths by.
#pragma once

#include <cstddef>

#include "swarf/toolpath/toolpath.h"

namespace swarf {

struct MetricsOptions {
  /// Rapid traverse rate of the machine, mm/min.
  double rapid_mm_min = 5000.0;
  /// The machine's acceleration along the path, mm/s^2, the same for every axis (1000 is
  /// about 0.1 g: a light mill or a stiff router; big machining centres reach 3000-5000).
  /// 0 = none: machine_time_s is then machining_time_s.
  double accel_mm_s2 = 1000.0;
  /// How far from the programmed corner the machine may round it at speed, mm (grbl's
  /// junction deviation, $11; LinuxCNC's G64 P tolerance plays the same part). 0 = exact
  /// stop at every corner (G61).
  double junction_deviation_mm = 0.01;
};

struct ToolpathMetrics {
  double cutting_length_mm = 0.0;  ///< feed moves flagged cutting (plunges, ramps, arcs too)
  double air_length_mm = 0.0;      ///< rapids plus feed moves flagged not cutting
  double rapid_length_mm = 0.0;    ///< rapids alone
  /// Times the tool leaves the work to the clearance plane between cuts (the final
  /// retract at the program's end is not counted).
  std::size_t lift_offs = 0;
  double machining_time_s = 0.0;  ///< feeds at their feed rates plus rapids at rapid_mm_min
  /// The same moves on a machine that accelerates at accel_mm_s2 and slows down for corners
  /// (machine_time_s below): what a reversal or a sharp corner costs shows here.
  double machine_time_s = 0.0;
  std::size_t moves = 0;
};

/// The first move's length is not counted (its start is the machine's unknown position).
ToolpathMetrics compute_metrics(const Toolpath& path, const MetricsOptions& options = {});

/// The time the path takes on a machine with the acceleration and junction deviation of
/// `options`, seconds, with look-ahead over the whole path: each move at its feed (rapids at
/// rapid_mm_min), arcs no faster than their centripetal acceleration allows, each corner no
/// faster than the arc that rounds it within the junction deviation allows, and the tool at
/// rest at the start and the end and around moves with no feed. Starts from the end of the
/// first move, as compute_metrics does.
double machine_time_s(const Toolpath& path, const MetricsOptions& options = {});

}  // namespace swarf
