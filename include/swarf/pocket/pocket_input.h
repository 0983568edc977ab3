// A 2.5D pocket: an outer boundary minus islands, read from JSON, SVG or DXF (mm).
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "swarf/core/status.h"
#include "swarf/polygon/polygon.h"

namespace swarf {

/// The region to clear. `region` is normalized: an outer ring counter-clockwise first,
/// then its islands clockwise; no ring intersects itself or another, every island lies
/// strictly inside its outer ring and outside every other island. Where the islands given
/// overlapped or reached the outer boundary, they were merged (see make_pocket) and the
/// region may hold several parts, each an outer ring followed by its islands, the largest
/// first.
struct Pocket {
  PolygonSet region;
  /// Where it came from (file name), for messages.
  std::string source;
  /// What make_pocket merged, for the user (empty for a pocket taken as drawn).
  std::vector<std::string> notes;

  const Ring& outer() const { return region.rings.front(); }
  /// Clockwise rings: islands.
  std::size_t island_count() const {
    return static_cast<std::size_t>(
        std::count_if(region.rings.begin(), region.rings.end(),
                      [](const Ring& r) { return signed_area(r) < 0.0; }));
  }
};

/// Checks and orients an outer ring and its islands. Islands that overlap or touch each
/// other or the outer boundary are merged: the pocket is then the outer ring's inside minus
/// the union of the islands (on the polygon grid, kPolygonResolutionMm), possibly in several
/// parts, and `notes` says so. kBadInput names `source` and the place (ring, edge, point) of
/// a self-intersection, an island wholly outside the outer ring or wholly inside another
/// island, islands covering the whole pocket, a ring with fewer than 3 points or no area,
/// or a non-finite coordinate.
Result<Pocket> make_pocket(Ring outer, std::vector<Ring> islands, std::string_view source);

/// {"outer": [[x,y],...], "islands": [[[x,y],...],...]} in mm; "islands" may be absent.
Result<Pocket> parse_pocket_json(std::string_view text, std::string_view source);

struct CurveInputOptions {
  /// Largest distance between an arc and the chords that replace it, mm.
  double arc_tolerance_mm = 0.01;
  /// Endpoints closer than this are joined when chaining DXF entities into loops, mm.
  double join_tolerance_mm = 1e-3;
};

/// SVG <polygon>, <polyline> (must close on itself), <rect>, <circle>, <ellipse> and <path>
/// with every command (M L H V C S Q T A Z, absolute and relative; curves flattened to the
/// arc tolerance), with transforms (docs/pocket.md, "Pocket input").
/// User units are mm unless a viewBox and an absolute width scale them; the y axis is
/// flipped so that the drawing keeps its look.
/// The loop with the largest area is the outer boundary, the others islands; a loop outside
/// every larger one (neither crossing nor touching it) is an outline of its own, a separate
/// pocket in the same region (pocket_from_loops).
Result<Pocket> parse_pocket_svg(std::string_view text, std::string_view source,
                                const CurveInputOptions& options = {});

/// ASCII DXF: LWPOLYLINE and POLYLINE (with bulges), LINE, ARC, CIRCLE, ELLIPSE and NURBS
/// SPLINE of the ENTITIES section,
/// chained end to end into closed loops. An open chain is rejected with its end points.
/// Coordinates are scaled to mm by the HEADER's $INSUNITS (unitless: mm).
Result<Pocket> parse_pocket_dxf(std::string_view text, std::string_view source,
                                const CurveInputOptions& options = {});

/// Reads a .json, .svg or .dxf file (chosen by extension, case-insensitive).
Result<Pocket> read_pocket(const std::string& path, const CurveInputOptions& options = {});

}  // namespace swarf
