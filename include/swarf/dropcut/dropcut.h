// Exact drop-cutter: the highest tool-tip height at which a cutter held vertically over (x, y)
// touches a triangle mesh. Ball, flat and bull-nose end mills, through the cutter profile of
// swarf/tool/tool.h (OpenCAMLib's split: a drop against a vertex, an edge and a facet).
//
// It is both a 3-axis strategy of its own (`swarf dropcut`) and the truth against which the
// tri-slice scanning paths of seed 001 are measured (Table 3).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/core/vec.h"
#include "swarf/mesh/mesh.h"
#include "swarf/mesh/slice.h"
#include "swarf/tool/tool.h"

namespace swarf {

/// Which feature of the mesh holds the tool up.
enum class ContactKind : std::uint8_t { kNone, kVertex, kEdge, kFacet };

struct DropResult {
  /// Tool-tip height, mm; -infinity when no triangle lies under the tool.
  double tip_z = -std::numeric_limits<double>::infinity();
  ContactKind contact = ContactKind::kNone;
  /// Triangle that gave the contact (for a shared vertex or edge: one of them).
  std::size_t triangle = 0;
  bool hit() const { return contact != ContactKind::kNone; }
};

struct DropCutterOptions {
  /// Side of the square cells of the spatial index, mm; 0 = a quarter of the tool radius
  /// (at least 1/2048 of the mesh's larger side), enlarged when the index would exceed
  /// `max_index_entries`.
  double cell_size_mm = 0.0;
  std::size_t max_index_entries = std::size_t{48} << 20;
};

/// The cutter's geometry, as the drop-cutter sees it.
struct CutterShape {
  double radius_mm = 4.0;         ///< R
  double corner_radius_mm = 4.0;  ///< 0 flat, R ball, in between bull-nose
  static CutterShape from(const Tool& tool) {
    return {tool.radius(),
            tool.kind == ToolKind::kFlat
                ? 0.0
                : (tool.kind == ToolKind::kBall ? tool.radius() : tool.corner_radius_mm)};
  }
};

/// A mesh prepared for dropping one cutter: per-triangle planes and a uniform xy grid in
/// which every triangle is listed in the cells its xy box overlaps, highest first, with each
/// cell's highest z. A query walks the cells within the tool radius, skips a cell whose top,
/// at the cell's nearest distance, cannot beat the contact found so far, and stops inside a
/// cell at the first triangle that cannot.
class DropCutter {
 public:
  /// Fails on an empty mesh, non-finite coordinates or an invalid cutter.
  static Result<DropCutter> build(const Mesh& mesh, const CutterShape& cutter,
                                  const DropCutterOptions& options = {});
  static Result<DropCutter> build(const Mesh& mesh, const Tool& tool,
                                  const DropCutterOptions& options = {}) {
    return build(mesh, CutterShape::from(tool), options);
  }

  DropResult drop(Vec2 p) const;
  /// The same tip height, trying triangle `hint` first (e.g. the previous point's contact
  /// along a line): a good first contact lets the sorted list stop far sooner. Any index
  /// is allowed; on an exact tie the contact kind and triangle may differ from drop(p).
  DropResult drop(Vec2 p, std::size_t hint) const;
  double drop_z(Vec2 p) const { return drop(p).tip_z; }
  /// The same answer without the index or the early stop: every triangle is tried.
  /// For tests and for checking the index.
  DropResult drop_brute_force(Vec2 p) const;

  const CutterShape& cutter() const { return cutter_; }
  std::size_t triangle_count() const { return tris_.size(); }
  std::size_t index_entries() const { return cell_items_.size(); }
  double cell_size_mm() const { return cell_; }
  const Box3& mesh_bounds() const { return bounds_; }

  struct Tri {
    std::array<Vec3, 3> p;
    Vec3 n;          ///< unit normal with n.z >= 0 (orientation does not matter to a drop)
    double d = 0.0;  ///< plane: dot(n, x) = d
    double zmax = 0.0;
    Box2 box;
  };

 private:
  void test_triangle(const Tri& t, std::size_t index, Vec2 p, DropResult& best) const;

  CutterShape cutter_;
  std::vector<Tri> tris_;
  Box3 bounds_;
  double cell_ = 1.0;
  Vec2 origin_;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> cell_start_;  ///< CSR: cell c holds cell_items_[start[c], start[c+1])
  std::vector<std::uint32_t> cell_items_;
  std::vector<double> cell_zmax_;  ///< highest triangle z per cell (-infinity when empty)
};

/// A raster of CL points: lines along `direction` (kX: lines at constant y, points along x),
/// `stepover_mm` apart, points `sampling_mm` apart, both from region.min to region.max
/// inclusive (the last step may be shorter so the far edge is always included).
struct ClGrid {
  Box2 region;
  Axis direction = Axis::kX;
  double stepover_mm = 0.5;
  double sampling_mm = 0.1;

  std::vector<double> line_positions() const;   ///< across the lines
  std::vector<double> point_positions() const;  ///< along one line
};
Status validate(const ClGrid& grid);

/// Positions from `from` to `to` inclusive at `step` (last step shorter when needed).
std::vector<double> grid_positions(double from, double to, double step);

/// CL points (tool tip) of every grid point, line after line, parallel over lines; points
/// with nothing under the tool get z = `floor_z`. Identical for any thread count.
Result<std::vector<Vec3>> drop_grid(const DropCutter& cutter, const ClGrid& grid, double floor_z,
                                    const Context& ctx = default_context());

}  // namespace swarf
