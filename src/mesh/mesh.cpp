#include "swarf/mesh/mesh.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <unordered_map>

namespace swarf {
namespace {

// Exact-coordinate key; -0.0 is folded into +0.0 so that both weld together.
struct VertexKey {
  std::uint64_t x, y, z;
  bool operator==(const VertexKey&) const = default;
};
std::uint64_t bits(double v) {
  v += 0.0;  // -0.0 + 0.0 == +0.0
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}
struct VertexKeyHash {
  std::size_t operator()(const VertexKey& k) const {
    std::uint64_t h = k.x * 0x9E3779B97F4A7C15ull;
    h ^= (k.y + 0x7F4A7C159E3779B9ull + (h << 6) + (h >> 2));
    h ^= (k.z + 0x94D049BB133111EBull + (h << 6) + (h >> 2));
    return static_cast<std::size_t>(h ^ (h >> 31));
  }
};

}  // namespace

Box3 bounds(const Mesh& mesh) {
  Box3 b;
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      b.add(mesh.vertices[t[k]]);
  return b;
}

Mesh weld(const std::vector<std::array<Vec3, 3>>& soup) {
  // The hash map is only looked up, never iterated, so the vertex order is the order of first
  // appearance in the soup and does not depend on the hash.
  Mesh mesh;
  mesh.triangles.reserve(soup.size());
  std::unordered_map<VertexKey, std::uint32_t, VertexKeyHash> index;
  index.reserve(soup.size());
  for (const auto& tri : soup) {
    std::array<std::uint32_t, 3> t{};
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = tri[k];
      const auto [it, inserted] =
          index.try_emplace(VertexKey{bits(p.x), bits(p.y), bits(p.z)},
                            static_cast<std::uint32_t>(mesh.vertices.size()));
      if (inserted) mesh.vertices.push_back({p.x + 0.0, p.y + 0.0, p.z + 0.0});
      t[k] = it->second;
    }
    mesh.triangles.push_back(t);
  }
  return mesh;
}

MeshCheck check_mesh(const Mesh& mesh) {
  MeshCheck c;
  c.triangles = mesh.size();
  // Every directed edge as (undirected key, direction); sorting groups the uses of an edge.
  struct EdgeUse {
    std::uint64_t key;
    bool forward;  ///< lower vertex index first
    bool operator<(const EdgeUse& o) const {
      return key != o.key ? key < o.key : forward < o.forward;
    }
  };
  std::vector<EdgeUse> uses;
  uses.reserve(3 * mesh.size());
  const Vec3 origin = bounds(mesh).center();
  double six_volume = 0.0;
  for (const auto& t : mesh.triangles) {
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c3 = mesh.vertices[t[2]];
    const Vec3 n = cross(b - a, c3 - a);
    const double longest = std::max({norm_sq(b - a), norm_sq(c3 - b), norm_sq(a - c3)});
    // Zero area relative to the triangle's size: exact collinearity survives float rounding
    // only approximately, so allow a relative 1e-12 (area ~ 1e-6 of the edge length squared).
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || norm(n) <= 1e-12 * longest)
      ++c.degenerate_triangles;
    six_volume += dot(a - origin, cross(b - origin, c3 - origin));
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = t[k], v = t[(k + 1) % 3];
      if (u == v) continue;
      const std::uint32_t lo = std::min(u, v), hi = std::max(u, v);
      uses.push_back({(std::uint64_t{lo} << 32) | hi, u < v});
    }
  }
  c.volume_mm3 = six_volume / 6.0;
  std::sort(uses.begin(), uses.end());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    std::size_t forward = 0;
    while (j < uses.size() && uses[j].key == uses[i].key)
      forward += uses[j++].forward ? 1 : 0;
    const std::size_t count = j - i;
    if (count == 1)
      ++c.open_edges;
    else if (count > 2)
      ++c.non_manifold_edges;
    else if (forward != 1)
      ++c.inconsistent_edges;
    i = j;
  }
  return c;
}

void append(Mesh& to, const Mesh& more) {
  const auto base = static_cast<std::uint32_t>(to.vertices.size());
  to.vertices.insert(to.vertices.end(), more.vertices.begin(), more.vertices.end());
  to.triangles.reserve(to.triangles.size() + more.triangles.size());
  for (const auto& t : more.triangles)
    to.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
}

Mesh transformed(const Mesh& mesh, double rotate_z_deg, Vec3 translation) {
  Mesh out = mesh;
  // Exact quarter turns keep exact coordinates (cos 90 deg is not exactly 0 in floating point).
  double c = std::cos(deg_to_rad(rotate_z_deg)), s = std::sin(deg_to_rad(rotate_z_deg));
  const double turns = rotate_z_deg / 90.0;
  if (std::abs(turns) < 1e9 && turns == std::round(turns)) {
    const long q = ((static_cast<long>(std::round(turns)) % 4) + 4) % 4;
    const double cs[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
    c = cs[q];
    s = sn[q];
  }
  for (Vec3& p : out.vertices)
    p = Vec3{c * p.x - s * p.y, s * p.x + c * p.y, p.z} + translation;
  return out;
}

}  // namespace swarf
