// seed 001 section 3.2: unmachinable regions by inflation, shrinkage and subtraction.
#include "swarf/trislice/rest.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "swarf/core/parallel.h"

namespace swarf {

Status validate(const RestOptions& o) {
  if (!(o.tool_radius_mm > 0.0)) return bad_parameter("rest: tool radius must be positive");
  if (!(o.min_thickness_mm >= 0.0)) return bad_parameter("rest: min thickness must be >= 0");
  if (!(o.convolution_tolerance_mm >= 0.0)) return bad_parameter("rest: negative tolerance");
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
  for (int a = 0; a < 3; ++a) {
    const SliceFamily& fam = model.families[static_cast<std::size_t>(a)];
    SliceFamily& res = out.families[static_cast<std::size_t>(a)];
    res.axis = fam.axis;
    res.pitch_mm = fam.pitch_mm;
    res.first_level = fam.first_level;
    if (!o.families[static_cast<std::size_t>(a)] || fam.size() == 0) continue;
    // Analysed slices [j0, j1]; the inflation is needed within r of them.
    long j0 = 0, j1 = static_cast<long>(fam.size()) - 1;
    if (!o.region.empty()) {
      j0 = std::max(j0, static_cast<long>(
                            std::ceil((o.region.min[a] - fam.first_level) / fam.pitch_mm - 1e-9)));
      j1 = std::min(j1, static_cast<long>(
                            std::floor((o.region.max[a] - fam.first_level) / fam.pitch_mm + 1e-9)));
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
    ctx.report("unmachinable regions", (a + 1) / 3.0);
  }
  return out;
}

double residue_thickness(const SliceFamily& family, std::size_t j, double s) {
  // Vertical line at in-plane position s: v = s for the y family ((u, v) = (z, x)), u = s for
  // the x family ((u, v) = (y, z)). Crossings sorted; normalized rings alternate in and out.
  std::vector<double> zs;
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
  double t = 0.0;
  for (std::size_t k = 0; k + 1 < zs.size(); k += 2)
    t += zs[k + 1] - zs[k];
  return t;
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

ThicknessMap thickness_map(const RestRegions& rest, double cell_mm) {
  ThicknessMap map;
  map.cell_mm = cell_mm > 0.0 ? cell_mm : rest.pitch_mm;
  const Box2 b = rest.bounds.xy();
  map.origin = b.min;
  map.nx = std::max(1, static_cast<int>(std::ceil(b.size().x / map.cell_mm)));
  map.ny = std::max(1, static_cast<int>(std::ceil(b.size().y / map.cell_mm)));
  const std::size_t ncell = static_cast<std::size_t>(map.nx) * static_cast<std::size_t>(map.ny);
  const double kUncovered = -1.0;
  map.mm.assign(ncell, kUncovered);
  auto cell_of = [&](double x, double y) -> long {
    const int i = static_cast<int>(std::floor((x - map.origin.x) / map.cell_mm));
    const int j = static_cast<int>(std::floor((y - map.origin.y) / map.cell_mm));
    if (i < 0 || j < 0 || i >= map.nx || j >= map.ny) return -1;
    return static_cast<long>(j) * map.nx + i;
  };
  for (Axis a : {Axis::kX, Axis::kY}) {
    const SliceFamily& f = rest.families[static_cast<std::size_t>(a)];
    if (f.size() == 0) continue;
    // This family's own map: 0 on the rows (columns) its slices cross, the largest thickness
    // found in a cell; uncovered elsewhere.
    std::vector<double> own(ncell, kUncovered);
    for (std::size_t j = 0; j < f.size(); ++j) {
      const double level = f.level(j);
      const int n_along = a == Axis::kY ? map.nx : map.ny;
      for (int k = 0; k < n_along; ++k) {
        const double s = (a == Axis::kY ? map.origin.x : map.origin.y) + (k + 0.5) * map.cell_mm;
        const long c = a == Axis::kY ? cell_of(s, level) : cell_of(level, s);
        if (c < 0) continue;
        const double t = f.slices[j].empty() ? 0.0 : residue_thickness(f, j, s);
        own[static_cast<std::size_t>(c)] = std::max(own[static_cast<std::size_t>(c)], t);
      }
    }
    for (std::size_t c = 0; c < ncell; ++c) {
      if (own[c] < 0.0) continue;
      map.mm[c] = map.mm[c] < 0.0 ? own[c] : std::min(map.mm[c], own[c]);
    }
  }
  // The xy family: the residue's vertical extent is the number of levels whose residue covers
  // the cell centre, times the pitch. It covers every cell, so it votes everywhere.
  const SliceFamily& fz = rest.families[static_cast<std::size_t>(Axis::kZ)];
  if (fz.size() > 0) {
    std::vector<double> own(ncell, 0.0);
    std::vector<double> xs;
    for (std::size_t l = 0; l < fz.size(); ++l) {
      if (fz.slices[l].empty()) continue;
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
          for (int i = i0; i <= i1; ++i)
            own[static_cast<std::size_t>(j) * static_cast<std::size_t>(map.nx) +
                static_cast<std::size_t>(i)] += fz.pitch_mm;
        }
      }
    }
    for (std::size_t c = 0; c < ncell; ++c)
      map.mm[c] = map.mm[c] < 0.0 ? own[c] : std::min(map.mm[c], own[c]);
  }
  for (double& v : map.mm)
    v = std::max(v, 0.0);
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
  std::vector<Vec3> pts;
  const double h = spacing_mm > 0.0 ? spacing_mm : rest.pitch_mm;
  std::vector<double> us;
  for (const SliceFamily& f : rest.families) {
    for (std::size_t j = 0; j < f.size(); ++j) {
      if (f.slices[j].empty()) continue;
      // Scanline fill of the residue in its plane: rows v = k h, crossings sorted in u.
      const Box2 b = bounds(f.slices[j]);
      for (double v = std::ceil(b.min.y / h) * h; v <= b.max.y; v += h) {
        us.clear();
        for (const Ring& ring : f.slices[j].rings)
          for (std::size_t k = 0; k < ring.size(); ++k) {
            const Vec2 p0 = ring[k], p1 = ring[(k + 1) % ring.size()];
            if ((p0.y <= v) == (p1.y <= v)) continue;
            us.push_back(p0.x + (v - p0.y) / (p1.y - p0.y) * (p1.x - p0.x));
          }
        std::sort(us.begin(), us.end());
        for (std::size_t k = 0; k + 1 < us.size(); k += 2)
          for (double u = std::ceil(us[k] / h) * h; u <= us[k + 1]; u += h)
            pts.push_back(from_plane({u, v}, f.level(j), f.axis));
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
