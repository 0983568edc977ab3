// Seed 003 section 2.2: ray-parity voxelization along z, plus the exact per-cell top of the
// part that keeps the roughing conservative between column centres.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "swarf/core/parallel.h"
#include "swarf/voxel/voxel.h"

namespace swarf {
namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();

bool lex_less(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// Is the ray point p, moved by (ε, ε²), strictly left of the directed edge u -> v? The
// orientation is evaluated with the vertices in one canonical order, so the answer for
// v -> u is exactly the opposite: a point on a shared edge belongs to exactly one side.
bool left_of(Vec2 u, Vec2 v, Vec2 p) {
  double s;
  if (lex_less(u, v)) {
    s = cross(v - u, p - u);
  } else {
    s = -cross(u - v, p - v);
  }
  if (s > 0.0) return true;
  if (s < 0.0) return false;
  // On the line: the perturbation decides. orient(u, v, p + (ε, ε²)) =
  // s + (v.x - u.x) ε² - (v.y - u.y) ε.
  if (v.y != u.y) return v.y < u.y;
  return v.x > u.x;
}

// The z where the vertical line through p meets the triangle's plane (p inside it).
double plane_z(const Vec3& a, const Vec3& b, const Vec3& c, Vec2 p) {
  const double area = cross(b.xy() - a.xy(), c.xy() - a.xy());
  const double wa = cross(c.xy() - b.xy(), p - b.xy()) / area;
  const double wb = cross(a.xy() - c.xy(), p - c.xy()) / area;
  return wa * a.z + wb * b.z + (1.0 - wa - wb) * c.z;
}

// Sutherland-Hodgman against one half-plane {axis coordinate * sign >= bound * sign}.
void clip(std::vector<Vec3>& poly, std::vector<Vec3>& scratch, int axis, double bound,
          double sign) {
  scratch.clear();
  const std::size_t n = poly.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& p = poly[i];
    const Vec3& q = poly[(i + 1) % n];
    const double dp = (p[axis] - bound) * sign, dq = (q[axis] - bound) * sign;
    if (dp >= 0.0) scratch.push_back(p);
    if ((dp >= 0.0) != (dq >= 0.0)) {
      const double t = dp / (dp - dq);
      Vec3 x = p + (q - p) * t;
      x[axis] = bound;  // exactly on the boundary
      scratch.push_back(x);
    }
  }
  poly.swap(scratch);
}

}  // namespace

double VoxelModel::layer_z(int k) const {
  return std::max(stock.max.z - (k + 1) * layer_mm, stock.min.z);
}

bool VoxelModel::filled(int i, int j, int k) const {
  const std::size_t c = column(i, j);
  const double lo = layer_z(k), hi = layer_top(k);
  for (std::uint32_t m = offsets[c]; m + 1 < offsets[c + 1]; m += 2) {
    if (crossings[m] < hi && crossings[m + 1] > lo) return true;
  }
  return false;
}

double VoxelModel::centre_top(int i, int j) const {
  const std::size_t c = column(i, j);
  return offsets[c + 1] > offsets[c] ? crossings[offsets[c + 1] - 1] : kNegInf;
}

Status validate(const VoxelizeOptions& o) {
  if (!(o.cell_mm > 0.0) || !(o.layer_mm > 0.0)) {
    return bad_parameter("voxel size must be positive (cell " + std::to_string(o.cell_mm) +
                         " mm, layer " + std::to_string(o.layer_mm) + " mm)");
  }
  if (!(o.margin_mm >= 0.0) || !(o.top_margin_mm >= 0.0)) {
    return bad_parameter("stock margins must be >= 0 mm");
  }
  if (o.top_subdivisions < 1 || o.top_subdivisions > 16) {
    return bad_parameter("top subdivisions must be in [1, 16]");
  }
  return {};
}

EdgeCheck check_edges(const Mesh& mesh) {
  // Weld by exact coordinates, then count the uses of every undirected edge.
  std::vector<std::uint32_t> idx(mesh.vertices.size());
  for (std::uint32_t i = 0; i < idx.size(); ++i)
    idx[i] = i;
  auto key = [&](std::uint32_t i) {
    const Vec3& v = mesh.vertices[i];
    return std::array<double, 3>{v.x, v.y, v.z};
  };
  std::sort(idx.begin(), idx.end(), [&](auto a, auto b) { return key(a) < key(b); });
  std::vector<std::uint32_t> id(idx.size());
  std::uint32_t next = 0;
  for (std::size_t r = 0; r < idx.size(); ++r) {
    if (r > 0 && key(idx[r]) != key(idx[r - 1])) ++next;
    id[idx[r]] = next;
  }
  // Undirected edges packed into one 64-bit key: sorting plain integers is several times
  // faster than sorting pairs.
  std::vector<std::uint64_t> edges;
  edges.reserve(mesh.triangles.size() * 3);
  for (const auto& t : mesh.triangles) {
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = id[t[k]], b = id[t[(k + 1) % 3]];
      if (a == b) continue;  // degenerate edge
      if (a > b) std::swap(a, b);
      edges.push_back(std::uint64_t{a} << 32 | b);
    }
  }
  std::sort(edges.begin(), edges.end());
  EdgeCheck check;
  for (std::size_t r = 0; r < edges.size();) {
    std::size_t s = r;
    while (s < edges.size() && edges[s] == edges[r])
      ++s;
    if (s - r == 1) ++check.open_edges;
    if (s - r > 2) ++check.non_manifold_edges;
    r = s;
  }
  return check;
}

Mesh rotate_about_z(const Mesh& mesh, double angle_deg) {
  Mesh out = mesh;
  const double a = deg_to_rad(angle_deg);
  for (Vec3& v : out.vertices) {
    const Vec2 p = rotated(v.xy(), a);
    v = {p.x, p.y, v.z};
  }
  return out;
}

Result<VoxelModel> voxelize(const Mesh& part, const VoxelizeOptions& opt, const Context& ctx) {
  SWARF_RETURN_IF_ERROR(validate(opt));
  if (part.empty()) return Status{Error::kEmptyResult, "voxelize: the part mesh is empty"};
  for (const auto& t : part.triangles) {
    for (auto v : t) {
      if (v >= part.vertices.size()) return bad_input("voxelize: triangle index out of range");
    }
  }
  // Open meshes are found by their effect: a column crossing the surface an odd number of
  // times is where parity is meaningless. (A hole no ray passes through, as in a vertical
  // wall, changes nothing, and sorting every edge would cost more than the voxelization.)
  VoxelModel m;
  Box3 part_box;
  for (const Vec3& v : part.vertices)
    part_box.add(v);
  Box3 stock = opt.stock;
  if (stock.empty()) {
    stock = part_box;
    stock.min.x -= opt.margin_mm;
    stock.min.y -= opt.margin_mm;
    stock.max.x += opt.margin_mm;
    stock.max.y += opt.margin_mm;
    stock.max.z += opt.top_margin_mm;
  } else if (!(stock.min.x <= part_box.min.x && stock.min.y <= part_box.min.y &&
               stock.max.x >= part_box.max.x && stock.max.y >= part_box.max.y)) {
    return bad_parameter("voxelize: the stock box does not contain the part's footprint");
  }
  m.stock = stock;
  m.cell_mm = opt.cell_mm;
  m.layer_mm = opt.layer_mm;
  const Vec3 size = stock.size();
  auto count = [](double len, double step) {
    return std::max(1, static_cast<int>(std::ceil(len / step - 1e-9)));
  };
  m.nx = count(size.x, opt.cell_mm);
  m.ny = count(size.y, opt.cell_mm);
  m.layers = count(size.z, opt.layer_mm);
  if (static_cast<double>(m.nx) * m.ny > 5e7) {
    return bad_parameter("voxelize: " + std::to_string(m.nx) + " x " + std::to_string(m.ny) +
                         " columns is too many; use a larger stepover");
  }
  // Centre the grid on the stock: the outermost centres lie inside it.
  m.origin = {stock.min.x + 0.5 * (size.x - (m.nx - 1) * opt.cell_mm),
              stock.min.y + 0.5 * (size.y - (m.ny - 1) * opt.cell_mm)};

  // Bucket triangles by the rows whose cell band they touch (the band contains the row's
  // centre line, so the parity pass needs no other bucket).
  const double c = opt.cell_mm;
  std::vector<std::vector<std::uint32_t>> rows(static_cast<std::size_t>(m.ny));
  for (std::uint32_t t = 0; t < part.triangles.size(); ++t) {
    double y0 = part.corner(t, 0).y, y1 = y0;
    for (int k = 1; k < 3; ++k) {
      y0 = std::min(y0, part.corner(t, k).y);
      y1 = std::max(y1, part.corner(t, k).y);
    }
    const int j0 = std::max(0, static_cast<int>(std::floor((y0 - m.origin.y) / c + 0.5)));
    const int j1 = std::min(m.ny - 1, static_cast<int>(std::floor((y1 - m.origin.y) / c + 0.5)));
    for (int j = j0; j <= j1; ++j)
      rows[static_cast<std::size_t>(j)].push_back(t);
  }

  const auto nx = static_cast<std::size_t>(m.nx);
  std::vector<std::vector<std::pair<int, double>>> hits(static_cast<std::size_t>(m.ny));
  std::vector<std::size_t> repaired(static_cast<std::size_t>(m.ny), 0);
  // Top squares: each cell split into sub x sub squares of f = cell_mm / sub.
  const int sub = opt.top_subdivisions;
  const double f = c / sub;
  const int fnx = m.nx * sub;
  const auto fnxs = static_cast<std::size_t>(fnx);
  const double x_edge = m.origin.x - 0.5 * c, y_edge = m.origin.y - 0.5 * c;
  m.top_sub = sub;
  m.cell_top.assign(fnxs * static_cast<std::size_t>(m.ny * sub), kNegInf);
  parallel_for(static_cast<std::size_t>(m.ny), ctx.threads, [&](std::size_t jr) {
    const int j = static_cast<int>(jr);
    const double yc = m.origin.y + j * c;
    auto& row_hits = hits[jr];
    std::vector<Vec3> poly, scratch, cell;
    for (std::uint32_t t : rows[jr]) {
      const Vec3 &a = part.corner(t, 0), &b = part.corner(t, 1), &d = part.corner(t, 2);
      // Parity: columns whose centre ray crosses the triangle.
      const double area = cross(b.xy() - a.xy(), d.xy() - a.xy());
      if (area != 0.0) {
        double xlo = std::min({a.x, b.x, d.x}), xhi = std::max({a.x, b.x, d.x});
        const int i0 = std::max(0, static_cast<int>(std::floor((xlo - m.origin.x) / c)));
        const int i1 = std::min(m.nx - 1, static_cast<int>(std::ceil((xhi - m.origin.x) / c)));
        for (int i = i0; i <= i1; ++i) {
          const Vec2 p{m.origin.x + i * c, yc};
          const bool l0 = left_of(a.xy(), b.xy(), p), l1 = left_of(b.xy(), d.xy(), p),
                     l2 = left_of(d.xy(), a.xy(), p);
          const bool inside = area > 0.0 ? (l0 && l1 && l2) : (!l0 && !l1 && !l2);
          if (inside) row_hits.emplace_back(i, plane_z(a, b, d, p));
        }
      }
      // Exact top over each top square (cell_mm / k wide): clip to the square's row band,
      // then to each column. Fast path: a triangle inside one square (fine meshes) just
      // lifts that square to its highest corner.
      const double xlo = std::min({a.x, b.x, d.x}), xhi = std::max({a.x, b.x, d.x});
      const double ylo = std::min({a.y, b.y, d.y}), yhi = std::max({a.y, b.y, d.y});
      const int fa = static_cast<int>(std::floor((xlo - x_edge) / f));
      const int fb = static_cast<int>(std::floor((xhi - x_edge) / f));
      const int ga = static_cast<int>(std::floor((ylo - y_edge) / f));
      const int gb = static_cast<int>(std::floor((yhi - y_edge) / f));
      if (fa == fb && ga == gb && fa >= 0 && fa < fnx && ga >= j * sub && ga < (j + 1) * sub &&
          xlo > x_edge + fa * f && xhi < x_edge + (fa + 1) * f && ylo > y_edge + ga * f &&
          yhi < y_edge + (ga + 1) * f) {
        double& top =
            m.cell_top[static_cast<std::size_t>(ga) * fnxs + static_cast<std::size_t>(fa)];
        top = std::max({top, a.z, b.z, d.z});
        continue;
      }
      for (int g = std::max(ga, j * sub); g <= std::min(gb, (j + 1) * sub - 1); ++g) {
        poly.assign({a, b, d});
        clip(poly, scratch, 1, y_edge + g * f, 1.0);
        if (!poly.empty()) clip(poly, scratch, 1, y_edge + (g + 1) * f, -1.0);
        if (poly.empty()) continue;
        double pxlo = poly[0].x, pxhi = poly[0].x;
        for (const Vec3& v : poly) {
          pxlo = std::min(pxlo, v.x);
          pxhi = std::max(pxhi, v.x);
        }
        const int i0 = std::max(0, static_cast<int>(std::floor((pxlo - x_edge) / f)));
        const int i1 = std::min(fnx - 1, static_cast<int>(std::floor((pxhi - x_edge) / f)));
        for (int i = i0; i <= i1; ++i) {
          cell = poly;
          clip(cell, scratch, 0, x_edge + i * f, 1.0);
          if (!cell.empty()) clip(cell, scratch, 0, x_edge + (i + 1) * f, -1.0);
          double& top =
              m.cell_top[static_cast<std::size_t>(g) * fnxs + static_cast<std::size_t>(i)];
          for (const Vec3& v : cell)
            top = std::max(top, v.z);
        }
      }
    }
    std::sort(row_hits.begin(), row_hits.end());
    // Columns with an odd count (open meshes, or a rounding accident): fill between the
    // lowest and highest crossing, which can only make the part bigger (no gouge).
    std::vector<std::pair<int, double>> fixed;
    fixed.reserve(row_hits.size());
    for (std::size_t r = 0; r < row_hits.size();) {
      std::size_t s = r;
      while (s < row_hits.size() && row_hits[s].first == row_hits[r].first)
        ++s;
      if ((s - r) % 2 == 1) {
        fixed.push_back(row_hits[r]);
        fixed.push_back(row_hits[s - 1]);
        ++repaired[jr];
      } else {
        fixed.insert(fixed.end(), row_hits.begin() + static_cast<std::ptrdiff_t>(r),
                     row_hits.begin() + static_cast<std::ptrdiff_t>(s));
      }
      r = s;
    }
    row_hits.swap(fixed);
  });
  if (ctx.cancelled()) return Status{Error::kCancelled, "voxelize: cancelled"};

  m.offsets.assign(nx * static_cast<std::size_t>(m.ny) + 1, 0);
  std::size_t total_repaired = 0;
  for (std::size_t j = 0; j < hits.size(); ++j) {
    total_repaired += repaired[j];
    for (const auto& h : hits[j])
      ++m.offsets[j * nx + static_cast<std::size_t>(h.first) + 1];
  }
  for (std::size_t k = 1; k < m.offsets.size(); ++k)
    m.offsets[k] += m.offsets[k - 1];
  m.crossings.resize(m.offsets.back());
  for (std::size_t j = 0; j < hits.size(); ++j) {
    std::size_t at = m.offsets[j * nx];
    for (const auto& h : hits[j])
      m.crossings[at++] = h.second;
  }
  if (total_repaired > 0) {
    const std::string what =
        std::to_string(total_repaired) + " columns cross the part surface an odd number of times";
    if (!opt.repair_open) {
      return Status{Error::kOpenMesh,
                    "voxelize: the part is not a closed solid (" + what +
                        "): ray parity is meaningless there (allow repair to fill each such "
                        "column between its lowest and highest crossing)"};
    }
    m.warnings.push_back("part mesh is open: " + what +
                         "; each was filled between its lowest and highest crossing");
  }
  return m;
}

}  // namespace swarf
