// Indexed triangle meshes in mm and their topology checks.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "swarf/core/vec.h"

namespace swarf {

/// Triangles as indices into a shared vertex list; counter-clockwise seen from outside.
struct Mesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::uint32_t, 3>> triangles;

  std::size_t size() const { return triangles.size(); }
  bool empty() const { return triangles.empty(); }
  /// Corner k (0..2) of triangle t.
  const Vec3& corner(std::size_t t, int k) const { return vertices[triangles[t][k]]; }
};

Box3 bounds(const Mesh& mesh);

/// Builds an indexed mesh from a triangle soup, merging vertices with identical coordinates.
Mesh weld(const std::vector<std::array<Vec3, 3>>& soup);

/// What a machinist needs to know about a mesh before trusting it as a solid.
struct MeshCheck {
  std::size_t triangles = 0;
  std::size_t degenerate_triangles = 0;  ///< zero area or repeated vertex
  std::size_t open_edges = 0;            ///< edges used by one triangle only
  std::size_t non_manifold_edges = 0;    ///< edges used by more than two triangles
  std::size_t inconsistent_edges = 0;    ///< edges whose two triangles disagree in orientation
  double volume_mm3 = 0.0;               ///< signed volume (divergence theorem)
  bool closed() const { return open_edges == 0 && non_manifold_edges == 0; }
};
MeshCheck check_mesh(const Mesh& mesh);

/// Adds `more`'s vertices and triangles to `to`, as a separate shell (nothing is welded:
/// overlapping solids stay overlapping; slicing unites them).
void append(Mesh& to, const Mesh& more);

/// Applies p' = R_z(angle) p + translation to every vertex.
Mesh transformed(const Mesh& mesh, double rotate_z_deg, Vec3 translation = {});

}  // namespace swarf
