// Polygon operations for other Swarf modules that are not part of the public interface.
#pragma once

#include <polyclipping/clipper.hpp>

#include "swarf/polygon/polygon.h"

namespace swarf::detail {

/// Same result as normalized(set, FillRule::kNonZero) for rings that are usually valid
/// already (sections of a clean closed mesh): the rings are snapped and cleaned, and when
/// they are then simple, pairwise disjoint and oriented as a normalized set (counter-clockwise
/// rings bound winding 0 outside, clockwise rings winding 1 outside; checked exactly on the
/// integer grid) they are returned without a Clipper union, which costs several times more
/// than slicing itself. Anything else goes through the union.
PolygonSet normalized_nonzero_fast(const PolygonSet& set);

/// Clipper's CleanPolygon rule on one ring of grid points (see polygon.cpp), in place: the
/// same points in the same order, with less overhead. Rings left with fewer than three
/// points become empty.
void clean_path(ClipperLib::Path& path, double distance);

}  // namespace swarf::detail
