// seed 001 section 3.1: contour (waterline) paths for a ball end mill from the xy slices of
// the tri-slice model, with the mesh's sharp features that fall between slices taken exactly.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "swarf/core/parallel.h"
#include "swarf/trislice/surface_paths.h"
#include "trislice/paths_internal.h"

namespace swarf {

using trislice_detail::clearance_of;
using trislice_detail::need_ball;
using trislice_detail::new_toolpath;

PolygonSet waterline_region(const SliceFamily& xy, double tip_z, double r_mm,
                            const ConvolutionOptions& options) {
  return waterline_region(xy, tip_z, r_mm, options, {}, {});
}

PolygonSet waterline_region(const SliceFamily& xy, double tip_z, double r_mm,
                            const ConvolutionOptions& options, std::span<const PolygonSet> extra,
                            std::span<const double> extra_levels) {
  // Ball centre at tip + r. Below the centre the ball meets slice j in a disc of radius
  // sqrt(r^2 - dz^2) (Eq. (1)); above it the shank is a cylinder of radius r, so every slice
  // higher than the centre counts at full radius: no undercut is ever entered from above.
  const double zc = tip_z + r_mm;
  OffsetOptions oo;
  oo.arc_tolerance_mm = options.arc_tolerance_mm;
  std::vector<PolygonSet> parts, above;
  auto add = [&](const PolygonSet& section, double level) {
    if (section.empty()) return;
    const double dz = zc - level;
    if (dz > r_mm) return;
    if (dz > 0.0) {
      parts.push_back(offset(section, std::sqrt(r_mm * r_mm - dz * dz), oo));
    } else {
      above.push_back(section);
    }
  };
  for (std::size_t j = 0; j < xy.size(); ++j)
    add(xy.slices[j], xy.level(j));
  for (std::size_t k = 0; k < extra.size() && k < extra_levels.size(); ++k)
    add(extra[k], extra_levels[k]);
  if (!above.empty()) parts.push_back(offset(unite(std::span<const PolygonSet>(above)), r_mm, oo));
  return unite(std::span<const PolygonSet>(parts));
}

namespace {

// What of a mesh no slice between two levels is sure to see, for waterlines:
//  - heights of its horizontal edges whose faces meet at more than kSharpDeg (the top of a
//    step, a flat ridge) and of its sharp peaks (a vertex at least as high as the other
//    corners of every triangle round it, one of them steeper than kSharpDeg): sliced
//    exactly. Smooth ones (the rings of a revolved surface, the top of a dome) are left to
//    the slices: there the error is second-order, and slicing them too cost 75 % more time
//    on the torus part. Sorted, without repeats (1e-7 mm); kept also where a lattice level
//    falls on one, since the slicer counts a vertex on the plane as above it and that
//    level's section has no trace of a peak there;
//  - points along its sharp edges that rise so slowly that the slices cross them more than
//    kEdgeStep apart (the top edge of a sloping side): the ball keeps its radius from each,
//    so between two points it can come closer by at most kEdgeStep^2 / (8 rho), about 1 um.
struct CriticalFeatures {
  std::vector<double> heights;
  std::vector<Vec3> edge_points;  ///< sorted by z
};

CriticalFeatures critical_features(const Mesh& mesh, double pitch_mm) {
  constexpr double kSharpDeg = 20.0, kEdgeStep = 0.1;
  const double cos_sharp = std::cos(deg_to_rad(kSharpDeg));
  std::vector<Vec3> normal(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 n =
        cross(mesh.corner(t, 1) - mesh.corner(t, 0), mesh.corner(t, 2) - mesh.corner(t, 0));
    const double len = norm(n);
    normal[t] = len > 0.0 ? n / len : Vec3{0, 0, 1};
  }
  std::vector<char> peak(mesh.vertices.size(), 1), steep(mesh.vertices.size(), 0);
  struct Edge {
    std::uint32_t a, b;
    std::size_t tri;
  };
  std::vector<Edge> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t ia = tri[k], ib = tri[(k + 1) % 3], ic = tri[(k + 2) % 3];
      const double za = mesh.vertices[ia].z;
      if (za < mesh.vertices[ib].z || za < mesh.vertices[ic].z) peak[ia] = 0;
      if (normal[t].z < cos_sharp) steep[ia] = 1;
      edges.push_back({std::min(ia, ib), std::max(ia, ib), t});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
    return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.tri < y.tri);
  });
  CriticalFeatures out;
  std::vector<double> h;
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    bool sharp = false;
    while (j < edges.size() && edges[j].a == edges[i].a && edges[j].b == edges[i].b) {
      if (dot(normal[edges[j].tri], normal[edges[i].tri]) < cos_sharp) sharp = true;
      ++j;
    }
    sharp = sharp || j - i == 1;  // or an open edge
    const Vec3 a = mesh.vertices[edges[i].a], b = mesh.vertices[edges[i].b];
    i = j;
    if (!sharp) continue;
    const double dz = std::abs(b.z - a.z), len = norm(b - a);
    if (dz == 0.0) {
      h.push_back(a.z);
    } else if (pitch_mm * len > kEdgeStep * dz) {
      // The ends too: a corner of two such edges (a crest along a sloping side) is the
      // highest point round it without being a peak of the mesh.
      const int n = std::max(1, static_cast<int>(std::ceil(len / kEdgeStep)));
      for (int k = 0; k <= n; ++k)
        out.edge_points.push_back(a + (b - a) * (static_cast<double>(k) / n));
    }
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
    if (peak[v] != 0 && steep[v] != 0) h.push_back(mesh.vertices[v].z);
  std::sort(h.begin(), h.end());
  for (double z : h)
    if (out.heights.empty() || z - out.heights.back() >= 1e-7) out.heights.push_back(z);
  std::sort(out.edge_points.begin(), out.edge_points.end(), [](const Vec3& p, const Vec3& q) {
    return p.z != q.z ? p.z < q.z : (p.x != q.x ? p.x < q.x : p.y < q.y);
  });
  out.edge_points.erase(std::unique(out.edge_points.begin(), out.edge_points.end(),
                                    [](const Vec3& p, const Vec3& q) {
                                      return p.x == q.x && p.y == q.y && p.z == q.z;
                                    }),
                        out.edge_points.end());
  return out;
}

// Disc of radius `radius` round c, as a polygon whose edges stay outside the circle (the
// region it joins is where the tool may not go), within `tol` of it.
Ring outer_disc(Vec2 c, double radius, double tol) {
  const double t = std::clamp(tol / std::max(radius, 1e-9), 1e-9, 1.0);
  const int n = std::max(8, static_cast<int>(std::ceil(kPi / std::acos(1.0 - t))));
  const double rr = radius / std::cos(kPi / n);
  Ring ring;
  ring.reserve(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * kPi * k / n;
    ring.push_back({c.x + rr * std::cos(a), c.y + rr * std::sin(a)});
  }
  return ring;
}

}  // namespace

Result<Toolpath> contour_paths(const TriSliceModel& model, const Tool& tool, const ContourParams& p,
                               const Context& ctx) {
  SWARF_RETURN_IF_ERROR(need_ball(tool));
  SWARF_RETURN_IF_ERROR(validate(p));
  const SliceFamily& xy = model.family(Axis::kZ);
  const double top_z = std::isfinite(p.top_z_mm) ? p.top_z_mm : model.bounds.max.z - p.stepdown_mm;
  const double bottom_z = std::isfinite(p.bottom_z_mm) ? p.bottom_z_mm : model.bounds.min.z;
  std::vector<double> levels;
  for (double z = top_z; z >= bottom_z - 1e-9; z -= p.stepdown_mm)
    levels.push_back(z);
  if (levels.empty())
    return Status{Error::kEmptyResult, "contour: no level between top and bottom"};
  const double R = tool.radius() + p.stock_to_leave_mm;
  ConvolutionOptions co;
  co.arc_tolerance_mm = p.arc_tolerance_mm;
  // Sections at the mesh's critical heights, taken 0.1 um below each (the solid under a
  // horizontal face or a peak), so that features between two levels count exactly. Closer
  // than that, the section round a peak is smaller than the polygon resolution and vanishes.
  std::vector<double> crit;
  std::vector<PolygonSet> crit_sections;
  CriticalFeatures features;
  if (p.critical_mesh != nullptr) {
    features = critical_features(*p.critical_mesh, xy.pitch_mm);
    crit.resize(features.heights.size());
    for (std::size_t k = 0; k < crit.size(); ++k)
      crit[k] = features.heights[k] - 1e-4;
    crit_sections = slice_mesh(*p.critical_mesh, Axis::kZ, crit, {}, ctx);
  }
  std::vector<std::vector<Ring>> rings(levels.size());
  parallel_for(levels.size(), ctx.threads, [&](std::size_t i) {
    if (ctx.cancelled()) return;
    // The tool centre is at tip + r; with stock to leave it keeps r + stock from the part.
    PolygonSet region =
        waterline_region(xy, levels[i] + tool.radius() - R, R, co, crit_sections, crit);
    // Points along slowly rising sharp edges: below the centre the ball's section there,
    // above it the shank (within a pitch: higher ones are inside the slices above).
    const double zc = levels[i] + tool.radius();
    const auto lo = std::lower_bound(features.edge_points.begin(), features.edge_points.end(),
                                     zc - R, [](const Vec3& q, double z) { return q.z < z; });
    PolygonSet discs;
    for (auto it = lo; it != features.edge_points.end() && it->z <= zc + xy.pitch_mm; ++it) {
      const double dz = std::max(0.0, zc - it->z);
      if (dz >= R) continue;
      discs.rings.push_back(outer_disc(it->xy(), std::sqrt(R * R - dz * dz), p.arc_tolerance_mm));
    }
    if (!discs.empty()) {
      const PolygonSet both[2] = {region, discs};
      region = unite(std::span<const PolygonSet>(both, 2));
    }

    OffsetOptions oo;
    oo.arc_tolerance_mm = p.arc_tolerance_mm;
    for (int k = p.radial_passes - 1; k >= 0; --k) {
      const PolygonSet ring_set = k == 0 ? region : offset(region, k * p.radial_step_mm, oo);
      for (const Ring& r : ring_set.rings)
        rings[i].push_back(r);
    }
  });
  if (ctx.cancelled()) return Status{Error::kCancelled, "contour: cancelled"};
  Toolpath tp =
      new_toolpath(tool, "tri-slice contour",
                   clearance_of(p.clearance_z_mm, model, -std::numeric_limits<double>::infinity()));
  for (std::size_t i = 0; i < levels.size(); ++i) {
    for (const Ring& r : rings[i]) {
      if (r.size() < 3) continue;
      tp.rapid_to({r.front().x, r.front().y, tp.clearance_z_mm});
      tp.plunge_to(levels[i], p.plunge_feed_mm_min);
      for (std::size_t k = 1; k <= r.size(); ++k) {
        const Vec2 q = r[k % r.size()];
        tp.feed_to({q.x, q.y, levels[i]}, p.feed_mm_min);
      }
      tp.retract();
    }
  }
  if (tp.empty()) return Status{Error::kEmptyResult, "contour: no ring at any level"};
  return tp;
}

}  // namespace swarf
