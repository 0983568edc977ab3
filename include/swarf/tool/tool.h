// End mills: flat, ball and bull-nose. A cutter is its profile (OpenCAMLib's idea):
// height above the tip as a function of the distance from the axis, and the inverse.
#pragma once

#include <string>
#include <string_view>

#include "swarf/core/status.h"

namespace swarf {

enum class ToolKind { kFlat, kBall, kBull };

std::string_view tool_kind_name(ToolKind kind);

struct Tool {
  ToolKind kind = ToolKind::kFlat;
  double diameter_mm = 10.0;
  /// Corner radius: 0 for flat, diameter/2 for ball, in (0, diameter/2) for bull-nose.
  double corner_radius_mm = 0.0;
  int flutes = 2;
  double helix_angle_deg = 30.0;
  /// Length of the cutting edges; a stepdown may not exceed it.
  double flute_length_mm = 30.0;
  /// Tool number in the machine's magazine (T word).
  int number = 1;
  std::string name;

  double radius() const { return diameter_mm * 0.5; }
  /// Height of the cutting surface above the tool tip at distance r from the axis, mm.
  /// +infinity beyond the radius.
  double height_at(double r) const;
  /// Distance from the axis of the cutting surface at height h above the tip, mm
  /// (the radius for h at or above the corner).
  double width_at(double h) const;
  /// "ø10 flat end mill, 3 flutes" for comments and reports.
  std::string description() const;
};

/// Checks a tool's dimensions; the message names the fault ("corner radius 6 mm exceeds
/// the tool radius 5 mm").
Status validate(const Tool& tool);

/// A ball end mill of the given diameter (corner radius = radius).
Tool ball_mill(double diameter_mm);
/// A flat end mill of the given diameter.
Tool flat_mill(double diameter_mm);

/// Parses "KIND:DIAMETER[:CORNER_RADIUS]", KIND flat, ball or bull; validates the result.
Result<Tool> parse_tool_spec(std::string_view spec);

}  // namespace swarf
