// Tool library files: a JSON list of tools a machinist keeps for a machine.
//   {"tools": [{"number": 1, "kind": "flat", "diameter": 10, "corner_radius": 0,
//               "flutes": 3, "helix_angle": 35, "flute_length": 25, "name": "..."}, ...]}
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "swarf/core/status.h"
#include "swarf/tool/tool.h"

namespace swarf {

struct ToolLibrary {
  std::vector<Tool> tools;
  /// The tool with this number, or nullptr.
  const Tool* find(int number) const;
};

Result<ToolLibrary> parse_tool_library(std::string_view json, std::string_view source_name);
Result<ToolLibrary> read_tool_library(const std::string& path);
std::string tool_library_json(const ToolLibrary& library);

}  // namespace swarf
