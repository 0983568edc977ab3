// Slicing a mesh by families of parallel planes into polygon sets.
#pragma once

#include <array>
#include <vector>

#include "swarf/core/context.h"
#include "swarf/mesh/mesh.h"
#include "swarf/polygon/polygon.h"

namespace swarf {

enum class Axis { kX = 0, kY = 1, kZ = 2 };

/// In-plane coordinates of a slice normal to `axis`, cyclic so that every family is
/// right-handed: kZ -> (x, y), kX -> (y, z), kY -> (z, x). An outer boundary of a closed,
/// outward-oriented mesh comes out counter-clockwise in these coordinates.
Vec2 to_plane(Vec3 p, Axis axis);
/// Inverse of to_plane for a point at `level` along `axis`.
Vec3 from_plane(Vec2 uv, double level, Axis axis);

struct SliceOptions {
  /// Join open chains (from open meshes) whose ends lie within this distance, mm.
  double gap_tolerance_mm = 1e-4;
};

/// Cuts `mesh` by the planes {axis = level} for each level, in parallel over levels
/// (results do not depend on ctx.threads). Vertices and edges lying exactly on a plane are
/// handled by symbolic perturbation (a vertex on the plane counts as above it), so every
/// loop closes on a closed mesh. Result i is the normalized cross-section at levels[i].
std::vector<PolygonSet> slice_mesh(const Mesh& mesh, Axis axis, const std::vector<double>& levels,
                                   const SliceOptions& options = {},
                                   const Context& ctx = default_context());

/// slice_mesh for the three axes at once (result a: the levels[a] cut normal to axis a), with
/// the mesh's edge table built once and one parallel loop over all levels. Same sections as
/// three calls of slice_mesh.
std::array<std::vector<PolygonSet>, 3> slice_mesh_axes(
    const Mesh& mesh, const std::array<std::vector<double>, 3>& levels,
    const SliceOptions& options = {}, const Context& ctx = default_context());

/// Evenly spaced levels from `from` to `to` (both inside the range) at `pitch`, centred so
/// that the margins at both ends are equal.
std::vector<double> slice_levels(double from, double to, double pitch);

}  // namespace swarf
