// Small exact-geometry helpers of the pocket module: ring checks, point-in-region,
// distances and arc flattening. Private to src/pocket.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "swarf/core/vec.h"
#include "swarf/polygon/polygon.h"

namespace swarf::pocket {

/// Signed area, > 0 counter-clockwise (shoelace).
double ring_area(const Ring& ring);
/// Even-odd point-in-ring test (boundary points may go either way).
bool point_in_ring(const Ring& ring, Vec2 p);
/// Even-odd over all rings: for a normalized region whose rings do not cross (outer rings,
/// each with its islands), inside an outer ring and outside all of its islands.
bool point_in_region(const PolygonSet& region, Vec2 p);
/// The point of segment ab nearest to p (a for a zero-length segment).
Vec2 nearest_on_segment(Vec2 p, Vec2 a, Vec2 b);
double point_segment_distance(Vec2 p, Vec2 a, Vec2 b);
/// Squared gap between the box [lo, hi] and the box of segment c-e (0 where they overlap):
/// no point of the segment lies nearer. The edge loops skip edges with it.
double box_gap_sq(Vec2 lo, Vec2 hi, Vec2 c, Vec2 e);
/// Least distance between segments a-b and c-e, 0 where they cross or touch.
double segment_segment_distance(Vec2 a, Vec2 b, Vec2 c, Vec2 e);
/// Distance from p to the line through a and b (to a when they coincide): the flatness
/// measure of curve flattening (chord error).
double point_line_distance(Vec2 p, Vec2 a, Vec2 b);
/// Distance from p to the nearest edge of any ring.
double distance_to_rings(const PolygonSet& region, Vec2 p);
/// Least distance from the segment a-b to any ring's edge (0 where it crosses one).
double segment_distance_to_rings(const PolygonSet& region, Vec2 a, Vec2 b);
/// The nearest point to p on any ring's edges.
Vec2 nearest_on_rings(const PolygonSet& region, Vec2 p);

/// A place where two edges cross: ring and edge indices and the point.
struct Crossing {
  std::size_t ring_a = 0, edge_a = 0, ring_b = 0, edge_b = 0;
  Vec2 point;
};
/// What touches what among the rings (non-adjacent edges that cross or touch, by a sweep
/// over x-sorted edge boxes, O(n log n + k)): the first self-crossing in the sweep's order
/// (the search stops there), else every pair of distinct rings with touching edges (ring_a <
/// ring_b, sorted).
struct RingContacts {
  std::optional<Crossing> self_crossing;
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
};
RingContacts find_ring_contacts(const std::vector<Ring>& rings);

/// Removes consecutive duplicate points (closer than eps) and a closing duplicate.
Ring cleaned_ring(const Ring& ring, double eps);

/// Points of the circular arc from angle a0 to a1 (radians, either sign of sweep) about
/// c, radius r, excluding the start point, including the end, with chord error <= tol.
void append_arc(std::vector<Vec2>& out, Vec2 c, double r, double a0, double a1, double tol);

}  // namespace swarf::pocket
