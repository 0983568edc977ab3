// A 2.5D pocket: an outer boundary minus islands, read from JSON, SVG or DXF (mm).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "swarf/core/status.h"
#include "swarf/polygon/polygon.h"

namespace swarf {

/// The region to clear. `region` is normalized: the outer ring counter-clockwise first,
/// then the islands clockwise; no ring intersects itself or another, every island lies
/// strictly inside the outer ring and outside every other island.
struct Pocket {
  PolygonSet region;
  /// Where it came from (file name), for messages.
  std::string source;

  const Ring& outer() const { return region.rings.front(); }
  /// Islands are region.rings[1..].
  std::size_t island_count() const { return region.rings.empty() ? 0 : region.rings.size() - 1; }
};

/// Checks and orients an outer ring and its islands. kBadInput names `source` and the place
/// (ring, edge, point) of a self-intersection, a crossing between rings, an island outside
/// the outer ring, a ring with fewer than 3 points or no area, or a non-finite coordinate.
Result<Pocket> make_pocket(Ring outer, std::vector<Ring> islands, std::string_view source);

/// {"outer": [[x,y],...], "islands": [[[x,y],...],...]} in mm; "islands" may be absent.
Result<Pocket> parse_pocket_json(std::string_view text, std::string_view source);

struct CurveInputOptions {
  /// Largest distance between an arc and the chords that replace it, mm.
  double arc_tolerance_mm = 0.01;
  /// Endpoints closer than this are joined when chaining DXF entities into loops, mm.
  double join_tolerance_mm = 1e-3;
};

/// SVG <polygon>, <polyline> (must close on itself), <rect>, <circle> and <path> with
/// M L H V Z and elliptical arcs A (absolute and relative; C/Q/S/T curves are rejected).
/// User units are taken as mm; the y axis is flipped so that the drawing keeps its look.
/// The loop with the largest area is the outer boundary, the others islands.
Result<Pocket> parse_pocket_svg(std::string_view text, std::string_view source,
                                const CurveInputOptions& options = {});

/// ASCII DXF: LWPOLYLINE (with bulges), LINE, ARC and CIRCLE of the ENTITIES section,
/// chained end to end into closed loops. An open chain is rejected with its end points.
/// Coordinates are scaled to mm by the HEADER's $INSUNITS (unitless: mm).
Result<Pocket> parse_pocket_dxf(std::string_view text, std::string_view source,
                                const CurveInputOptions& options = {});

/// Reads a .json, .svg or .dxf file (chosen by extension, case-insensitive).
Result<Pocket> read_pocket(const std::string& path, const CurveInputOptions& options = {});

}  // namespace swarf
