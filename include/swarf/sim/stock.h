// The workpiece of a material-removal simulation (seed 001 section 3.3, Fig. 8-10): a
// tri-slice model (three families of polygon slices) from which the tool's swept cross-
// sections are subtracted, slice by slice, and against which cutting-edge points are tested.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/core/vec.h"
#include "swarf/mesh/mesh.h"
#include "swarf/tool/tool.h"
#include "swarf/trislice/model.h"

namespace swarf::sim {

/// How the three families' answers for one point combine (seed 001 Fig. 10b).
enum class EngagementRule {
  /// Inside when any family says inside: the paper's rule. Biased towards material by up to
  /// half a pitch on faces parallel to a family's planes (a slot floor for the xy slices).
  kAny,
  /// Inside when two of the three say so: the family whose planes are parallel to a face is
  /// outvoted by the two that cut the face exactly. The default; it does better than the
  /// paper's rule on flat floors and walls.
  kMajority,
};

/// The cutter as a solid of revolution with a cylinder above the corner that never ends
/// (the shank removes what it meets, as on the machine).
struct ToolSolid {
  double radius_mm = 4.0;
  double corner_radius_mm = 4.0;  ///< 0 flat, radius for ball
  /// Half-width of the solid at height h above the tip (0 below the tip).
  double width_at(double h) const;
};
ToolSolid tool_solid(const Tool& tool);

/// What one removal did.
struct Removal {
  /// Material removed, per family (indexed by Axis): the change of slice areas times pitch.
  std::array<double, 3> by_family_mm3{};
  /// The estimate reported: the median of the three families (each one is exact across its
  /// planes and a midpoint rule along its axis; the median drops the family that is worst
  /// off on faces parallel to its planes).
  double volume_mm3 = 0.0;
};

/// Top-view height map: top[iy * nx + ix] is the highest material at cell centre
/// (x0 + (ix + 0.5) cell, y0 + (iy + 0.5) cell), NaN where there is none.
struct HeightMap {
  double x0 = 0.0, y0 = 0.0, cell_mm = 0.1;
  int nx = 0, ny = 0;
  std::vector<float> top;
};

class Stock {
 public:
  /// A rectangular block. Slice j of each family lies at min + (j + 1/2) pitch, so the faces
  /// of the block (and of any cut at a whole number of pitches from them) fall on cell
  /// boundaries. This is sim's own block builder (the trislice area owns trislice_block).
  static Result<Stock> block(const Box3& box, double pitch_mm);
  /// A closed mesh sliced in the three families at `pitch_mm`, with the same level placement
  /// as block() over the mesh's bounds (slices through swarf/mesh/slice.h).
  static Result<Stock> from_mesh(const Mesh& mesh, double pitch_mm,
                                 const Context& ctx = default_context());
  /// "box:XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX" or the path of an STL file.
  static Result<Stock> from_spec(const std::string& spec, double pitch_mm,
                                 const Context& ctx = default_context());
  /// Any tri-slice model, e.g. an STL sliced by build_trislice. The three families must
  /// share one pitch.
  static Result<Stock> from_model(TriSliceModel model);

  const TriSliceModel& model() const { return model_; }
  double pitch_mm() const { return model_.pitch_mm; }
  const Box3& bounds() const { return model_.bounds; }

  /// Volume of material by one family (sum of slice areas times pitch), and the median of
  /// the three.
  double volume_mm3(Axis family) const;
  double volume_mm3() const;

  /// Inside test of one point against the nearest slice of one family (within pitch / 2):
  /// O(edges in one row) with a per-slice row index, rebuilt only when the slice changes.
  bool inside(Vec3 p, Axis family) const;
  bool inside(Vec3 p, EngagementRule rule) const;

  /// Subtracts the solid swept by the tool along the polyline of tip positions (each pair of
  /// consecutive points a straight move), only in the slices it reaches. The swept section
  /// in each slice plane is built exactly for horizontal moves (a stadium from
  /// inflate_polylines in xy slices; translated convex sections elsewhere) and from dense
  /// convex hulls of the sections along inclined moves; all sections of the polyline are
  /// united before one subtraction per slice. Parallel over slices, deterministic.
  Removal remove(const ToolSolid& tool, std::span<const Vec3> tips,
                 const Context& ctx = default_context());

  /// Height map of the material's top, from the yz slices, at the given cell size (empty
  /// for a cell that is not positive or would give more than 1e8 cells).
  HeightMap height_map(double cell_mm) const;

 private:
  struct SliceIndex {
    double v0 = 0.0, row_h = 1.0;
    std::vector<std::uint32_t> row_start;      ///< rows + 1 offsets into edges
    std::vector<std::array<double, 4>> edges;  ///< (ua, va, vb, du/dv) per row, duplicated
  };
  void rebuild_index(int family, std::size_t slice);
  double thickness(int family, std::size_t slice) const;
  bool inside_slice(int family, std::size_t slice, Vec2 uv) const;

  TriSliceModel model_;
  std::array<std::vector<double>, 3> areas_;
  std::array<std::vector<Box2>, 3> slice_bounds_;
  std::array<std::vector<SliceIndex>, 3> index_;
};

/// In-plane coordinates of each family (the convention of swarf/mesh/slice.h):
/// kZ -> (x, y), kX -> (y, z), kY -> (z, x).
Vec2 plane_coords(Vec3 p, Axis axis);

}  // namespace swarf::sim
