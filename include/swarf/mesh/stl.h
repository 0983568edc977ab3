// STL reading (binary and ASCII, detected from the content, not the first five bytes) and
// writing. Malformed files are rejected with a message naming the file and the place.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "swarf/core/status.h"
#include "swarf/mesh/mesh.h"

namespace swarf {

struct StlFile {
  Mesh mesh;
  MeshCheck check;
  bool binary = false;
  /// Non-fatal findings: open edges, degenerate triangles, normals disagreeing with winding.
  std::vector<std::string> warnings;
};

/// Parses STL bytes. `source_name` names the input in messages ("part.stl").
/// Rejects truncated files, wrong triangle counts, NaN/inf coordinates and empty meshes.
Result<StlFile> parse_stl(std::string_view bytes, std::string_view source_name);
Result<StlFile> read_stl(const std::string& path);

/// Writes binary (default) or ASCII STL atomically.
Status write_stl(const std::string& path, const Mesh& mesh, bool binary = true);
std::string stl_binary_bytes(const Mesh& mesh);

}  // namespace swarf
