// seed 001 section 3.2: unmachinable regions by inflation, shrinkage and subtraction.
#include "swarf/trislice/rest.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "swarf/core/parallel.h"

namespace swarf {

Status validate(const RestOptions& o) {
  if (!(o.tool_radius_mm > 0.0)) return bad_parameter("rest: tool radius must be positive");
  if (!(o.min_thickness_mm >= 0.0)) return bad_parameter("rest: min thickness must be >= 0");
  if (!(o.convolution_tolerance_mm >= 0.0)) return bad_parameter("rest: negative tolerance");
  if (!(o.convolution.simplify_mm >= 0.0) || !std::isfinite(o.convolution.simplify_mm))
    return bad_parameter("rest: slice simplification must be >= 0 mm");
  if (!(o.convolution.arc_tolerance_mm > 0.0))
    return bad_parameter("rest: arc tolerance must be positive");
  return {};
}

Result<RestRegions> unmachinable_regions(const TriSliceModel& model, const RestOptions& o,
                                         const Context& ctx) {
  SWARF_RETURN_IF_ERROR(validate(o));
  RestRegions out;
  out.pitch_mm = model.pitch_mm;
  out.bounds = model.bounds;
  // The xy family first: a point is residue only where all the families analysed agree
  // (thickness_map), so the x family is needed only over the xy family's residue (its bounds
  // plus a pitch, for the map's nearest-slice reading) and the y family only over where both
  // hold some; elsewhere their answer cannot change the map or the points. The Kiri:Moto
  // pocket part takes half the time. On the torus part the xy family's own film along the
  // outer flank spans the part, so the x family is analysed whole, but its residue stays
  // within |y| < 25.1 mm (the inner fillet, and the flank where its planes graze it): the y
  // family reads 499 of its 801 slices at 0.1 mm (14.6 -> 11.6 s with both cores).
  Box3 limit = o.region;
  bool nothing_left = false;
  for (int a : {2, 0, 1}) {
    const SliceFamily& fam = model.families[static_cast<std::size_t>(a)];
    SliceFamily& res = out.families[static_cast<std::size_t>(a)];
    res.axis = fam.axis;
    res.pitch_mm = fam.pitch_mm;
    res.first_level = fam.first_level;
    if (!o.families[static_cast<std::size_t>(a)] || fam.size() == 0 || nothing_left) continue;
    // Analysed slices [j0, j1]; the inflation is needed within r of them.
    long j0 = 0, j1 = static_cast<long>(fam.size()) - 1;
    if (!limit.empty()) {
      j0 = std::max(
          j0, static_cast<long>(std::ceil((limit.min[a] - fam.first_level) / fam.pitch_mm - 1e-9)));
      j1 = std::min(j1, static_cast<long>(
                            std::floor((limit.max[a] - fam.first_level) / fam.pitch_mm + 1e-9)));
    }
    if (j0 > j1) continue;
    const long nr = static_cast<long>(std::ceil(o.tool_radius_mm / fam.pitch_mm - 1e-9));
    ConvolutionOptions conv = o.convolution;
    if (o.convolution_tolerance_mm > 0.0)
      conv.neighbour_stride = std::max(
          1, static_cast<int>(std::floor(
                 std::sqrt(8.0 * o.tool_radius_mm * o.convolution_tolerance_mm) / fam.pitch_mm +
                 1e-9)));
    const long base = lattice_index(fam, 0);
    SliceFamily inflated;
    inflated.axis = fam.axis;
    inflated.pitch_mm = fam.pitch_mm;
    inflated.first_level = static_cast<double>(base + j0 - nr) * fam.pitch_mm;
    // Eq. (1) level by level (convolve_slices: each neighbour offset once for both levels
    // that use it, the same result as convolve_slice per level).
    inflated.slices =
        convolve_slices(fam, base + j0 - nr, static_cast<std::size_t>(j1 - j0 + 1 + 2 * nr),
                        o.tool_radius_mm, conv, ctx);
    if (ctx.cancelled()) return Status{Error::kCancelled, "rest: cancelled"};
    res.first_level = fam.level(static_cast<std::size_t>(j0));
    // Shrink the inflated family back at the analysed slices' own levels.
    std::vector<PolygonSet> closed =
        convolve_slices(inflated, lattice_index(fam, static_cast<std::size_t>(j0)),
                        static_cast<std::size_t>(j1 - j0 + 1), -o.tool_radius_mm, conv, ctx);
    if (ctx.cancelled()) return Status{Error::kCancelled, "rest: cancelled"};
    res.slices.resize(static_cast<std::size_t>(j1 - j0 + 1));
    parallel_for(res.slices.size(), ctx.threads, [&](std::size_t k) {
      if (ctx.cancelled()) return;
      const std::size_t j = static_cast<std::size_t>(j0) + k;
      // Subtract the part.
      PolygonSet residue = subtract(closed[k], fam.slices[j]);
      // Drop slivers thinner than min_thickness (an opening by half of it): the closing of a
      // concave arc of exactly the tool radius leaves micrometre films along the arc, which a
      // vertical thickness would count in full where the arc is steep.
      if (o.min_thickness_mm > 0.0 && !residue.empty()) {
        OffsetOptions oo;
        oo.arc_tolerance_mm = conv.arc_tolerance_mm;
        residue =
            offset(offset(residue, -0.5 * o.min_thickness_mm, oo), 0.5 * o.min_thickness_mm, oo);
      }
      res.slices[k] = std::move(residue);
    });
    if (ctx.cancelled()) return Status{Error::kCancelled, "rest: cancelled"};
    ctx.report("unmachinable regions", a == 2 ? 1.0 / 3.0 : (a + 2) / 3.0);
    if ((a == 2 || a == 0) && o.prune_by_xy_residue) {
      // The xy footprint of this family's residue: the xy family's bounds, or for the x family
      // (slices in (y, z)) each slice's level x with the y extent of its residue. The next
      // families are analysed only over it (plus a pitch, for the map's nearest-slice reading):
      // the y family only where the xy and x families both hold some.
      Box2 xy;
      for (std::size_t k = 0; k < res.slices.size(); ++k) {
        if (res.slices[k].empty()) continue;
        const Box2 b = bounds(res.slices[k]);
        if (a == 2) {
          xy.merge(b);
        } else {
          xy.add(Vec2{res.level(k), b.min.x});
          xy.add(Vec2{res.level(k), b.max.x});
        }
      }
      const double m = fam.pitch_mm, inf = std::numeric_limits<double>::infinity();
      Box3 agreed{{xy.min.x - m, xy.min.y - m, -inf}, {xy.max.x + m, xy.max.y + m, inf}};
      if (!xy.empty() && !limit.empty()) {
        agreed.min = {std::max(agreed.min.x, limit.min.x), std::max(agreed.min.y, limit.min.y),
                      limit.min.z};
        agreed.max = {std::min(agreed.max.x, limit.max.x), std::min(agreed.max.y, limit.max.y),
                      limit.max.z};
      }
      limit = agreed;
      nothing_left = xy.empty() || limit.empty();  // no residue here: none agreed anywhere
    }
  }
  return out;
}

namespace {

// Residue intervals [z0, z1] of one vertical-family slice along the vertical line at in-plane
// position s (x for the y family, y for the x family), sorted and disjoint.
void residue_intervals(const SliceFamily& family, std::size_t j, double s,
                       std::vector<double>& zs) {
  // Vertical line at in-plane position s: v = s for the y family ((u, v) = (z, x)), u = s for
  // the x family ((u, v) = (y, z)). Crossings sorted; normalized rings alternate in and out.
  zs.clear();
  const bool fam_y = family.axis == Axis::kY;
  for (const Ring& ring : family.slices[j].rings) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
      const double sa = fam_y ? a.y : a.x, sb = fam_y ? b.y : b.x;
      const double za = fam_y ? a.x : a.y, zb = fam_y ? b.x : b.y;
      if ((sa <= s) == (sb <= s)) continue;  // half-open: each crossing counted once
      zs.push_back(za + (s - sa) / (sb - sa) * (zb - za));
    }
  }
  std::sort(zs.begin(), zs.end());
  if (zs.size() % 2 != 0) zs.pop_back();
}

// Intersection of two sorted lists of disjoint intervals (flattened pairs), in place in `a`.
void intersect_intervals(std::vector<double>& a, const std::vector<double>& b,
                         std::vector<double>& scratch) {
  scratch.clear();
  std::size_t i = 0, k = 0;
  while (i + 1 < a.size() && k + 1 < b.size()) {
    const double lo = std::max(a[i], b[k]), hi = std::min(a[i + 1], b[k + 1]);
    if (lo < hi) {
      scratch.push_back(lo);
      scratch.push_back(hi);
    }
    if (a[i + 1] < b[k + 1]) {
      i += 2;
    } else {
      k += 2;
    }
  }
  a.swap(scratch);
}

// Union of a list of intervals (flattened pairs, any order), sorted and disjoint.
void merge_intervals(std::vector<double>& a) {
  std::vector<std::pair<double, double>> iv;
  for (std::size_t i = 0; i + 1 < a.size(); i += 2)
    iv.emplace_back(a[i], a[i + 1]);
  std::sort(iv.begin(), iv.end());
  a.clear();
  for (const auto& [lo, hi] : iv) {
    if (!a.empty() && lo <= a.back()) {
      a.back() = std::max(a.back(), hi);
    } else {
      a.push_back(lo);
      a.push_back(hi);
    }
  }
}

double total_length(const std::vector<double>& a) {
  double t = 0.0;
  for (std::size_t i = 0; i + 1 < a.size(); i += 2)
    t += a[i + 1] - a[i];
  return t;
}

}  // namespace

double residue_thickness(const SliceFamily& family, std::size_t j, double s) {
  std::vector<double> zs;
  residue_intervals(family, j, s, zs);
  return total_length(zs);
}

double ThicknessMap::at(Vec2 p) const {
  const int i = static_cast<int>(std::floor((p.x - origin.x) / cell_mm));
  const int j = static_cast<int>(std::floor((p.y - origin.y) / cell_mm));
  if (i < 0 || j < 0 || i >= nx || j >= ny) return 0.0;
  return mm[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) +
            static_cast<std::size_t>(i)];
}

double ThicknessMap::max() const {
  double m = 0.0;
  for (double v : mm)
    m = std::max(m, v);
  return m;
}

namespace {

// The map's grid, and per cell the heights at which every family analysed holds residue on
// the cell's vertical line: sorted, disjoint intervals (flattened pairs).
struct AgreedResidue {
  ThicknessMap grid;  ///< geometry only (mm empty)
  std::vector<std::vector<double>> z;
};

AgreedResidue agreed_residue(const RestRegions& rest, double cell_mm) {
  AgreedResidue out;
  ThicknessMap& map = out.grid;
  map.cell_mm = cell_mm > 0.0 ? cell_mm : rest.pitch_mm;
  const Box2 b = rest.bounds.xy();
  map.origin = b.min;
  map.nx = std::max(1, static_cast<int>(std::ceil(b.size().x / map.cell_mm)));
  map.ny = std::max(1, static_cast<int>(std::ceil(b.size().y / map.cell_mm)));
  const std::size_t ncell = static_cast<std::size_t>(map.nx) * static_cast<std::size_t>(map.ny);

  // Per family and cell: the residue's z intervals on the cell's vertical line (the union
  // over the family's slices crossing the cell), and whether any slice of it crosses the cell.
  struct Family {
    std::vector<std::vector<double>> z;
    std::vector<bool> covers;
  };
  std::vector<Family> fams;
  // Each cell reads a vertical family at its slice nearest to the cell's centre line (when
  // that slice is within half a cell or half a pitch of it). Assigning slices to cells by
  // flooring their levels instead put two slices in some cells and none in their neighbours
  // (the levels sit on the cell edges, up to rounding), and the uncovered columns showed the
  // other families' false residues as stripes (the torus part at 0.1 mm, outer fillet).
  for (Axis a : {Axis::kX, Axis::kY}) {
    const SliceFamily& f = rest.families[static_cast<std::size_t>(a)];
    if (f.size() == 0) continue;
    Family own{std::vector<std::vector<double>>(ncell), std::vector<bool>(ncell, false)};
    const bool fam_y = a == Axis::kY;
    const int n_across = fam_y ? map.ny : map.nx, n_along = fam_y ? map.nx : map.ny;
    const double reach = 0.5 * std::max(f.pitch_mm, map.cell_mm) + 1e-9;
    for (int c = 0; c < n_across; ++c) {
      const double centre = (fam_y ? map.origin.y : map.origin.x) + (c + 0.5) * map.cell_mm;
      // On the model's lattice (not relative to the first analysed slice), so that a centre
      // half-way between two slices picks the same one whatever range was analysed.
      const long j = std::lround(centre / f.pitch_mm) - lattice_index(f, 0);
      if (j < 0 || j >= static_cast<long>(f.size())) continue;
      const auto ju = static_cast<std::size_t>(j);
      if (std::abs(f.level(ju) - centre) > reach) continue;
      for (int k = 0; k < n_along; ++k) {
        const double s = (fam_y ? map.origin.x : map.origin.y) + (k + 0.5) * map.cell_mm;
        const std::size_t cu = fam_y ? static_cast<std::size_t>(c) * map.nx + k
                                     : static_cast<std::size_t>(k) * map.nx + c;
        own.covers[cu] = true;
        if (f.slices[ju].empty()) continue;
        residue_intervals(f, ju, s, own.z[cu]);
      }
    }
    fams.push_back(std::move(own));
  }
  // The xy family: each level whose residue covers the cell centre adds the pitch's slab
  // round that level. It covers every cell.
  const SliceFamily& fz = rest.families[static_cast<std::size_t>(Axis::kZ)];
  if (fz.size() > 0) {
    Family own{std::vector<std::vector<double>>(ncell), std::vector<bool>(ncell, true)};
    std::vector<double> xs;
    for (std::size_t l = 0; l < fz.size(); ++l) {
      if (fz.slices[l].empty()) continue;
      const double z0 = fz.level(l) - 0.5 * fz.pitch_mm, z1 = fz.level(l) + 0.5 * fz.pitch_mm;
      const Box2 pb = bounds(fz.slices[l]);
      const int j0 =
          std::max(0, static_cast<int>(std::floor((pb.min.y - map.origin.y) / map.cell_mm)));
      const int j1 = std::min(
          map.ny - 1, static_cast<int>(std::floor((pb.max.y - map.origin.y) / map.cell_mm)));
      for (int j = j0; j <= j1; ++j) {
        const double y = map.origin.y + (j + 0.5) * map.cell_mm;
        xs.clear();
        for (const Ring& ring : fz.slices[l].rings)
          for (std::size_t k = 0; k < ring.size(); ++k) {
            const Vec2 p0 = ring[k], p1 = ring[(k + 1) % ring.size()];
            if ((p0.y <= y) == (p1.y <= y)) continue;
            xs.push_back(p0.x + (y - p0.y) / (p1.y - p0.y) * (p1.x - p0.x));
          }
        std::sort(xs.begin(), xs.end());
        for (std::size_t k = 0; k + 1 < xs.size(); k += 2) {
          const int i0 =
              std::max(0, static_cast<int>(std::ceil((xs[k] - map.origin.x) / map.cell_mm - 0.5)));
          const int i1 = std::min(
              map.nx - 1,
              static_cast<int>(std::floor((xs[k + 1] - map.origin.x) / map.cell_mm - 0.5)));
          for (int i = i0; i <= i1; ++i) {
            auto& cz = own.z[static_cast<std::size_t>(j) * static_cast<std::size_t>(map.nx) +
                             static_cast<std::size_t>(i)];
            cz.push_back(z0);
            cz.push_back(z1);
          }
        }
      }
    }
    fams.push_back(std::move(own));
  }
  // A point is residue only where every family that sees it agrees (superposition, section
  // 2.1): the z intervals are intersected, not the families' thicknesses compared. Each
  // family's false residues (walls nearly parallel to its planes, offset.h) sit at heights
  // the others do not share; the minimum of the thicknesses kept them wherever the other
  // families had residue of their own at other heights on the same vertical line.
  out.z.resize(ncell);
  std::vector<double> scratch;
  for (std::size_t c = 0; c < ncell; ++c) {
    bool any = false;
    std::vector<double>& acc = out.z[c];
    for (Family& f : fams) {
      if (!f.covers[c]) continue;
      merge_intervals(f.z[c]);
      if (!any) {
        acc = f.z[c];
        any = true;
      } else {
        intersect_intervals(acc, f.z[c], scratch);
      }
      if (acc.empty()) break;
    }
  }
  return out;
}

}  // namespace

ThicknessMap thickness_map(const RestRegions& rest, double cell_mm) {
  AgreedResidue agreed = agreed_residue(rest, cell_mm);
  ThicknessMap map = std::move(agreed.grid);
  map.mm.resize(agreed.z.size());
  for (std::size_t c = 0; c < agreed.z.size(); ++c)
    map.mm[c] = total_length(agreed.z[c]);
  return map;
}

Image thickness_image(const ThicknessMap& map, double min_mm) {
  Image img(map.nx, map.ny);
  const double top = std::max(map.max(), 1e-9);
  for (int j = 0; j < map.ny; ++j)
    for (int i = 0; i < map.nx; ++i) {
      const double t = map.mm[static_cast<std::size_t>(j) * static_cast<std::size_t>(map.nx) +
                              static_cast<std::size_t>(i)];
      if (t >= min_mm && t > 0.0) img.at(i, map.ny - 1 - j) = heat_color(t / top);
    }
  return img;
}

std::string residue_points_ply(const RestRegions& rest, double spacing_mm) {
  // The agreed residue (as the map): each family alone also holds the false residue of its
  // planes (a film along the whole outer fillet of the torus part, for one), which a viewer
  // would show as unmachinable.
  std::vector<Vec3> pts;
  const double h = spacing_mm > 0.0 ? spacing_mm : rest.pitch_mm;
  const AgreedResidue agreed = agreed_residue(rest, h);
  const ThicknessMap& g = agreed.grid;
  for (int j = 0; j < g.ny; ++j) {
    for (int i = 0; i < g.nx; ++i) {
      const auto& z = agreed.z[static_cast<std::size_t>(j) * static_cast<std::size_t>(g.nx) +
                               static_cast<std::size_t>(i)];
      const double x = g.origin.x + (i + 0.5) * h, y = g.origin.y + (j + 0.5) * h;
      for (std::size_t k = 0; k + 1 < z.size(); k += 2) {
        for (double v = std::ceil(z[k] / h) * h; v <= z[k + 1]; v += h)
          pts.push_back({x, y, v});
      }
    }
  }
  std::ostringstream os;
  os << "ply\nformat ascii 1.0\ncomment swarf unmachinable regions (seed 001 section 3.2)\n"
     << "element vertex " << pts.size()
     << "\nproperty float x\nproperty float y\nproperty float z\n"
     << "end_header\n";
  os.precision(6);
  for (const Vec3& p : pts)
    os << p.x << ' ' << p.y << ' ' << p.z << '\n';
  return os.str();
}

}  // namespace swarf
