// Post-processing shared by every strategy: simplification, corner smoothing, arc fitting.
#pragma once

#include <functional>
#include <vector>

#include "swarf/core/vec.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf {

/// Douglas-Peucker: drops points so that the polyline moves by at most tolerance_mm.
/// Keeps the first and last points.
std::vector<Vec3> simplify_polyline(const std::vector<Vec3>& points, double tolerance_mm);
std::vector<Vec2> simplify_polyline(const std::vector<Vec2>& points, double tolerance_mm);

/// A raster line of CL points refined below its sampling where it climbs steeper than 3:1 and
/// bends away from its chord. Beside a wall the CL jumps (the ball rests on the rim or falls
/// past it), and rolling over a rim it rises along a circle with a vertical tangent, so two
/// points a sampling step apart can differ by millimetres and the straight move between them
/// runs through the wall's top. Such a stretch is halved, with `height(xy)` giving the CL
/// height at its middle, while the middle leaves the chord by more than tolerance / 2 normal
/// to it, down to 2 um: a jump becomes a step that wide. A smooth steep stretch that turns
/// from its neighbours by dtheta bends away from them by about s dtheta / 8 and is left as it
/// is while that is under tolerance / 4 (a jump turns by about 90 degrees).
std::vector<Vec3> refine_steep_stretches(const std::vector<Vec3>& line, double tolerance_mm,
                                         const std::function<double(Vec2)>& height);

/// Chaikin corner cutting, `iterations` times, keeping the end points (open polyline).
/// Each pass replaces a corner by points at `ratio` and 1 - ratio along its edges.
std::vector<Vec2> chaikin_smooth(const std::vector<Vec2>& points, int iterations,
                                 double ratio = 0.25);

/// Simplifies each run of consecutive linear moves of the same kind, feed and cutting flag.
Toolpath simplify(const Toolpath& path, double tolerance_mm);

struct ArcFitOptions {
  double tolerance_mm = 0.005;  ///< largest distance of a replaced point from the arc
  double min_radius_mm = 0.05;
  double max_radius_mm = 1000.0;
  int min_points = 4;  ///< shortest run of lines to turn into an arc
  /// Optional veto on a fitted arc (e.g. one that would cut into a wall between the points
  /// it replaces): `start` is where the arc begins, `arc` the G2/G3 move. A vetoed arc is
  /// tried shorter; where none is accepted the lines stay.
  std::function<bool(Vec2 start, const Move& arc)> accept;
};
/// Replaces runs of linear feed moves at constant height whose points lie on a circle
/// within the tolerance by XY arcs (G2/G3).
Toolpath fit_arcs(const Toolpath& path, const ArcFitOptions& options = {});

}  // namespace swarf
