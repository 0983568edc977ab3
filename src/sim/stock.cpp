// seed 001 section 3.3 (Fig. 8, 9): the tri-slice stock, its point queries and the
// subtraction of the tool's swept cross-sections.
#include "swarf/sim/stock.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <string>

#include "sim/sections.h"
#include "swarf/core/parallel.h"
#include "swarf/mesh/slice.h"
#include "swarf/mesh/stl.h"
#include "swarf/polygon/polygon.h"

namespace swarf::sim {

double ToolSolid::width_at(double h) const {
  if (h < 0.0) return 0.0;
  const double rc = corner_radius_mm;
  if (rc <= 0.0 || h >= rc) return radius_mm;
  const double dz = rc - h;
  return radius_mm - rc + std::sqrt(std::max(0.0, rc * rc - dz * dz));
}

ToolSolid tool_solid(const Tool& tool) {
  ToolSolid s;
  s.radius_mm = tool.diameter_mm * 0.5;
  switch (tool.kind) {
    case ToolKind::kFlat:
      s.corner_radius_mm = 0.0;
      break;
    case ToolKind::kBall:
      s.corner_radius_mm = s.radius_mm;
      break;
    case ToolKind::kBull:
      s.corner_radius_mm = tool.corner_radius_mm;
      break;
  }
  return s;
}

Vec2 plane_coords(Vec3 p, Axis axis) {
  switch (axis) {
    case Axis::kZ:
      return {p.x, p.y};
    case Axis::kX:
      return {p.y, p.z};
    case Axis::kY:
      return {p.z, p.x};
  }
  return {p.x, p.y};
}

namespace {

Ring rect_ring(Vec2 lo, Vec2 hi) {
  return {{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}};
}

double median3(double a, double b, double c) {
  return std::max(std::min(a, b), std::min(std::max(a, b), c));
}

}  // namespace

Result<Stock> Stock::block(const Box3& box, double pitch_mm) {
  if (box.empty() || !(box.size().x > 0 && box.size().y > 0 && box.size().z > 0)) {
    return bad_parameter("stock block: the box must have a positive size on every axis");
  }
  if (!(pitch_mm > 0.0)) {
    return bad_parameter("stock block: slice pitch " + std::to_string(pitch_mm) +
                         " mm must be positive");
  }
  TriSliceModel m;
  m.bounds = box;
  m.pitch_mm = pitch_mm;
  for (int a = 0; a < 3; ++a) {
    const Axis axis = static_cast<Axis>(a);
    const double lo = box.min[a], size = box.max[a] - box.min[a];
    const double count = std::ceil(size / pitch_mm - 1e-9);
    if (count > 200000) {
      return bad_parameter("stock block: " + std::to_string(count) +
                           " slices along one axis; raise the pitch");
    }
    SliceFamily& f = m.family(axis);
    f.axis = axis;
    f.pitch_mm = pitch_mm;
    f.first_level = lo + 0.5 * pitch_mm;
    const Ring r = rect_ring(plane_coords(box.min, axis), plane_coords(box.max, axis));
    f.slices.assign(static_cast<std::size_t>(count), PolygonSet{{r}});
  }
  return from_model(std::move(m));
}

Result<Stock> Stock::from_mesh(const Mesh& mesh, double pitch_mm, const Context& ctx) {
  if (mesh.empty()) return bad_input("stock mesh: no triangles");
  if (!(pitch_mm > 0.0)) return bad_parameter("stock mesh: slice pitch must be positive");
  const Box3 box = swarf::bounds(mesh);
  TriSliceModel m;
  m.bounds = box;
  m.pitch_mm = pitch_mm;
  for (int a = 0; a < 3; ++a) {
    const Axis axis = static_cast<Axis>(a);
    const double count = std::ceil((box.max[a] - box.min[a]) / pitch_mm - 1e-9);
    if (count > 200000 || count < 1) {
      return bad_parameter("stock mesh: " + std::to_string(count) + " slices along one axis");
    }
    SliceFamily& f = m.family(axis);
    f.axis = axis;
    f.pitch_mm = pitch_mm;
    f.first_level = box.min[a] + 0.5 * pitch_mm;
    std::vector<double> levels(static_cast<std::size_t>(count));
    for (std::size_t j = 0; j < levels.size(); ++j)
      levels[j] = f.level(j);
    f.slices = slice_mesh(mesh, axis, levels, {}, ctx);
  }
  return from_model(std::move(m));
}

Result<Stock> Stock::from_spec(const std::string& spec, double pitch_mm, const Context& ctx) {
  if (spec.rfind("box:", 0) == 0) {
    std::vector<double> v;
    std::size_t start = 4;
    while (start <= spec.size()) {
      const std::size_t comma = std::min(spec.find(',', start), spec.size());
      const std::string cell = spec.substr(start, comma - start);
      char* end = nullptr;
      const double x = std::strtod(cell.c_str(), &end);
      if (cell.empty() || end != cell.c_str() + cell.size() || !std::isfinite(x)) {
        return bad_parameter("stock \"" + spec + "\": \"" + cell + "\" is not a number");
      }
      v.push_back(x);
      start = comma + 1;
    }
    if (v.size() != 6) {
      return bad_parameter("stock \"" + spec + "\": need box:XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX");
    }
    const Box3 box{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    Result<Stock> s = block(box, pitch_mm);
    if (!s.ok()) return s.status().with_context("stock \"" + spec + "\"");
    return s;
  }
  Result<StlFile> stl = read_stl(spec);
  if (!stl.ok()) return stl.status();
  if (!stl->check.closed()) {
    return Status{Error::kOpenMesh, spec + ": the stock mesh is not closed"};
  }
  return from_mesh(stl->mesh, pitch_mm, ctx);
}

Result<Stock> Stock::from_model(TriSliceModel model) {
  if (!(model.pitch_mm > 0.0)) return bad_parameter("stock: the model's pitch must be positive");
  for (int a = 0; a < 3; ++a) {
    const SliceFamily& f = model.families[a];
    if (std::abs(f.pitch_mm - model.pitch_mm) > 1e-12) {
      return bad_parameter("stock: the three slice families must share one pitch");
    }
    if (static_cast<int>(f.axis) != a) return bad_parameter("stock: family axes out of order");
  }
  Stock s;
  s.model_ = std::move(model);
  for (int a = 0; a < 3; ++a) {
    const std::size_t n = s.model_.families[a].slices.size();
    s.areas_[a].resize(n);
    s.slice_bounds_[a].resize(n);
    s.index_[a].resize(n);
    for (std::size_t j = 0; j < n; ++j) {
      s.areas_[a][j] = area(s.model_.families[a].slices[j]);
      s.slice_bounds_[a][j] = swarf::bounds(s.model_.families[a].slices[j]);
      s.rebuild_index(a, j);
    }
  }
  return s;
}

double Stock::thickness(int family, std::size_t slice) const {
  // Cells are [level - pitch/2, level + pitch/2] clipped to the model's bounds: the last
  // cell of a box whose size is not a whole number of pitches is thinner.
  const SliceFamily& f = model_.families[family];
  const double c = f.level(slice);
  const double lo = std::max(c - 0.5 * f.pitch_mm, model_.bounds.min[family]);
  const double hi = std::min(c + 0.5 * f.pitch_mm, model_.bounds.max[family]);
  return std::max(0.0, hi - lo);
}

double Stock::volume_mm3(Axis family) const {
  const int a = static_cast<int>(family);
  double v = 0.0;
  for (std::size_t j = 0; j < areas_[a].size(); ++j)
    v += areas_[a][j] * thickness(a, j);
  return v;
}

double Stock::volume_mm3() const {
  return median3(volume_mm3(Axis::kX), volume_mm3(Axis::kY), volume_mm3(Axis::kZ));
}

void Stock::rebuild_index(int family, std::size_t slice) {
  SliceIndex& ix = index_[family][slice];
  ix = SliceIndex{};
  const PolygonSet& set = model_.families[family].slices[slice];
  const Box2& b = slice_bounds_[family][slice];
  if (set.empty() || b.empty()) return;
  ix.v0 = b.min.y;
  const double span = b.max.y - b.min.y;
  ix.row_h = std::max(model_.pitch_mm, span / 8192.0);
  const auto rows = static_cast<std::size_t>(std::floor(span / ix.row_h)) + 1;
  std::vector<std::uint32_t> counts(rows + 1, 0);
  auto row_range = [&](double va, double vb, std::size_t& r0, std::size_t& r1) {
    const double lo = std::min(va, vb), hi = std::max(va, vb);
    r0 = static_cast<std::size_t>(
        std::clamp(std::floor((lo - ix.v0) / ix.row_h), 0.0, static_cast<double>(rows - 1)));
    r1 = static_cast<std::size_t>(
        std::clamp(std::floor((hi - ix.v0) / ix.row_h), 0.0, static_cast<double>(rows - 1)));
  };
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      ix.row_start.assign(rows + 1, 0);
      for (std::size_t r = 0; r < rows; ++r)
        ix.row_start[r + 1] = ix.row_start[r] + counts[r];
      ix.edges.resize(ix.row_start[rows]);
      std::fill(counts.begin(), counts.end(), 0);
    }
    for (const Ring& ring : set.rings) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Vec2 a = ring[i], c = ring[(i + 1) % ring.size()];
        if (a.y == c.y) continue;  // horizontal edges never cross a horizontal ray
        std::size_t r0, r1;
        row_range(a.y, c.y, r0, r1);
        for (std::size_t r = r0; r <= r1; ++r) {
          if (pass == 0) {
            ++counts[r];
          } else {
            // (u at va, va, vb, du/dv): the crossing test needs no division.
            ix.edges[ix.row_start[r] + counts[r]++] = {a.x, a.y, c.y, (c.x - a.x) / (c.y - a.y)};
          }
        }
      }
    }
  }
}

bool Stock::inside_slice(int family, std::size_t slice, Vec2 uv) const {
  const Box2& b = slice_bounds_[family][slice];
  if (!b.contains(uv)) return false;
  const SliceIndex& ix = index_[family][slice];
  if (ix.row_start.empty()) return false;
  const std::size_t rows = ix.row_start.size() - 1;
  const auto r = static_cast<std::size_t>(
      std::clamp(std::floor((uv.y - ix.v0) / ix.row_h), 0.0, static_cast<double>(rows - 1)));
  bool in = false;
  for (std::uint32_t e = ix.row_start[r]; e < ix.row_start[r + 1]; ++e) {
    const auto& [ua, va, vb, slope] = ix.edges[e];
    if ((va > uv.y) != (vb > uv.y)) {
      const double u = ua + (uv.y - va) * slope;
      if (uv.x < u) in = !in;
    }
  }
  return in;
}

bool Stock::inside(Vec3 p, Axis family) const {
  const int a = static_cast<int>(family);
  if (p[a] < model_.bounds.min[a] || p[a] > model_.bounds.max[a]) return false;
  const SliceFamily& f = model_.families[a];
  // seed 001 Fig. 10b: the slice nearest to the point along the family's axis, within ds/2.
  const double j = std::round((p[a] - f.first_level) / f.pitch_mm);
  if (j < 0.0 || j >= static_cast<double>(f.slices.size())) return false;
  return inside_slice(a, static_cast<std::size_t>(j), plane_coords(p, family));
}

bool Stock::inside(Vec3 p, EngagementRule rule) const {
  const int needed = rule == EngagementRule::kAny ? 1 : 2;
  int votes = 0;
  // The xy family first: it decides most points of a 3-axis cut on its own.
  for (int a : {2, 0, 1}) {
    if (inside(p, static_cast<Axis>(a))) {
      if (++votes >= needed) return true;
    } else if (rule == EngagementRule::kMajority && a == 0 && votes == 0) {
      return false;  // two outside votes already
    }
  }
  return false;
}

Removal Stock::remove(const ToolSolid& tool, std::span<const Vec3> tips, const Context& ctx) {
  Removal out;
  if (tips.empty()) return out;
  const double radius = tool.radius_mm;
  const double pitch = model_.pitch_mm;
  Box3 reach;
  for (const Vec3& p : tips)
    reach.add(p);
  // Which slices the tool can reach: within a radius across the x and y families, and every
  // xy slice above the lowest tip (the shank continues upwards).
  struct Job {
    int family;
    std::size_t slice;
  };
  std::vector<Job> jobs;
  for (int a = 0; a < 3; ++a) {
    const SliceFamily& f = model_.families[a];
    if (f.slices.empty()) continue;
    const double lo = a == 2 ? reach.min.z : reach.min[a] - radius;
    const double hi = a == 2 ? std::numeric_limits<double>::infinity() : reach.max[a] + radius;
    const double j0 = std::max(0.0, std::ceil((lo - f.first_level) / f.pitch_mm - 1e-9));
    const double j1 = std::min(static_cast<double>(f.slices.size()) - 1.0,
                               std::floor((hi - f.first_level) / f.pitch_mm + 1e-9));
    for (double j = j0; j <= j1; j += 1.0) {
      const auto s = static_cast<std::size_t>(j);
      if (areas_[a][s] <= 0.0) continue;
      jobs.push_back({a, s});
    }
  }
  // The sections in yz / zx planes are the tool's profile plus the shank up to a common top.
  // The top must clear the stock and every tip's corner (a ramp may start in the air): only
  // then are all sections translates of one shape cut by the same plane, and the hull of
  // two of them the exact sweep.
  const double top = std::max(model_.bounds.max.z, reach.max.z + tool.corner_radius_mm) + 1.0;
  // Every xy slice at or above the highest tip plus the corner radius sees the full-width
  // section: compute that one once (an offset of a long polyline is the costly part).
  const double saturated_level = reach.max.z + tool.corner_radius_mm;
  const PolygonSet saturated = swept_section(tool, tips, Axis::kZ, saturated_level, top, pitch);
  std::vector<double> removed(jobs.size(), 0.0);
  parallel_for(jobs.size(), ctx.threads, [&](std::size_t i) {
    const Job& job = jobs[i];
    const Axis axis = static_cast<Axis>(job.family);
    const double level = model_.families[job.family].level(job.slice);
    PolygonSet swept = axis == Axis::kZ && level >= saturated_level
                           ? saturated
                           : swept_section(tool, tips, axis, level, top, pitch);
    if (swept.empty()) return;
    const Box2 sb = swarf::bounds(swept);
    const Box2& kb = slice_bounds_[job.family][job.slice];
    if (sb.max.x < kb.min.x || sb.min.x > kb.max.x || sb.max.y < kb.min.y || sb.min.y > kb.max.y) {
      return;
    }
    PolygonSet& slice = model_.families[job.family].slices[job.slice];
    PolygonSet next = subtract(slice, swept);
    const double a_next = area(next);
    const double delta = areas_[job.family][job.slice] - a_next;
    if (delta <= 1e-12) return;
    slice = std::move(next);
    areas_[job.family][job.slice] = a_next;
    slice_bounds_[job.family][job.slice] = swarf::bounds(slice);
    rebuild_index(job.family, job.slice);
    removed[i] = delta * thickness(job.family, job.slice);
  });
  for (std::size_t i = 0; i < jobs.size(); ++i)
    out.by_family_mm3[jobs[i].family] += removed[i];
  out.volume_mm3 = median3(out.by_family_mm3[0], out.by_family_mm3[1], out.by_family_mm3[2]);
  return out;
}

HeightMap Stock::height_map(double cell_mm) const {
  HeightMap hm;
  const Box3& b = model_.bounds;
  hm.cell_mm = cell_mm;
  const Vec3 size = b.size();
  if (!(cell_mm > 0.0) || size.x / cell_mm * (size.y / cell_mm) > 1e8) return hm;  // nx = ny = 0
  hm.x0 = b.min.x;
  hm.y0 = b.min.y;
  hm.nx = std::max(1, static_cast<int>(std::ceil((b.max.x - b.min.x) / cell_mm - 1e-9)));
  hm.ny = std::max(1, static_cast<int>(std::ceil((b.max.y - b.min.y) / cell_mm - 1e-9)));
  hm.top.assign(static_cast<std::size_t>(hm.nx) * static_cast<std::size_t>(hm.ny),
                std::numeric_limits<float>::quiet_NaN());
  const SliceFamily& f = model_.family(Axis::kX);  // planes x = level, coordinates (y, z)
  if (f.slices.empty()) return hm;
  for (int ix = 0; ix < hm.nx; ++ix) {
    const double x = hm.x0 + (ix + 0.5) * cell_mm;
    const double j = std::round((x - f.first_level) / f.pitch_mm);
    if (j < 0.0 || j >= static_cast<double>(f.slices.size())) continue;
    for (const Ring& ring : f.slices[static_cast<std::size_t>(j)].rings) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const Vec2 a = ring[i], c = ring[(i + 1) % ring.size()];
        const double lo = std::min(a.x, c.x), hi = std::max(a.x, c.x);
        if (hi - lo <= 0.0) continue;
        const int k0 = std::max(0, static_cast<int>(std::ceil((lo - hm.y0) / cell_mm - 0.5)));
        const int k1 =
            std::min(hm.ny - 1, static_cast<int>(std::floor((hi - hm.y0) / cell_mm - 0.5)));
        for (int k = k0; k <= k1; ++k) {
          const double y = hm.y0 + (k + 0.5) * cell_mm;
          const double z = a.y + (y - a.x) * (c.y - a.y) / (c.x - a.x);
          float& t = hm.top[static_cast<std::size_t>(k) * hm.nx + ix];
          if (std::isnan(t) || z > t) t = static_cast<float>(z);
        }
      }
    }
  }
  return hm;
}

}  // namespace swarf::sim
