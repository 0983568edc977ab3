// The tri-slice model of seed 001 (section 2): a solid held as three families of 2D polygon
// slices, cut by planes normal to x, y and z at a common pitch. Slice j of a family lies at
// level first_level + j * pitch, in the in-plane coordinates of swarf/mesh/slice.h.
#pragma once

#include <array>
#include <vector>

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/mesh/mesh.h"
#include "swarf/mesh/slice.h"
#include "swarf/polygon/polygon.h"

namespace swarf {

struct SliceFamily {
  Axis axis = Axis::kZ;
  double first_level = 0.0;  ///< level of slice 0, mm
  double pitch_mm = 0.1;
  std::vector<PolygonSet> slices;

  double level(std::size_t j) const { return first_level + static_cast<double>(j) * pitch_mm; }
  std::size_t size() const { return slices.size(); }
};

struct TriSliceModel {
  /// Indexed by Axis: families[0] normal to x (yz planes), [1] normal to y (zx), [2] to z (xy).
  std::array<SliceFamily, 3> families;
  Box3 bounds;
  double pitch_mm = 0.1;

  const SliceFamily& family(Axis a) const { return families[static_cast<int>(a)]; }
  SliceFamily& family(Axis a) { return families[static_cast<int>(a)]; }
};

/// Slices `mesh` in all three families at `pitch_mm` over `region` (the mesh's bounds when
/// empty), in parallel over slices; results do not depend on ctx.threads.
Result<TriSliceModel> build_trislice(const Mesh& mesh, double pitch_mm, const Box3& region = {},
                                     const Context& ctx = default_context());

/// As build_trislice, slicing only the families marked (indexed by Axis); the others stay
/// empty. Scanning paths need the x and y families only, waterlines the z family.
Result<TriSliceModel> build_trislice_families(const Mesh& mesh, double pitch_mm,
                                              const std::array<bool, 3>& families,
                                              const Box3& region = {},
                                              const Context& ctx = default_context());

/// A rectangular block as a tri-slice model (the usual stock), exact at any pitch.
TriSliceModel trislice_block(const Box3& block, double pitch_mm);

}  // namespace swarf
