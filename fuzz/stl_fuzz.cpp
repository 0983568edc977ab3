// libFuzzer target for the STL reader: parse_stl must never crash, hang or read out of bounds
// on any input, and what it accepts must be a valid indexed mesh. Accepted meshes are also
// sliced, which exercises the slicer on degenerate and non-manifold meshes.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "swarf/mesh/slice.h"
#include "swarf/mesh/stl.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  const swarf::Result<swarf::StlFile> file = swarf::parse_stl(bytes, "fuzz.stl");
  if (!file.ok()) {
    if (file.status().message().empty()) std::abort();  // every rejection must say why
    return 0;
  }
  const swarf::Mesh& mesh = file->mesh;
  if (mesh.empty()) std::abort();  // empty meshes must be rejected
  for (const auto& t : mesh.triangles)
    for (std::uint32_t v : t)
      if (v >= mesh.vertices.size()) std::abort();
  if (mesh.size() > 2000) return 0;  // keep each run fast
  const swarf::Box3 b = swarf::bounds(mesh);
  swarf::Context ctx;
  ctx.threads = 1;
  const std::vector<double> levels{b.min.z, b.center().z, b.max.z, 0.0};
  (void)swarf::slice_mesh(mesh, swarf::Axis::kZ, levels, {}, ctx);
  (void)swarf::slice_mesh(mesh, swarf::Axis::kX, {b.center().x}, {}, ctx);
  return 0;
}
