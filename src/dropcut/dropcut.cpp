// Exact drop-cutter against a triangle mesh. The cutter is a convex solid of revolution whose
// lower surface is z = tip + h(d), d the distance from the axis (h of Tool::height_at), so the
// tip height over a triangle is max over its points q of q.z - h(|q.xy - p|): the maximum of a
// concave function, reached at a vertex, on an edge or inside the facet. Closed forms for the
// ball (all three), the flat end (all three) and the bull-nose (vertex, facet); the bull-nose
// edge is a one-dimensional concave maximisation solved by golden section.
#include "swarf/dropcut/dropcut.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "swarf/core/ball_contact.h"
#include "swarf/core/parallel.h"

namespace swarf {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Height of the cutter surface above the tip at distance d from the axis (d <= R).
double profile_height(const CutterShape& c, double d) {
  const double flat = c.radius_mm - c.corner_radius_mm;
  if (d <= flat) return 0.0;
  const double e = std::min(d - flat, c.corner_radius_mm);
  return c.corner_radius_mm -
         std::sqrt(std::max(0.0, c.corner_radius_mm * c.corner_radius_mm - e * e));
}

double box_distance(const Box2& b, Vec2 p) {
  const double dx = std::max({b.min.x - p.x, 0.0, p.x - b.max.x});
  const double dy = std::max({b.min.y - p.y, 0.0, p.y - b.max.y});
  return std::sqrt(dx * dx + dy * dy);  // not hypot: no overflow here, and hypot is slow
}

// True when q lies in the xy projection of the triangle (boundary included).
bool inside_xy(const std::array<Vec3, 3>& p, Vec2 q) {
  const Vec2 a = p[0].xy(), b = p[1].xy(), c = p[2].xy();
  const double d0 = cross(b - a, q - a);
  const double d1 = cross(c - b, q - b);
  const double d2 = cross(a - c, q - c);
  const bool has_neg = d0 < 0 || d1 < 0 || d2 < 0;
  const bool has_pos = d0 > 0 || d1 > 0 || d2 > 0;
  return !(has_neg && has_pos);
}

void consider(DropResult& best, double tip, ContactKind kind, std::size_t tri) {
  if (tip > best.tip_z) {
    best.tip_z = tip;
    best.contact = kind;
    best.triangle = tri;
  }
}

// Ball of radius r against the segment a-b (interior contact; the vertices are tried apart).
double ball_edge(Vec3 a, Vec3 b, Vec2 p, double r) {
  return ball_on_segment_centre(a, b, p, r) - r;
}

// Range of t in [0, 1] for which a + t (b - a) lies within distance R of p in xy.
bool disc_interval(Vec3 a, Vec3 b, Vec2 p, double R, double& t0, double& t1) {
  const Vec2 d = b.xy() - a.xy();
  const Vec2 f = a.xy() - p;
  const double qa = norm_sq(d), qb = dot(f, d);
  if (qa < 1e-300) {
    if (norm_sq(f) > R * R) return false;
    t0 = 0.0;
    t1 = 1.0;
    return true;
  }
  // |f + t d|^2 = R^2: quarter discriminant qb^2 - qa (|f|^2 - R^2) = qa R^2 - cross(f, d)^2
  // (as in ball_edge: exact 0 for a tool exactly R from an axis-aligned edge).
  const double cr = cross(f, d);
  const double disc = qa * R * R - cr * cr;
  if (disc < 0.0) return false;
  const double sq = std::sqrt(disc);
  t0 = std::max(0.0, (-qb - sq) / qa);
  t1 = std::min(1.0, (-qb + sq) / qa);
  return t0 <= t1;
}

// Bull-nose (corner radius 0 < rc < R) against the edge a + s e, s in [t0, t1] (where the edge
// is within R of the axis p): the highest tip at which the cutter touches it, or -inf when
// that cannot exceed `best`. The tip may sit at f(s) = z(s) - g(d(s)) on the edge point s
// (d its distance from the axis, g the cutter's profile height); f is concave (g is convex
// and non-decreasing, d convex, z linear), so its maximum is the root of f' where f' changes
// sign. The tangents at the two ends bound the maximum from above, which rejects most edges
// at the cost of two evaluations; a search then runs Newton's method on f' inside a bracket
// that halves when a Newton step would leave it. About six evaluations instead of the ~50
// of a golden-section search; every f(s) evaluated is a contact the cutter can rest on, so
// the answer is the best of them.
double bull_edge(Vec3 a, Vec3 e, Vec2 p, double R, double rc, double t0, double t1, double best) {
  const double flat = R - rc;
  const Vec2 exy = e.xy();
  const double elen2 = norm_sq(exy);
  struct Eval {
    double f, df, ddf;  // f and its first two derivatives in s (df may be +-inf at d = R)
  };
  auto eval = [&](double s) {
    const Vec3 q = a + e * s;
    const Vec2 w = q.xy() - p;
    const double d = std::sqrt(norm_sq(w));
    if (d <= flat) return Eval{q.z, e.z, 0.0};
    const double u = std::min(d, R) - flat;
    const double root = std::sqrt(std::max(0.0, rc * rc - u * u));
    const double dd = dot(w, exy) / d;         // d'(s)
    const double ddd = (elen2 - dd * dd) / d;  // d''(s) >= 0
    if (!(root > 0.0)) {
      // At the rim the profile is vertical: f' is -inf moving outwards, +inf moving in.
      const double inf = std::numeric_limits<double>::infinity();
      return Eval{q.z - rc, dd > 0.0 ? -inf : (dd < 0.0 ? inf : e.z), 0.0};
    }
    const double gp = u / root, gpp = rc * rc / (root * root * root);
    return Eval{q.z - (rc - root), e.z - gp * dd, -gpp * dd * dd - gp * ddd};
  };
  const Eval first = eval(t0), last = eval(t1);
  double out = std::max(first.f, last.f);
  if (!(first.df > 0.0) || !(last.df < 0.0) || !(t1 > t0)) return out;  // an end is the maximum
  // Tangent bound: f <= min(first.f + first.df (s - t0), last.f + last.df (s - t1)).
  double bound = std::numeric_limits<double>::infinity();
  if (std::isfinite(first.df) && std::isfinite(last.df)) {
    const double s = (last.f - first.f + first.df * t0 - last.df * t1) / (first.df - last.df);
    bound = first.f + first.df * (std::clamp(s, t0, t1) - t0);
  } else if (std::isfinite(last.df)) {
    bound = last.f + last.df * (t0 - t1);
  } else if (std::isfinite(first.df)) {
    bound = first.f + first.df * (t1 - t0);
  }
  if (bound <= best) return -std::numeric_limits<double>::infinity();
  double lo = t0, hi = t1, s = 0.5 * (t0 + t1);
  const double tol = 1e-10 / std::max(1e-300, std::sqrt(norm_sq(e)));  // 0.1 nm along the edge
  for (int it = 0; it < 100 && hi - lo > tol; ++it) {
    const Eval q = eval(s);
    out = std::max(out, q.f);
    if (q.df == 0.0) {
      break;
    }
    (q.df > 0.0 ? lo : hi) = s;
    // Newton on f' (f'' < 0 where the corner holds the edge); halve the bracket otherwise.
    const double next = q.ddf < 0.0 ? s - q.df / q.ddf : lo - 1.0;
    s = next > lo && next < hi ? next : 0.5 * (lo + hi);
  }
  return out;
}

}  // namespace

Result<DropCutter> DropCutter::build(const Mesh& mesh, const CutterShape& cutter,
                                     const DropCutterOptions& options) {
  if (mesh.empty()) return bad_input("drop-cutter: the mesh has no triangles");
  if (!(cutter.radius_mm > 0.0) || !std::isfinite(cutter.radius_mm))
    return bad_parameter("drop-cutter: tool radius " + std::to_string(cutter.radius_mm) +
                         " mm must be positive");
  if (cutter.corner_radius_mm < 0.0 || cutter.corner_radius_mm > cutter.radius_mm + 1e-12)
    return bad_parameter("drop-cutter: corner radius " + std::to_string(cutter.corner_radius_mm) +
                         " mm must lie in [0, tool radius]");
  if (options.cell_size_mm < 0.0) return bad_parameter("drop-cutter: negative cell size");
  DropCutter dc;
  dc.cutter_ = cutter;
  dc.cutter_.corner_radius_mm = std::min(cutter.corner_radius_mm, cutter.radius_mm);
  dc.tris_.reserve(mesh.size());
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    Tri tri;
    for (int k = 0; k < 3; ++k) {
      const Vec3& v = mesh.corner(t, k);
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
        return bad_input("drop-cutter: triangle " + std::to_string(t) +
                         " has a non-finite coordinate");
      tri.p[static_cast<std::size_t>(k)] = v;
      tri.box.add(v.xy());
      dc.bounds_.add(v);
    }
    tri.zmax = std::max({tri.p[0].z, tri.p[1].z, tri.p[2].z});
    Vec3 n = cross(tri.p[1] - tri.p[0], tri.p[2] - tri.p[0]);
    if (n.z < 0.0) n = -n;
    tri.n = normalized(n);
    tri.d = dot(tri.n, tri.p[0]);
    dc.tris_.push_back(tri);
  }

  // A uniform xy grid over the mesh; each triangle is listed in the cells its xy box
  // overlaps (not grown by the tool radius), highest triangles first, and each cell keeps
  // its highest z. A query walks the cells within R of the tool axis and rules a cell out
  // when even its highest point, as near to the axis as the cell allows, cannot lift the tool
  // above the best contact so far. Listing every triangle in every cell within R of it (one
  // cell per query, as before) made each list hold all triangles under a whole tool: on a
  // 290,000-triangle part with a ø6 ball that was 81 entries per triangle and a walk of about
  // a thousand of them per query.
  const double R = dc.cutter_.radius_mm;
  const Box2 area = dc.bounds_.xy().inflated(1e-9);
  double cell = options.cell_size_mm > 0.0 ? options.cell_size_mm : R / 4.0;
  cell = std::max(cell, std::max(area.size().x, area.size().y) / 2048.0);
  auto span_of = [&](const Tri& tri, double c, int nx, int ny) {
    return std::array<int, 4>{
        std::clamp(static_cast<int>(std::floor((tri.box.min.x - area.min.x) / c)), 0, nx - 1),
        std::clamp(static_cast<int>(std::floor((tri.box.max.x - area.min.x) / c)), 0, nx - 1),
        std::clamp(static_cast<int>(std::floor((tri.box.min.y - area.min.y) / c)), 0, ny - 1),
        std::clamp(static_cast<int>(std::floor((tri.box.max.y - area.min.y) / c)), 0, ny - 1)};
  };
  int nx = 0, ny = 0;
  for (;;) {
    nx = std::max(1, static_cast<int>(std::ceil(area.size().x / cell)));
    ny = std::max(1, static_cast<int>(std::ceil(area.size().y / cell)));
    std::size_t total = 0;
    for (const Tri& tri : dc.tris_) {
      const auto s = span_of(tri, cell, nx, ny);
      total +=
          static_cast<std::size_t>(s[1] - s[0] + 1) * static_cast<std::size_t>(s[3] - s[2] + 1);
    }
    if (total <= options.max_index_entries) break;
    cell *= 1.5;
  }
  dc.cell_ = cell;
  dc.origin_ = area.min;
  dc.nx_ = nx;
  dc.ny_ = ny;
  const std::size_t ncell = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
  auto for_cells = [&](const Tri& tri, auto&& fn) {
    const auto s = span_of(tri, cell, nx, ny);
    for (int j = s[2]; j <= s[3]; ++j)
      for (int i = s[0]; i <= s[1]; ++i)
        fn(static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) +
           static_cast<std::size_t>(i));
  };
  std::vector<std::uint32_t> counts(ncell + 1, 0);
  for (const Tri& tri : dc.tris_)
    for_cells(tri, [&](std::size_t c) { ++counts[c + 1]; });
  for (std::size_t c = 0; c < ncell; ++c)
    counts[c + 1] += counts[c];
  dc.cell_start_ = counts;
  dc.cell_items_.resize(counts[ncell]);
  std::vector<std::uint32_t> fill(counts.begin(), counts.end() - 1);
  for (std::size_t t = 0; t < dc.tris_.size(); ++t)
    for_cells(dc.tris_[t],
              [&](std::size_t c) { dc.cell_items_[fill[c]++] = static_cast<std::uint32_t>(t); });
  // Highest triangles first, so that a query can stop early; ties by index (deterministic).
  dc.cell_zmax_.assign(ncell, -kInf);
  parallel_for(ncell, 0, [&](std::size_t c) {
    auto b = dc.cell_items_.begin() + dc.cell_start_[c];
    auto e = dc.cell_items_.begin() + dc.cell_start_[c + 1];
    std::sort(b, e, [&](std::uint32_t x, std::uint32_t y) {
      const double zx = dc.tris_[x].zmax, zy = dc.tris_[y].zmax;
      return zx != zy ? zx > zy : x < y;
    });
    if (b != e) dc.cell_zmax_[c] = dc.tris_[*b].zmax;
  });
  return dc;
}

void DropCutter::test_triangle(const Tri& t, std::size_t index, Vec2 p, DropResult& best) const {
  const double R = cutter_.radius_mm;
  const double rc = cutter_.corner_radius_mm;
  const double R2 = R * R;
  const bool ball = rc >= R;
  // Vertices.
  for (const Vec3& v : t.p) {
    const double d2 = norm_sq(v.xy() - p);
    if (d2 > R2) continue;
    consider(best, v.z - profile_height(cutter_, std::sqrt(d2)), ContactKind::kVertex, index);
  }
  // Facet interior.
  if (t.n.z > 1e-12) {
    const Vec2 nxy{t.n.x, t.n.y};
    const double nh = norm(nxy);
    if (rc > 0.0) {
      // The corner torus meets the plane where its sub-ball (radius rc, centre on the ring of
      // radius R - rc) is furthest down the slope: offset -nxy/|nxy| * (R - rc) from the axis.
      const Vec2 c = (nh > 1e-15 && !ball) ? p - nxy * ((R - rc) / nh) : p;
      const double zc = (rc + t.d - t.n.x * c.x - t.n.y * c.y) / t.n.z;
      const Vec2 q{c.x - rc * t.n.x, c.y - rc * t.n.y};
      if (inside_xy(t.p, q)) consider(best, zc - rc, ContactKind::kFacet, index);
    } else {
      // Flat end: the plane is highest over the disc at its rim, up the slope.
      const Vec2 q = nh > 1e-15 ? p - nxy * (R / nh) : p;
      if (inside_xy(t.p, q))
        consider(best, (t.d - t.n.x * q.x - t.n.y * q.y) / t.n.z, ContactKind::kFacet, index);
    }
  }
  // Edges.
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = t.p[static_cast<std::size_t>(k)];
    const Vec3 b = t.p[static_cast<std::size_t>((k + 1) % 3)];
    if (ball) {
      consider(best, ball_edge(a, b, p, R), ContactKind::kEdge, index);
      continue;
    }
    double t0 = 0.0, t1 = 0.0;
    if (!disc_interval(a, b, p, R, t0, t1)) continue;
    const Vec3 e = b - a;
    // No point of the edge lies higher than its higher end nor nearer than its nearest point:
    // an edge that cannot beat the best contact even so is not searched (the bull-nose's
    // golden section is most of a drop's cost).
    {
      const Vec2 exy = e.xy();
      const double len2 = norm_sq(exy);
      const double s = len2 > 0.0 ? std::clamp(dot(p - a.xy(), exy) / len2, 0.0, 1.0) : 0.0;
      const double dmin = std::min(R, std::sqrt(norm_sq(a.xy() + exy * s - p)));
      if (std::max(a.z, b.z) - profile_height(cutter_, dmin) <= best.tip_z) continue;
    }
    if (rc <= 0.0) {
      // Flat end: the profile is flat, the tip height along the edge linear: its ends.
      auto f = [&](double s) { return (a + e * s).z; };
      consider(best, std::max(f(t0), f(t1)), ContactKind::kEdge, index);
      continue;
    }
    consider(best, bull_edge(a, e, p, R, rc, t0, t1, best.tip_z), ContactKind::kEdge, index);
  }
}

DropResult DropCutter::drop(Vec2 p) const {
  return drop(p, tris_.size());
}

DropResult DropCutter::drop(Vec2 p, std::size_t hint) const {
  DropResult best;
  const double R = cutter_.radius_mm;
  if (hint < tris_.size() && box_distance(tris_[hint].box, p) <= R)
    test_triangle(tris_[hint], hint, p, best);
  const int i0 = std::max(0, static_cast<int>(std::floor((p.x - R - origin_.x) / cell_)));
  const int i1 = std::min(nx_ - 1, static_cast<int>(std::floor((p.x + R - origin_.x) / cell_)));
  const int j0 = std::max(0, static_cast<int>(std::floor((p.y - R - origin_.y) / cell_)));
  const int j1 = std::min(ny_ - 1, static_cast<int>(std::floor((p.y + R - origin_.y) / cell_)));
  for (int j = j0; j <= j1; ++j) {
    const double cy0 = origin_.y + j * cell_;
    const double dy = std::max({cy0 - p.y, 0.0, p.y - cy0 - cell_});
    for (int i = i0; i <= i1; ++i) {
      const double cx0 = origin_.x + i * cell_;
      const double dx = std::max({cx0 - p.x, 0.0, p.x - cx0 - cell_});
      const double d2 = dx * dx + dy * dy;
      if (d2 > R * R) continue;
      const double dcell = std::sqrt(d2);
      const std::size_t c =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(nx_) + static_cast<std::size_t>(i);
      // Nothing in the cell comes nearer than dcell nor higher than its top.
      const double lift = profile_height(cutter_, dcell);
      if (cell_zmax_[c] - lift <= best.tip_z) continue;
      for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
        const std::uint32_t id = cell_items_[k];
        const Tri& t = tris_[id];
        if (t.zmax - lift <= best.tip_z) break;  // sorted: nothing further down can win
        // A triangle spanning several cells is tested in one of them only: the cell holding
        // the point of its box nearest to p (listed there, and never ruled out while the
        // triangle could still win: that cell is as near and at least as high).
        const int ci = std::clamp(
            static_cast<int>(
                std::floor((std::clamp(p.x, t.box.min.x, t.box.max.x) - origin_.x) / cell_)),
            0, nx_ - 1);
        const int cj = std::clamp(
            static_cast<int>(
                std::floor((std::clamp(p.y, t.box.min.y, t.box.max.y) - origin_.y) / cell_)),
            0, ny_ - 1);
        if (ci != i || cj != j) continue;
        const double d = box_distance(t.box, p);
        if (d > R) continue;
        if (t.zmax - profile_height(cutter_, d) <= best.tip_z) continue;
        test_triangle(t, id, p, best);
      }
    }
  }
  return best;
}

DropResult DropCutter::drop_brute_force(Vec2 p) const {
  DropResult best;
  for (std::size_t k = 0; k < tris_.size(); ++k) {
    if (box_distance(tris_[k].box, p) > cutter_.radius_mm) continue;
    test_triangle(tris_[k], k, p, best);
  }
  return best;
}

std::vector<double> grid_positions(double from, double to, double step) {
  std::vector<double> out;
  if (!(step > 0.0) || !(to >= from)) return out;
  const auto n = static_cast<std::size_t>(std::floor((to - from) / step + 1e-9));
  out.reserve(n + 2);
  for (std::size_t k = 0; k <= n; ++k)
    out.push_back(from + static_cast<double>(k) * step);
  if (out.back() < to - 1e-9) out.push_back(to);
  return out;
}

std::vector<double> ClGrid::line_positions() const {
  return direction == Axis::kX ? grid_positions(region.min.y, region.max.y, stepover_mm)
                               : grid_positions(region.min.x, region.max.x, stepover_mm);
}
std::vector<double> ClGrid::point_positions() const {
  return direction == Axis::kX ? grid_positions(region.min.x, region.max.x, sampling_mm)
                               : grid_positions(region.min.y, region.max.y, sampling_mm);
}

Status validate(const ClGrid& grid) {
  if (grid.region.empty()) return bad_parameter("CL grid: empty region");
  if (!(grid.stepover_mm > 0.0))
    return bad_parameter("CL grid: stepover " + std::to_string(grid.stepover_mm) +
                         " mm must be positive");
  if (!(grid.sampling_mm > 0.0))
    return bad_parameter("CL grid: sampling " + std::to_string(grid.sampling_mm) +
                         " mm must be positive");
  if (grid.direction == Axis::kZ) return bad_parameter("CL grid: lines must run along x or y");
  const Vec2 s = grid.region.size();
  if ((s.x / grid.sampling_mm + 1) * (s.y / grid.stepover_mm + 1) > 2e8)
    return bad_parameter("CL grid: more than 200 million points");
  return {};
}

Result<std::vector<Vec3>> drop_grid(const DropCutter& cutter, const ClGrid& grid, double floor_z,
                                    const Context& ctx) {
  SWARF_RETURN_IF_ERROR(validate(grid));
  const std::vector<double> lines = grid.line_positions();
  const std::vector<double> pts = grid.point_positions();
  std::vector<Vec3> out(lines.size() * pts.size());
  parallel_for(lines.size(), ctx.threads, [&](std::size_t i) {
    if (ctx.cancelled()) return;
    // Neighbouring points along a line mostly share their contact triangle: trying the
    // previous one first gives the sorted lists an early stop (a 65k-triangle sphere: 7.2 ->
    // 4.2 s with a ø20 ball, 2.1 -> 1.4 s with ø8, one thread; the same CL to the bit). Per
    // line, so independent of the thread count.
    std::size_t hint = std::numeric_limits<std::size_t>::max();
    for (std::size_t k = 0; k < pts.size(); ++k) {
      const Vec2 p = grid.direction == Axis::kX ? Vec2{pts[k], lines[i]} : Vec2{lines[i], pts[k]};
      const DropResult r = cutter.drop(p, hint);
      if (r.hit()) hint = r.triangle;
      out[i * pts.size() + k] = {p.x, p.y, r.hit() ? std::max(r.tip_z, floor_z) : floor_z};
    }
  });
  if (ctx.cancelled()) return Status{Error::kCancelled, "drop-cutter: cancelled"};
  return out;
}

}  // namespace swarf
