// seed 001 section 2.1: the tri-slice model. Every family's slices sit on the lattice
// k * pitch (k integer), so the families of a part, of its offsets and of a stock block line up
// and a scan line at a multiple of the pitch falls exactly on a slice.
#include "swarf/trislice/model.h"

#include <cmath>
#include <string>

namespace swarf {
namespace {

// Lattice indices k with k * pitch inside [lo, hi].
void lattice(double lo, double hi, double pitch, long& k0, long& k1) {
  k0 = static_cast<long>(std::ceil(lo / pitch - 1e-9));
  k1 = static_cast<long>(std::floor(hi / pitch + 1e-9));
}

}  // namespace

Result<TriSliceModel> build_trislice(const Mesh& mesh, double pitch_mm, const Box3& region,
                                     const Context& ctx) {
  return build_trislice_families(mesh, pitch_mm, {true, true, true}, region, ctx);
}

Result<TriSliceModel> build_trislice_families(const Mesh& mesh, double pitch_mm,
                                              const std::array<bool, 3>& families,
                                              const Box3& region, const Context& ctx) {
  if (!(pitch_mm > 0.0) || !std::isfinite(pitch_mm))
    return bad_parameter("tri-slice: pitch " + std::to_string(pitch_mm) + " mm must be positive");
  if (mesh.empty()) return bad_input("tri-slice: the mesh has no triangles");
  TriSliceModel model;
  model.pitch_mm = pitch_mm;
  model.bounds = region.empty() ? swarf::bounds(mesh) : region;
  const Vec3 ext = model.bounds.size();
  const double count = (ext.x + ext.y + ext.z) / pitch_mm;
  if (count > 2e6)
    return bad_parameter("tri-slice: pitch " + std::to_string(pitch_mm) + " mm gives " +
                         std::to_string(static_cast<long>(count)) + " slices (limit 2 million)");
  std::array<std::vector<double>, 3> levels;
  for (int a = 0; a < 3; ++a) {
    const auto axis = static_cast<Axis>(a);
    SliceFamily& fam = model.family(axis);
    fam.axis = axis;
    fam.pitch_mm = pitch_mm;
    long k0 = 0, k1 = -1;
    lattice(model.bounds.min[a], model.bounds.max[a], pitch_mm, k0, k1);
    fam.first_level = static_cast<double>(k0) * pitch_mm;
    if (!families[static_cast<std::size_t>(a)]) continue;
    for (long k = k0; k <= k1; ++k)
      levels[static_cast<std::size_t>(a)].push_back(static_cast<double>(k) * pitch_mm);
  }
  // The three families in one call: one edge table, one parallel loop over all slices.
  auto slices = slice_mesh_axes(mesh, levels, {}, ctx);
  if (ctx.cancelled()) return Status{Error::kCancelled, "tri-slice: cancelled"};
  for (std::size_t a = 0; a < 3; ++a)
    model.families[a].slices = std::move(slices[a]);
  ctx.report("tri-slice model", 1.0);
  return model;
}

TriSliceModel trislice_block(const Box3& block, double pitch_mm) {
  TriSliceModel model;
  model.pitch_mm = pitch_mm;
  model.bounds = block;
  if (block.empty() || !(pitch_mm > 0.0)) return model;
  for (int a = 0; a < 3; ++a) {
    const auto axis = static_cast<Axis>(a);
    SliceFamily& fam = model.family(axis);
    fam.axis = axis;
    fam.pitch_mm = pitch_mm;
    long k0 = 0, k1 = -1;
    lattice(block.min[a], block.max[a], pitch_mm, k0, k1);
    fam.first_level = static_cast<double>(k0) * pitch_mm;
    const Vec2 lo = to_plane(block.min, axis), hi = to_plane(block.max, axis);
    PolygonSet rect;
    rect.rings.push_back({{lo.x, lo.y}, {hi.x, lo.y}, {hi.x, hi.y}, {lo.x, hi.y}});
    rect = normalized(rect);
    fam.slices.assign(static_cast<std::size_t>(std::max(0L, k1 - k0 + 1)), rect);
  }
  return model;
}

}  // namespace swarf
