// Analytic test parts. Every surface is built directly as an indexed mesh that shares its
// vertices exactly (no welding by distance), so the parts are closed by construction and
// triangles are counter-clockwise seen from outside.
#include "swarf/mesh/generate.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace swarf {
namespace {

class Builder {
 public:
  std::uint32_t vertex(Vec3 p) {
    mesh_.vertices.push_back(p);
    return static_cast<std::uint32_t>(mesh_.vertices.size() - 1);
  }
  void tri(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    mesh_.triangles.push_back({a, b, c});
  }
  /// Quad a-b-c-d, counter-clockwise seen from outside.
  void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
    tri(a, b, c);
    tri(a, c, d);
  }
  Mesh take() { return std::move(mesh_); }

 private:
  Mesh mesh_;
};

// Surface of revolution about the vertical axis through `center`. `profile` holds (rho, z)
// points, rho >= 0, ordered so that the outside lies to the right when walking along the
// profile in the (rho, z) half-plane (e.g. over the top of a solid in the +rho direction):
// then (profile tangent) x (azimuth direction) is the outward normal. Points with rho == 0
// become one pole vertex. Returns the vertex index of profile point j at azimuth step k.
std::vector<std::vector<std::uint32_t>> revolve(Builder& b, Vec3 center,
                                                const std::vector<Vec2>& profile,
                                                bool closed_profile, int segments) {
  std::vector<std::vector<std::uint32_t>> idx(profile.size());
  for (std::size_t j = 0; j < profile.size(); ++j) {
    const Vec2 p = profile[j];
    if (p.x == 0.0) {
      idx[j].assign(static_cast<std::size_t>(segments), b.vertex(center + Vec3{0, 0, p.y}));
      continue;
    }
    for (int k = 0; k < segments; ++k) {
      const double a = 2.0 * kPi * k / segments;
      idx[j].push_back(b.vertex(center + Vec3{p.x * std::cos(a), p.x * std::sin(a), p.y}));
    }
  }
  const std::size_t spans = closed_profile ? profile.size() : profile.size() - 1;
  for (std::size_t j = 0; j < spans; ++j) {
    const std::size_t j1 = (j + 1) % profile.size();
    for (int k = 0; k < segments; ++k) {
      const auto k0 = static_cast<std::size_t>(k),
                 k1 = static_cast<std::size_t>((k + 1) % segments);
      const std::uint32_t a = idx[j][k0], bb = idx[j1][k0], c = idx[j1][k1], d = idx[j][k1];
      if (profile[j].x != 0.0 && profile[j1].x != 0.0)
        b.quad(a, bb, c, d);
      else if (profile[j].x == 0.0 && profile[j1].x != 0.0)
        b.tri(a, bb, c);
      else if (profile[j].x != 0.0)
        b.tri(a, c, d);
    }
  }
  return idx;
}

// Points of the circular arc about c of radius r from angle a0 to a1 (radians, either
// direction), both ends included, about `step` radians apart.
void append_arc(std::vector<Vec2>& out, Vec2 c, double r, double a0, double a1, double step,
                bool include_first) {
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(a1 - a0) / step)));
  for (int i = include_first ? 0 : 1; i <= n; ++i) {
    const double a = a0 + (a1 - a0) * i / n;
    out.push_back(c + Vec2{r * std::cos(a), r * std::sin(a)});
  }
}

}  // namespace

Mesh make_box(const Box3& box) {
  Builder b;
  std::uint32_t v[8];
  for (int i = 0; i < 8; ++i)
    v[i] = b.vertex({(i & 1) ? box.max.x : box.min.x, (i & 2) ? box.max.y : box.min.y,
                     (i & 4) ? box.max.z : box.min.z});
  b.quad(v[0], v[2], v[3], v[1]);  // bottom, -z
  b.quad(v[4], v[5], v[7], v[6]);  // top, +z
  b.quad(v[0], v[1], v[5], v[4]);  // front, -y
  b.quad(v[2], v[6], v[7], v[3]);  // back, +y
  b.quad(v[0], v[4], v[6], v[2]);  // left, -x
  b.quad(v[1], v[3], v[7], v[5]);  // right, +x
  return b.take();
}

Mesh make_cylinder(Vec3 base, double radius, double height, int segments) {
  segments = std::max(segments, 3);
  Builder b;
  revolve(b, base, {{0, height}, {radius, height}, {radius, 0}, {0, 0}}, false, segments);
  return b.take();
}

Mesh make_sphere(Vec3 center, double radius, int segments) {
  segments = std::max(segments, 4);
  const int rings = segments / 2;
  std::vector<Vec2> profile;
  for (int j = 0; j <= rings; ++j) {
    const double phi = kPi * j / rings;  // from the north pole down
    profile.push_back(
        {(j == 0 || j == rings) ? 0.0 : radius * std::sin(phi), radius * std::cos(phi)});
  }
  Builder b;
  revolve(b, center, profile, false, segments);
  return b.take();
}

Mesh make_torus(Vec3 center, double major, double minor, int major_segments, int minor_segments) {
  major_segments = std::max(major_segments, 3);
  minor_segments = std::max(minor_segments, 3);
  std::vector<Vec2> profile;
  for (int j = 0; j < minor_segments; ++j) {
    const double phi = -2.0 * kPi * j / minor_segments;  // clockwise: over the top outwards
    profile.push_back({major + minor * std::cos(phi), minor * std::sin(phi)});
  }
  Builder b;
  revolve(b, center, profile, true, major_segments);
  return b.take();
}

Mesh make_filleted_torus_part(const FilletedTorusPart& part) {
  // Profile in the (rho, z) half-plane: the tube circle about C = (R, r) rests on the plate
  // top z = 0. A fillet of radius f is a circle tangent to the plate (centre height f) and
  // externally tangent to the tube (centre distance r + f), so its centre lies at
  // rho = R -+ d with d^2 + (r - f)^2 = (r + f)^2, i.e. d = 2 sqrt(r f); it touches the
  // plate at (R -+ d, 0) and the tube on the line between the two centres.
  const double R = part.major_radius, r = std::max(part.minor_radius, 1e-3);
  const double half = 0.5 * part.plate_size;
  // Keep the inner fillet off the axis and the outer one on the plate (clamping the radii
  // rather than building a self-intersecting part).
  const double fi = std::clamp(part.inner_fillet, 1e-3, 0.99 * R * R / (4.0 * r));
  const double max_do = 0.99 * (half - R);
  const double fo = std::clamp(part.outer_fillet, 1e-3, max_do * max_do / (4.0 * r));
  const double di = 2.0 * std::sqrt(r * fi), d_o = 2.0 * std::sqrt(r * fo);
  const Vec2 c{R, r}, ci{R - di, fi}, co{R + d_o, fo};
  const int segments = std::max(part.segments, 8);
  const double step = 2.0 * kPi / segments;

  std::vector<Vec2> profile{{0.0, 0.0}};  // the plate top inside the ring, a pole
  profile.push_back({R - di, 0.0});
  // Inner fillet: from straight below its centre, counter-clockwise to the tube tangency.
  const double ai = std::atan2(c.y - ci.y, c.x - ci.x);
  append_arc(profile, ci, fi, -0.5 * kPi, ai, step, false);
  // Tube: from the inner tangency clockwise over the top to the outer one.
  const double ti = std::atan2(ci.y - c.y, ci.x - c.x);  // lower left: negative
  const double to = std::atan2(co.y - c.y, co.x - c.x);
  const double ti_unwrapped = ti < 0.0 ? ti + 2.0 * kPi : ti;
  append_arc(profile, c, r, ti_unwrapped, to, step, false);
  // Outer fillet: from the tube tangency counter-clockwise down to the plate.
  const double ao = std::atan2(c.y - co.y, c.x - co.x);
  append_arc(profile, co, fo, ao, 1.5 * kPi, step, false);
  profile.back() = {R + d_o, 0.0};  // exactly on the plate
  Builder b;
  const auto idx = revolve(b, {}, profile, false, segments);
  const std::vector<std::uint32_t>& rim = idx.back();  // circle rho = R + d_o on the plate

  // Plate top outside the ring: between the rim circle and the square, with the square's
  // points on the rays of the rim's vertices plus the four corners.
  const double t = std::max(part.plate_thickness, 1e-3);
  auto snap = [&](double v) {
    return std::abs(std::abs(v) - half) < 1e-9 * half ? std::copysign(half, v) : v;
  };
  std::vector<Vec2> square;         // boundary, counter-clockwise
  std::vector<std::size_t> on_ray;  // index in `square` of the point on ray k
  for (int k = 0; k < segments; ++k) {
    const double a = 2.0 * kPi * k / segments, a_next = 2.0 * kPi * (k + 1) / segments;
    const Vec2 dir{std::cos(a), std::sin(a)};
    const double s = half / std::max(std::abs(dir.x), std::abs(dir.y));
    on_ray.push_back(square.size());
    square.push_back({snap(dir.x * s), snap(dir.y * s)});
    // A corner strictly between this ray and the next (tolerance: a ray through a corner
    // already produced it, snapped exactly).
    for (int q = 0; q < 5; ++q) {
      const double ac = (0.25 + 0.5 * q) * kPi;
      if (ac > a + 1e-12 && ac < a_next - 1e-12)
        square.push_back({std::cos(ac) > 0 ? half : -half, std::sin(ac) > 0 ? half : -half});
    }
  }
  on_ray.push_back(square.size());
  std::vector<std::uint32_t> top, bottom;
  for (const Vec2& p : square)
    top.push_back(b.vertex({p.x, p.y, 0.0}));
  for (const Vec2& p : square)
    bottom.push_back(b.vertex({p.x, p.y, -t}));
  // Cell k: rim_k -> square points from ray k to ray k+1 -> rim_k+1, fanned from rim_k.
  for (std::size_t k = 0; k < static_cast<std::size_t>(segments); ++k) {
    const std::uint32_t r0 = rim[k], r1 = rim[(k + 1) % rim.size()];
    for (std::size_t i = on_ray[k]; i < on_ray[k + 1]; ++i)
      b.tri(r0, top[i], top[(i + 1) % top.size()]);
    b.tri(r0, top[on_ray[k + 1] % top.size()], r1);
  }
  // Side walls and bottom.
  const std::uint32_t bottom_center = b.vertex({0.0, 0.0, -t});
  for (std::size_t i = 0; i < top.size(); ++i) {
    const std::size_t j = (i + 1) % top.size();
    b.quad(top[i], bottom[i], bottom[j], top[j]);
    b.tri(bottom_center, bottom[j], bottom[i]);
  }
  return b.take();
}

Mesh make_block_with_bosses(Vec3 size, double boss_size, double boss_height) {
  // A height field on a 5 x 5 grid of cells: the block, with the four cells centred on the
  // quarter points raised by boss_height. Every wall and face is made from shared grid
  // vertices, so the mesh is closed without T-junctions. Min corner at the origin.
  const double sx = std::max(size.x, 1e-3), sy = std::max(size.y, 1e-3),
               sz = std::max(size.z, 1e-3);
  const double bs = std::clamp(boss_size, 1e-3, 0.45 * std::min(sx, sy));
  const double bh = std::max(boss_height, 0.0);
  const double xs[6] = {
      0, 0.25 * sx - 0.5 * bs, 0.25 * sx + 0.5 * bs, 0.75 * sx - 0.5 * bs, 0.75 * sx + 0.5 * bs,
      sx};
  const double ys[6] = {
      0, 0.25 * sy - 0.5 * bs, 0.25 * sy + 0.5 * bs, 0.75 * sy - 0.5 * bs, 0.75 * sy + 0.5 * bs,
      sy};
  auto cell_height = [&](int i, int j) {
    return ((i == 1 || i == 3) && (j == 1 || j == 3) && bh > 0.0) ? sz + bh : sz;
  };
  Builder b;
  // Vertex (i, j) at z: created once per distinct height.
  std::vector<std::vector<std::vector<std::pair<double, std::uint32_t>>>> grid(
      6, std::vector<std::vector<std::pair<double, std::uint32_t>>>(6));
  auto v = [&](int i, int j, double z) {
    auto& list = grid[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)];
    for (const auto& [zz, id] : list)
      if (zz == z) return id;
    const std::uint32_t id = b.vertex({xs[i], ys[j], z});
    list.emplace_back(z, id);
    return id;
  };
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const double h = cell_height(i, j);
      b.quad(v(i, j, h), v(i + 1, j, h), v(i + 1, j + 1, h), v(i, j + 1, h));  // top, +z
      b.quad(v(i, j, 0), v(i, j + 1, 0), v(i + 1, j + 1, 0), v(i + 1, j, 0));  // bottom, -z
    }
  // Walls along x = xs[i] between cell (i-1, j) (height hl) and cell (i, j) (height hr);
  // outside the block the height is 0. The wall faces the lower side.
  for (int i = 0; i <= 5; ++i)
    for (int j = 0; j < 5; ++j) {
      const double hl = i > 0 ? cell_height(i - 1, j) : 0.0, hr = i < 5 ? cell_height(i, j) : 0.0;
      if (hl == hr) continue;
      const double lo = std::min(hl, hr), hi = std::max(hl, hr);
      if (hl > hr)  // faces +x
        b.quad(v(i, j, lo), v(i, j + 1, lo), v(i, j + 1, hi), v(i, j, hi));
      else  // faces -x
        b.quad(v(i, j, lo), v(i, j, hi), v(i, j + 1, hi), v(i, j + 1, lo));
    }
  for (int j = 0; j <= 5; ++j)
    for (int i = 0; i < 5; ++i) {
      const double hl = j > 0 ? cell_height(i, j - 1) : 0.0, hr = j < 5 ? cell_height(i, j) : 0.0;
      if (hl == hr) continue;
      const double lo = std::min(hl, hr), hi = std::max(hl, hr);
      if (hl > hr)  // faces +y
        b.quad(v(i, j, lo), v(i, j, hi), v(i + 1, j, hi), v(i + 1, j, lo));
      else  // faces -y
        b.quad(v(i, j, lo), v(i + 1, j, lo), v(i + 1, j, hi), v(i, j, hi));
    }
  return b.take();
}

}  // namespace swarf
