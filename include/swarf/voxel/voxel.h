// The voxel part model of seed 003 section 2.2: columns of Δx x Δy (= the stepover) cells
// over the stock, each holding the z intervals in which the part is solid (found by ray
// parity along z through the column centre), cut into layers of Δz (= the stepdown).
// A run-length column is the same model as the paper's 3D 0/1 array, without its memory.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/core/vec.h"
#include "swarf/mesh/mesh.h"

namespace swarf {

struct VoxelizeOptions {
  double cell_mm = 6.6;   ///< Δx = Δy, the stepover (section 2.2)
  double layer_mm = 2.0;  ///< Δz, the stepdown
  /// Stock box; empty = the part's box grown by margin_mm sideways and top_margin_mm on top.
  Box3 stock;
  double margin_mm = 0.0;
  double top_margin_mm = 0.0;
  /// Open meshes, found as columns that cross the surface an odd number of times (where
  /// parity is meaningless; a hole no column ray passes through changes nothing): false =
  /// Error::kOpenMesh; true = repaired conservatively (such a column is solid from its
  /// lowest to its highest crossing) with a warning. The exact cell tops, which decide
  /// where the tool may go, come from the triangles and need no closed mesh.
  bool repair_open = false;
  /// The exact part tops are kept on squares of cell_mm / top_subdivisions, so that the
  /// tool offset is conservative by that much instead of by a whole cell.
  int top_subdivisions = 1;
};

Status validate(const VoxelizeOptions& options);

struct VoxelModel {
  int nx = 0, ny = 0;  ///< columns
  int layers = 0;      ///< layer 0 is the top one
  double cell_mm = 0.0, layer_mm = 0.0;
  /// Centre of column (0, 0); column (i, j) is centred at origin + (i, j) * cell_mm.
  Vec2 origin;
  Box3 stock;
  /// Per column (index j * nx + i), crossings with the part surface along the centre ray,
  /// sorted upwards; solid between crossings 2m and 2m+1 (CSR: column c uses
  /// crossings[offsets[c] .. offsets[c+1])).
  std::vector<std::uint32_t> offsets;
  std::vector<double> crossings;
  /// Highest point of the part over each closed top square, exact (the triangles clipped
  /// to the square); -infinity where the part does not reach it. Top squares are cells
  /// split top_sub x top_sub ways: square (u, v) (index v * nx * top_sub + u) spans
  /// x from origin.x - cell_mm / 2 + u * cell_mm / top_sub, one top_sub-th of a cell wide.
  /// This is what makes the model conservative between column centres.
  int top_sub = 1;
  std::vector<double> cell_top;
  std::vector<std::string> warnings;

  std::size_t column(int i, int j) const {
    return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i);
  }
  Vec2 centre(int i, int j) const { return origin + Vec2{i * cell_mm, j * cell_mm}; }
  /// Tool tip height of layer k: the bottom of its slab, not below the stock bottom.
  double layer_z(int k) const;
  /// Top of layer k's slab.
  double layer_top(int k) const { return stock.max.z - k * layer_mm; }
  /// Seed 003 Fig. 2: voxel (i, j, k) is 1 (non-machinable) when the part's solid along the
  /// centre ray overlaps the slab of layer k.
  bool filled(int i, int j, int k) const;
  /// Top of the part along the centre ray (-infinity when the ray misses it).
  double centre_top(int i, int j) const;
};

/// Voxelizes a closed mesh (section 2.2). Rays through vertices and edges are decided by
/// symbolic perturbation (the ray is moved by (ε, ε²)), with each edge's side test evaluated
/// in one canonical vertex order, so a ray through an edge shared by two triangles counts
/// exactly once. Parallel over rows; identical for any thread count.
Result<VoxelModel> voxelize(const Mesh& part, const VoxelizeOptions& options,
                            const Context& ctx = default_context());

/// Open and non-manifold edges, welding vertices by exact coordinates (independent of
/// the mesh's own indexing).
struct EdgeCheck {
  std::size_t open_edges = 0;
  std::size_t non_manifold_edges = 0;
};
EdgeCheck check_edges(const Mesh& mesh);

/// p' = R_z(angle) p about the origin (used by the orientation study, section 3.1.1).
Mesh rotate_about_z(const Mesh& mesh, double angle_deg);

}  // namespace swarf
