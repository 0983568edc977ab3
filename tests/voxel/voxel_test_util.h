// Test helpers for the voxel roughing: meshes built here (independent of the mesh module),
// and brute-force truths computed from the triangles themselves.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "swarf/mesh/mesh.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf::voxel_test {

// A closed heightfield solid over the rectilinear grid xs x ys: top z = f(x, y) at the
// nodes, flat bottom at z = base. Twin grid lines a hair apart give near-vertical walls.
inline Mesh heightfield(const std::vector<double>& xs, const std::vector<double>& ys,
                        const std::function<double(double, double)>& f, double base) {
  Mesh m;
  const auto nx = static_cast<std::uint32_t>(xs.size()), ny = static_cast<std::uint32_t>(ys.size());
  auto top = [&](std::uint32_t i, std::uint32_t j) { return j * nx + i; };
  auto bot = [&](std::uint32_t i, std::uint32_t j) { return nx * ny + j * nx + i; };
  for (int layer = 0; layer < 2; ++layer) {
    for (std::uint32_t j = 0; j < ny; ++j) {
      for (std::uint32_t i = 0; i < nx; ++i) {
        m.vertices.push_back({xs[i], ys[j], layer == 0 ? f(xs[i], ys[j]) : base});
      }
    }
  }
  for (std::uint32_t j = 0; j + 1 < ny; ++j) {
    for (std::uint32_t i = 0; i + 1 < nx; ++i) {
      m.triangles.push_back({top(i, j), top(i + 1, j), top(i + 1, j + 1)});
      m.triangles.push_back({top(i, j), top(i + 1, j + 1), top(i, j + 1)});
      m.triangles.push_back({bot(i, j), bot(i + 1, j + 1), bot(i + 1, j)});
      m.triangles.push_back({bot(i, j), bot(i, j + 1), bot(i + 1, j + 1)});
    }
  }
  auto wall = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    // a, b on top, c, d below them
    m.triangles.push_back({a, c, d});
    m.triangles.push_back({a, d, b});
  };
  for (std::uint32_t i = 0; i + 1 < nx; ++i) {
    wall(top(i + 1, 0), top(i, 0), bot(i + 1, 0), bot(i, 0));
    wall(top(i, ny - 1), top(i + 1, ny - 1), bot(i, ny - 1), bot(i + 1, ny - 1));
  }
  for (std::uint32_t j = 0; j + 1 < ny; ++j) {
    wall(top(0, j), top(0, j + 1), bot(0, j), bot(0, j + 1));
    wall(top(nx - 1, j + 1), top(nx - 1, j), bot(nx - 1, j + 1), bot(nx - 1, j));
  }
  return m;
}

// Seed 003 Fig. 6(a): a block with four protruding rectangular bosses.
inline Mesh block_with_bosses(double size, double height, double boss, double boss_h) {
  const double e = 1e-3;
  std::vector<double> lines{0.0, size};
  std::vector<std::array<double, 4>> bosses;  // x0, x1, y0, y1
  const double a = 0.15 * size, b = 0.6 * size;
  for (double x : {a, b}) {
    for (double y : {a, b})
      bosses.push_back(
          {x, x + boss, y + (x == b ? 0.1 * size : 0.0), y + (x == b ? 0.1 * size : 0.0) + boss});
  }
  std::vector<double> xs{0.0, size}, ys{0.0, size};
  for (auto& bb : bosses) {
    for (double v : {bb[0] - e, bb[0], bb[1], bb[1] + e})
      xs.push_back(v);
    for (double v : {bb[2] - e, bb[2], bb[3], bb[3] + e})
      ys.push_back(v);
  }
  std::sort(xs.begin(), xs.end());
  std::sort(ys.begin(), ys.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  return heightfield(
      xs, ys,
      [=](double x, double y) {
        for (auto& bb : bosses) {
          if (x >= bb[0] && x <= bb[1] && y >= bb[2] && y <= bb[3]) return height + boss_h;
        }
        return height;
      },
      0.0);
}

inline std::vector<double> linspace(double a, double b, int n) {
  std::vector<double> v;
  for (int i = 0; i <= n; ++i)
    v.push_back(a + (b - a) * i / n);
  return v;
}

// Minimal ASCII STL reader (the test data is ASCII), welding exact duplicates.
inline Mesh read_ascii_stl(const std::string& path) {
  std::ifstream in(path);
  std::string word;
  std::map<std::array<double, 3>, std::uint32_t> ids;
  Mesh m;
  std::array<std::uint32_t, 3> tri{};
  int k = 0;
  while (in >> word) {
    if (word != "vertex") continue;
    std::array<double, 3> v{};
    in >> v[0] >> v[1] >> v[2];
    auto it = ids.find(v);
    if (it == ids.end()) {
      it = ids.emplace(v, static_cast<std::uint32_t>(m.vertices.size())).first;
      m.vertices.push_back({v[0], v[1], v[2]});
    }
    tri[static_cast<std::size_t>(k++)] = it->second;
    if (k == 3) {
      m.triangles.push_back(tri);
      k = 0;
    }
  }
  return m;
}

// The highest point of the part within distance rho of (x, y), exactly, from the
// triangles: the maximum of a linear function over triangle ∩ disk is at a vertex inside
// the disk, at an edge's crossing of the circle, or on the circle along the gradient.
class PartHeights {
 public:
  explicit PartHeights(const Mesh& m, double bin = 10.0) : m_(m), bin_(bin) {
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
      for (int k = 0; k < 3; ++k) {
        x0 = std::min(x0, m.corner(t, k).x);
        x1 = std::max(x1, m.corner(t, k).x);
        y0 = std::min(y0, m.corner(t, k).y);
        y1 = std::max(y1, m.corner(t, k).y);
      }
      for (long i = key(x0); i <= key(x1); ++i) {
        for (long j = key(y0); j <= key(y1); ++j)
          bins_[{i, j}].push_back(t);
      }
    }
  }

  double max_in_disk(double x, double y, double rho) const {
    double best = -std::numeric_limits<double>::infinity();
    std::vector<std::size_t> seen;
    for (long i = key(x - rho); i <= key(x + rho); ++i) {
      for (long j = key(y - rho); j <= key(y + rho); ++j) {
        auto it = bins_.find({i, j});
        if (it == bins_.end()) continue;
        for (std::size_t t : it->second)
          best = std::max(best, triangle_max(t, x, y, rho));
      }
    }
    return best;
  }

 private:
  long key(double v) const { return static_cast<long>(std::floor(v / bin_)); }

  double triangle_max(std::size_t t, double cx, double cy, double rho) const {
    const Vec3 p[3] = {m_.corner(t, 0), m_.corner(t, 1), m_.corner(t, 2)};
    double best = -std::numeric_limits<double>::infinity();
    const Vec2 c{cx, cy};
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = p[k], b = p[(k + 1) % 3];
      if (distance(a.xy(), c) <= rho) best = std::max(best, a.z);
      // Edge crossings of the circle: |a + s (b - a) - c| = rho.
      const Vec2 d = b.xy() - a.xy(), f = a.xy() - c;
      const double qa = dot(d, d), qb = 2 * dot(f, d), qc = dot(f, f) - rho * rho;
      const double disc = qb * qb - 4 * qa * qc;
      if (qa > 0 && disc >= 0) {
        for (double sg : {-1.0, 1.0}) {
          const double s = (-qb + sg * std::sqrt(disc)) / (2 * qa);
          if (s >= 0 && s <= 1) best = std::max(best, a.z + s * (b.z - a.z));
        }
      }
    }
    // Interior: the plane's gradient direction on the circle.
    const Vec2 e1 = p[1].xy() - p[0].xy(), e2 = p[2].xy() - p[0].xy();
    const double det = cross(e1, e2);
    if (std::abs(det) > 1e-12) {
      const double dz1 = p[1].z - p[0].z, dz2 = p[2].z - p[0].z;
      const Vec2 g{(dz1 * e2.y - dz2 * e1.y) / det, (e1.x * dz2 - e2.x * dz1) / det};
      const Vec2 q = norm(g) > 0 ? c + normalized(g) * rho : c;
      const double u = cross(q - p[0].xy(), e2) / det, v = cross(e1, q - p[0].xy()) / det;
      if (u >= 0 && v >= 0 && u + v <= 1) best = std::max(best, p[0].z + dot(g, q - p[0].xy()));
    }
    return best;
  }

  const Mesh& m_;
  double bin_;
  std::map<std::pair<long, long>, std::vector<std::size_t>> bins_;
};

// Tool positions along the toolpath, at most `step` apart (every move, rapids included).
inline void for_each_tool_position(const Toolpath& tp, double step,
                                   const std::function<void(Vec3)>& f) {
  if (tp.moves.empty()) return;
  Vec3 at = tp.moves.front().end;
  f(at);
  for (std::size_t i = 1; i < tp.moves.size(); ++i) {
    const Vec3 to = tp.moves[i].end;
    const int n = std::max(1, static_cast<int>(std::ceil(distance(at, to) / step)));
    for (int s = 1; s <= n; ++s)
      f(at + (to - at) * (static_cast<double>(s) / n));
    at = to;
  }
}

}  // namespace swarf::voxel_test
