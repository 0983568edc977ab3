// Exact contacts with the mesh itself for the tri-slice scans (ScanParams::vertex_mesh): where
// the slices are first-order wrong or miss a contact altogether.
#pragma once

#include <cstdint>
#include <vector>

#include "swarf/core/vec.h"
#include "swarf/mesh/mesh.h"

namespace swarf::trislice_detail {

/// The mesh's vertices and its fold edges as exact contacts of a ball of radius R.
///
/// Vertices: the slices miss a sharp convex vertex lying between them by up to about a pitch
/// (a box corner off the slice lattice: 30 um at 0.05 mm).
///
/// Fold edges, where the surface turns under as seen from above (the two faces lie on the
/// same side of the edge in the xy projection, or one is vertical: the rim of a wall, the
/// equator of a torus or sphere): a ball beside such an edge either rests on it or falls past
/// it, so the CL jumps there by up to the height of what lies below. A ball grazing the edge
/// reaches it over a patch as narrow as one likes, which the slices can step over: on the
/// Table 2 part at 0.05 mm a point 3.9999 mm from the outer equator dropped 5.9 mm onto the
/// plate. Taking those edges exactly closes that gap; everywhere else the slices' error is
/// second-order and the edges change nothing.
class MeshContacts {
 public:
  MeshContacts(const Mesh& mesh, double radius_mm);
  /// The highest centre over p of a ball of radius R resting on a vertex or a fold edge, or
  /// `best` when none beats it.
  double centre_height(Vec2 p, double R, double best) const;
  std::size_t fold_edge_count() const { return edges_.size(); }

 private:
  double vertex_height(Vec2 p, double R, double best) const;
  double edge_height(Vec2 p, double R, double best) const;

  // Vertices: cells of R / 8, highest first.
  double cell_ = 1.0;
  Vec2 origin_;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> start_;
  std::vector<Vec3> pts_;
  std::vector<double> cellmax_;
  // Fold edges: listed in the cells they cross, highest end first.
  struct Edge {
    Vec3 a, b;
    Box2 box;
    double zmax;
  };
  std::vector<Edge> edges_;
  double ecell_ = 1.0;
  Vec2 eorigin_;
  int enx_ = 0, eny_ = 0;
  std::vector<std::uint32_t> estart_, eitems_;
  std::vector<double> ecellmax_;
};

}  // namespace swarf::trislice_detail
