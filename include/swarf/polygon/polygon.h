// Polygon sets in the plane and the boolean operations and offsets on them.
// Clipper 6 (libpolyclipping) does the work behind this header; no other folder sees it
// (STYLE.md 2). Coordinates are mm, snapped to a fixed-point grid of 1e-5 mm.
#pragma once

#include <span>
#include <vector>

#include "swarf/core/vec.h"

namespace swarf {

/// Fixed-point resolution of every polygon operation, mm.
inline constexpr double kPolygonResolutionMm = 1e-5;

/// A closed loop of points; the closing edge from back() to front() is implied.
using Ring = std::vector<Vec2>;
/// An open chain of points.
using Polyline2 = std::vector<Vec2>;

/// A region of the plane: outer boundaries counter-clockwise, holes clockwise, no
/// self-intersections, once normalized. Operations below return normalized sets.
struct PolygonSet {
  std::vector<Ring> rings;

  bool empty() const { return rings.empty(); }
};

/// How the rings of an input that is not yet normalized define its inside.
enum class FillRule { kEvenOdd, kNonZero, kPositive };

/// Resolves self-intersections and overlaps under `rule`, orients outers CCW and holes CW,
/// removes rings smaller than the resolution.
PolygonSet normalized(const PolygonSet& set, FillRule rule = FillRule::kNonZero);

/// Each ring with the vertices Douglas-Peucker can drop while it moves by at most
/// tolerance_mm (rings that would fall under three vertices are kept whole), normalized.
/// Finely faceted curves keep about one vertex in sqrt(tolerance / sagitta per edge).
PolygonSet simplified(const PolygonSet& set, double tolerance_mm);

PolygonSet unite(const PolygonSet& a, const PolygonSet& b);
/// Union of many sets (halves first, then the two: much faster than folding unite(), and than
/// one pass when the sets overlap).
PolygonSet unite(std::span<const PolygonSet> sets);
PolygonSet subtract(const PolygonSet& a, const PolygonSet& b);
PolygonSet intersect(const PolygonSet& a, const PolygonSet& b);
/// Intersection of many sets; empty when `sets` is empty.
PolygonSet intersect(std::span<const PolygonSet> sets);

struct OffsetOptions {
  /// Largest distance between a true round join and its polygonal approximation, mm.
  double arc_tolerance_mm = 0.001;
};
/// Grows (delta > 0) or shrinks (delta < 0) the region by |delta| mm with round joins:
/// the Minkowski sum with (or difference by) a disk, up to the arc tolerance.
PolygonSet offset(const PolygonSet& set, double delta_mm, const OffsetOptions& options = {});
/// The region swept by a disk of `radius_mm` along open polylines (round ends and joins).
PolygonSet inflate_polylines(std::span<const Polyline2> lines, double radius_mm,
                             const OffsetOptions& options = {});

/// Signed area of one ring: > 0 counter-clockwise.
double signed_area(const Ring& ring);
/// Area of the region, mm^2 (outers minus holes).
double area(const PolygonSet& set);
Box2 bounds(const PolygonSet& set);
/// Total length of all ring boundaries, mm.
double perimeter(const PolygonSet& set);

/// True when p lies inside the region (boundary points count as inside).
bool contains(const PolygonSet& set, Vec2 p);
/// Distance from p to the nearest boundary edge, mm (positive inside and outside).
double distance_to_boundary(const PolygonSet& set, Vec2 p);

/// Splits a region into its connected parts, each an outer ring followed by its holes.
std::vector<PolygonSet> connected_parts(const PolygonSet& set);

}  // namespace swarf
