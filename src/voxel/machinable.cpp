// Seed 003 section 2.3: stock allowance and tool-radius offset, voxel projection.
#include "voxel/machinable.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include "swarf/core/parallel.h"

namespace swarf::voxel_detail {
namespace {

constexpr double kNegInf = -std::numeric_limits<double>::infinity();
// Heights within this of a layer's threshold count as blocking (round towards safety).
constexpr double kHeightEps = 1e-7;

// A stencil as one x-interval of cell offsets per row offset: every convex shape (disk,
// stadium, square) is one interval per row.
struct StencilRow {
  int dy, lo, hi;
};

// Distance between the closed intervals [a0, a1] and [b0, b1].
double gap(double a0, double a1, double b0, double b1) {
  return std::max({0.0, b0 - a1, a0 - b1});
}

// Top squares (side `square` mm, k per cell) whose closed square comes closer than
// `radius` to the segment from the centre of cell (0, 0) to the centre of cell (sx, sy)
// (sx, sy in {0, 1}). Offsets count squares from the cell's lower-left square.
std::vector<StencilRow> segment_stencil(double radius, double square, int k, int sx, int sy) {
  std::vector<StencilRow> rows;
  const double p = 0.5 * k;  // the cell centre, in squares from the cell's corner
  const int reach = static_cast<int>(std::ceil(radius / square)) + k + 2;
  for (int dy = -reach; dy <= reach; ++dy) {
    int lo = 1, hi = 0;
    for (int dx = -reach; dx <= reach; ++dx) {
      const double gx = gap(p, p + sx * k, dx, dx + 1) * square;
      const double gy = gap(p, p + sy * k, dy, dy + 1) * square;
      // Touching at exactly the radius counts as blocked: round towards safety.
      if (std::hypot(gx, gy) < radius * (1.0 + 1e-12) + 1e-9) {
        if (lo > hi) lo = hi = dx;
        hi = dx;
      }
    }
    if (lo <= hi) rows.push_back({dy, lo, hi});
  }
  return rows;
}

// max over di in [lo, hi] of h(i + di, j), for every cell (monotonic queue per row).
std::vector<double> row_window_max(const std::vector<double>& h, int nx, int ny, int lo, int hi,
                                   int threads) {
  std::vector<double> out(h.size(), kNegInf);
  parallel_for(static_cast<std::size_t>(ny), threads, [&](std::size_t j) {
    const double* row = h.data() + j * static_cast<std::size_t>(nx);
    double* dst = out.data() + j * static_cast<std::size_t>(nx);
    std::vector<int> q(static_cast<std::size_t>(nx));
    std::size_t head = 0, tail = 0;
    int next = 0;
    for (int i = 0; i < nx; ++i) {
      const int wlo = i + lo, whi = std::min(i + hi, nx - 1);
      for (; next <= whi; ++next) {
        if (next < 0) continue;
        while (tail > head && row[q[tail - 1]] <= row[next])
          --tail;
        q[tail++] = next;
      }
      while (tail > head && q[head] < wlo)
        ++head;
      dst[i] = tail > head ? row[q[head]] : kNegInf;
    }
  });
  return out;
}

// For every cell (i, j): the max of h (a grid of fnx x fny squares, k per cell) over the
// stencil placed at square (i k, j k).
std::vector<double> dilate(const std::vector<double>& h, int fnx, int fny, int k,
                           const std::vector<StencilRow>& stencil, int threads) {
  std::map<std::pair<int, int>, std::vector<double>> windows;
  for (const StencilRow& r : stencil) {
    auto key = std::make_pair(r.lo, r.hi);
    if (!windows.count(key)) windows.emplace(key, row_window_max(h, fnx, fny, r.lo, r.hi, threads));
  }
  const int nx = fnx / k, ny = fny / k;
  std::vector<double> out(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), kNegInf);
  parallel_for(static_cast<std::size_t>(ny), threads, [&](std::size_t jr) {
    const int j = static_cast<int>(jr);
    for (const StencilRow& r : stencil) {
      const int js = j * k + r.dy;
      if (js < 0 || js >= fny) continue;
      const auto& w = windows.at({r.lo, r.hi});
      const std::size_t src = static_cast<std::size_t>(js) * static_cast<std::size_t>(fnx);
      const std::size_t dst = jr * static_cast<std::size_t>(nx);
      for (int i = 0; i < nx; ++i) {
        const auto ii = static_cast<std::size_t>(i);
        out[dst + ii] = std::max(out[dst + ii], w[src + static_cast<std::size_t>(i * k)]);
      }
    }
  });
  return out;
}

// Distance from segment pq to the closed axis-aligned square [lo, hi].
double segment_square_distance(Vec2 p, Vec2 q, Vec2 lo, Vec2 hi) {
  auto point_box = [&](Vec2 a) {
    return std::hypot(gap(a.x, a.x, lo.x, hi.x), gap(a.y, a.y, lo.y, hi.y));
  };
  auto point_seg = [&](Vec2 a) {
    const Vec2 d = q - p;
    const double l2 = norm_sq(d);
    const double t = l2 > 0.0 ? std::clamp(dot(a - p, d) / l2, 0.0, 1.0) : 0.0;
    return distance(a, p + d * t);
  };
  // Does the segment cross the square? (Liang-Barsky clip.)
  double t0 = 0.0, t1 = 1.0;
  const Vec2 d = q - p;
  bool inside = true;
  for (int axis = 0; axis < 2 && inside; ++axis) {
    const double pa = axis == 0 ? p.x : p.y, da = axis == 0 ? d.x : d.y;
    const double l = axis == 0 ? lo.x : lo.y, h = axis == 0 ? hi.x : hi.y;
    if (da == 0.0) {
      if (pa < l || pa > h) inside = false;
    } else {
      double a = (l - pa) / da, b = (h - pa) / da;
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
      if (t0 > t1) inside = false;
    }
  }
  if (inside) return 0.0;
  return std::min({point_box(p), point_box(q), point_seg(lo), point_seg(hi),
                   point_seg({lo.x, hi.y}), point_seg({hi.x, lo.y})});
}

}  // namespace

Reach compute_reach(const VoxelModel& m, double tool_radius_mm, double allowance_mm,
                    OffsetRule rule, int threads) {
  Reach r;
  r.radius_mm = tool_radius_mm + allowance_mm;
  r.allowance_mm = allowance_mm;
  r.rule = rule;
  const std::size_t n = static_cast<std::size_t>(m.nx) * static_cast<std::size_t>(m.ny);
  if (rule == OffsetRule::kDisk) {
    // Projection (2.3.2) is implicit: a cell's height is the top of all the part over it,
    // so a layer is blocked under any material above it.
    const int k = m.top_sub;
    r.base = m.cell_top;
    r.base_nx = m.nx * k;
    r.base_ny = m.ny * k;
    r.base_square_mm = m.cell_mm / k;
    r.base_origin = m.origin - Vec2{0.5 * m.cell_mm, 0.5 * m.cell_mm} +
                    Vec2{0.5 * r.base_square_mm, 0.5 * r.base_square_mm};
    auto grow = [&](int sx, int sy) {
      return dilate(r.base, r.base_nx, r.base_ny, k,
                    segment_stencil(r.radius_mm, r.base_square_mm, k, sx, sy), threads);
    };
    r.centre = grow(0, 0);
    r.link_x = grow(1, 0);
    r.link_y = grow(0, 1);
    return r;
  }
  // Seed 003 Eq. (3.1) on the centre-ray voxels, projected by taking each ray's top.
  r.base.resize(n);
  for (int j = 0; j < m.ny; ++j) {
    for (int i = 0; i < m.nx; ++i)
      r.base[m.column(i, j)] = m.centre_top(i, j);
  }
  const double w = m.cell_mm, d = 2.0 * tool_radius_mm;
  const int n0 = std::max(0, static_cast<int>(std::ceil((2.0 * allowance_mm + d - w) / (2.0 * w))));
  std::vector<StencilRow> square;
  for (int dy = -n0; dy <= n0; ++dy)
    square.push_back({dy, -n0, n0});
  r.base_nx = m.nx;
  r.base_ny = m.ny;
  r.base_square_mm = m.cell_mm;
  r.base_origin = m.origin;
  r.centre = dilate(r.base, m.nx, m.ny, 1, square, threads);
  // The paper checks only the voxels the tool stands on.
  r.link_x = dilate(r.centre, m.nx, m.ny, 1, {{0, 0, 1}}, threads);
  r.link_y = dilate(r.centre, m.nx, m.ny, 1, {{0, 0, 0}, {1, 0, 0}}, threads);
  return r;
}

double layer_threshold(const VoxelModel& m, const Reach& reach, int k) {
  return m.layer_z(k) - reach.allowance_mm - kHeightEps;
}

std::vector<std::uint8_t> layer_flags(const VoxelModel& m, const Reach& reach, int k,
                                      const std::vector<std::uint8_t>& stock) {
  const double thr = layer_threshold(m, reach, k);
  // A layer with no room for the tool (below the part's top everywhere) has no flags at
  // all: most layers of a prismatic part are like that, and they need no memory.
  bool any = false;
  for (std::size_t c = 0; c < reach.centre.size() && !any; ++c) {
    any = reach.centre[c] < thr && (stock.empty() || stock[c]);
  }
  if (!any) return {};
  std::vector<std::uint8_t> f(reach.centre.size(), 0);
  // Branch-free over each row (this runs for every layer on every column): the flags are
  // the same comparisons as one test per flag, combined as bits.
  const auto nx = static_cast<std::size_t>(m.nx);
  const double* centre = reach.centre.data();
  const double* lx = reach.link_x.data();
  const double* ly = reach.link_y.data();
  for (int j = 0; j < m.ny; ++j) {
    const std::size_t row = static_cast<std::size_t>(j) * nx;
    const bool last_row = j + 1 >= m.ny;
    for (std::size_t i = 0; i < nx; ++i) {
      const std::size_t c = row + i;
      const bool has_stock = stock.empty() || stock[c] != 0;
      const bool is_free = centre[c] < thr;
      const bool link_x = is_free && i + 1 < nx && lx[c] < thr && centre[c + 1] < thr;
      const bool link_y = is_free && !last_row && ly[c] < thr && centre[c + nx] < thr;
      f[c] = static_cast<std::uint8_t>((has_stock ? kStock : 0) | (is_free ? kFree : 0) |
                                       (link_x ? kLinkX : 0) | (link_y ? kLinkY : 0));
    }
  }
  return f;
}

bool straight_move_clear(const VoxelModel& m, const Reach& reach, int k, Vec2 p, Vec2 q) {
  const double thr = layer_threshold(m, reach, k);
  const double c = m.cell_mm;
  auto cell_of = [&](double v, double o) {
    return static_cast<int>(std::floor((v - o) / c + 0.5));
  };
  if (reach.rule == OffsetRule::kPaperSquare) {
    // The paper's model: every cell the move passes over must be free.
    const int steps = std::max(1, static_cast<int>(std::ceil(distance(p, q) / (0.25 * c))));
    for (int s = 0; s <= steps; ++s) {
      const Vec2 a = p + (q - p) * (static_cast<double>(s) / steps);
      const int i = cell_of(a.x, m.origin.x), j = cell_of(a.y, m.origin.y);
      if (i < 0 || j < 0 || i >= m.nx || j >= m.ny) return false;
      if (reach.centre[m.column(i, j)] >= thr) return false;
    }
    return true;
  }
  // Rows of top squares the stadium touches; in each, the columns its x-extent can reach.
  const double rad = reach.radius_mm;
  const double sq = reach.base_square_mm;
  const Vec2 o = reach.base_origin;
  auto square_of = [&](double v, double org) {
    return static_cast<int>(std::floor((v - org) / sq + 0.5));
  };
  const int j0 = std::max(0, square_of(std::min(p.y, q.y) - rad, o.y) - 1);
  const int j1 = std::min(reach.base_ny - 1, square_of(std::max(p.y, q.y) + rad, o.y) + 1);
  const auto bnx = static_cast<std::size_t>(reach.base_nx);
  for (int j = j0; j <= j1; ++j) {
    const double yc = o.y + j * sq;
    const double ylo = yc - 0.5 * sq - rad, yhi = yc + 0.5 * sq + rad;
    // x-range of the segment within the band [ylo, yhi].
    double xa, xb;
    if (p.y == q.y) {
      if (p.y < ylo || p.y > yhi) continue;
      xa = std::min(p.x, q.x);
      xb = std::max(p.x, q.x);
    } else {
      double t0 = (ylo - p.y) / (q.y - p.y), t1 = (yhi - p.y) / (q.y - p.y);
      if (t0 > t1) std::swap(t0, t1);
      t0 = std::max(t0, 0.0);
      t1 = std::min(t1, 1.0);
      if (t0 > t1) continue;
      const double x0 = p.x + (q.x - p.x) * t0, x1 = p.x + (q.x - p.x) * t1;
      xa = std::min(x0, x1);
      xb = std::max(x0, x1);
    }
    const int i0 = std::max(0, square_of(xa - rad, o.x) - 1);
    const int i1 = std::min(reach.base_nx - 1, square_of(xb + rad, o.x) + 1);
    const std::size_t row = static_cast<std::size_t>(j) * bnx;
    for (int i = i0; i <= i1; ++i) {
      if (reach.base[row + static_cast<std::size_t>(i)] < thr) continue;
      const Vec2 ctr = o + Vec2{i * sq, j * sq};
      const Vec2 h{0.5 * sq, 0.5 * sq};
      if (segment_square_distance(p, q, ctr - h, ctr + h) < rad * (1.0 + 1e-12) + 1e-9) {
        return false;
      }
    }
  }
  return true;
}

}  // namespace swarf::voxel_detail
