// The tool solid cut by one slice plane (seed 001 Fig. 9): a disk in an xy plane, the
// tool's side profile (a U open upwards) in a yz or zx plane, and the region such sections
// sweep along a polyline of tip positions.
#pragma once

#include <span>
#include <vector>

#include "swarf/polygon/polygon.h"
#include "swarf/sim/stock.h"

namespace swarf::sim {

/// Convex hull (Andrew's monotone chain), counter-clockwise, collinear points dropped.
Ring convex_hull(std::vector<Vec2> points);

/// Appends the points of the section of the tool (tip at `tip`) by the plane {axis = level},
/// in the plane's coordinates, up to the absolute height `top`. Nothing when the plane misses.
void append_section_points(const ToolSolid& tool, Vec3 tip, Axis axis, double level, double top,
                           std::vector<Vec2>& out);

/// Region swept in the plane {axis = level} by the tool along the tips polyline (each pair
/// of consecutive tips a straight move). `pitch` sets the sampling of inclined moves.
PolygonSet swept_section(const ToolSolid& tool, std::span<const Vec3> tips, Axis axis, double level,
                         double top, double pitch);

}  // namespace swarf::sim
