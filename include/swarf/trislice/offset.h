// seed 001 section 2.2: the convolutional 3D offset of a tri-slice model, Eq. (1).
//
// Slice i of a family inflated by r is the union over the slices j within r of it of slice j
// offset in 2D by sqrt(r^2 - ((i - j) ds)^2); shrunk by r it is the intersection of slice j
// offset by -sqrt(...). This equals the exact Minkowski sum (difference) of the solid held by
// the slices with a ball of radius r, cut at slice i. Where it differs from the offset of the
// true solid, because the solid between two slices is not held by the model:
//  - inflation never grows too far: it is contained in the exact offset (up to the 2D arc
//    tolerance), since every slice is part of the solid;
//  - it can fall short. A point c of the exact offset has a solid point q with |c - q| <= r.
//    If the solid's surface crosses the slice planes transversally near q, the nearest
//    slice j holds a surface point q' within h = (ds/2) / sin(theta) of q (theta: angle
//    between the surface and the slice plane), and the ball of radius r about c misses q'
//    by at most r - sqrt(r^2 - h^2) ~= h^2 / (2 r) along the normal when q is a tangent
//    contact, i.e. ds^2 / (8 r sin^2 theta). For the ball-centre height over a surface of unit
//    normal n this is ds^2 / (8 r sin^2 theta n_z). Walls parallel to the slice planes
//    (theta -> 0) and sharp vertices between slices escape this bound (first order in ds);
//    the other families of the tri-slice model see those walls transversally, which is why
//    surface_paths.h combines two families.
//  - shrinkage is the dual: it can keep up to the same amount too much.
// Tests: tests/trislice/offset_test.cpp checks the bound on a sphere and a box.
#pragma once

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/polygon/polygon.h"
#include "swarf/trislice/model.h"

namespace swarf {

struct ConvolutionOptions {
  /// 2D offsets: largest gap between a round join and its polygon, mm.
  double arc_tolerance_mm = 0.001;
  /// Use only the neighbours i +- k * stride. Eq. (1) then samples the solid every
  /// stride * ds, with the error bound above for that spacing; the cost falls by the stride.
  /// 1 (every slice) is the paper's method.
  int neighbour_stride = 1;
  /// Douglas-Peucker tolerance applied to each slice before it is offset (polygon.h
  /// simplified), mm; 0 = off (the paper's method). The result moves by at most this much more.
  /// Shrinking an inflated slice is where it pays: the inflation leaves arcs of radius rho,
  /// which the shrink by rho collapses, every edge of an arc crossing every other (quadratic
  /// in Clipper); a finely faceted curve also keeps fewer vertices. `rest` uses 1 um.
  double simplify_mm = 0.0;
};

/// Eq. (1) for one slice: the family offset by r_mm (> 0 inflates, < 0 shrinks) cut at the
/// lattice level level_index * pitch (any integer; slices outside the family are empty).
PolygonSet convolve_slice(const SliceFamily& family, long level_index, double r_mm,
                          const ConvolutionOptions& options = {});

/// convolve_slice at the `count` consecutive lattice levels from first_index on, equal to it
/// level by level, with each neighbour offset computed once for all the levels that use it
/// (slice j offset by sqrt(r^2 - (k ds)^2) serves the levels j - k and j + k: half the
/// offsets). Parallel over slices, then over levels; independent of ctx.threads. An empty
/// result when cancelled.
std::vector<PolygonSet> convolve_slices(const SliceFamily& family, long first_index,
                                        std::size_t count, double r_mm,
                                        const ConvolutionOptions& options = {},
                                        const Context& ctx = default_context());

/// Lattice index of slice j of a family (level = index * pitch).
long lattice_index(const SliceFamily& family, std::size_t j);

/// Eq. (1) for a whole family, parallel per slice. An inflation gets ceil(r / ds) more slices
/// at each end (the offset reaches beyond the solid); a shrinkage keeps the family's range.
Result<SliceFamily> offset_family(const SliceFamily& family, double r_mm,
                                  const ConvolutionOptions& options = {},
                                  const Context& ctx = default_context());

/// All three families offset by r_mm; bounds grow (shrink) by r.
Result<TriSliceModel> offset_model(const TriSliceModel& model, double r_mm,
                                   const ConvolutionOptions& options = {},
                                   const Context& ctx = default_context());

/// Eq. (1) at an arbitrary level (not necessarily on the lattice): the union of the slices
/// within r of `level` offset by sqrt(r^2 - (level - level_j)^2). Used for waterline levels.
PolygonSet inflate_at_level(const SliceFamily& family, double level, double r_mm,
                            const ConvolutionOptions& options = {});

}  // namespace swarf
