#include "swarf/tool/library.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "swarf/core/io.h"

namespace swarf {

const Tool* ToolLibrary::find(int number) const {
  for (const Tool& t : tools)
    if (t.number == number) return &t;
  return nullptr;
}

namespace {

using nlohmann::json;

Status get_number(const json& j, const char* key, double& out, const std::string& where,
                  bool required) {
  auto it = j.find(key);
  if (it == j.end()) {
    if (required) return bad_input(where + ": missing \"" + key + "\"");
    return {};
  }
  if (!it->is_number()) return bad_input(where + ": \"" + key + "\" must be a number");
  out = it->get<double>();
  return {};
}

}  // namespace

Result<ToolLibrary> parse_tool_library(std::string_view text, std::string_view source_name) {
  const std::string src(source_name);
  json doc = json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded()) return bad_input(src + ": not valid JSON");
  if (!doc.is_object() || !doc.contains("tools") || !doc["tools"].is_array())
    return bad_input(src + ": expected an object with a \"tools\" array");
  ToolLibrary lib;
  std::set<int> numbers;
  int index = 0;
  for (const json& jt : doc["tools"]) {
    const std::string where = src + ": tools[" + std::to_string(index++) + "]";
    if (!jt.is_object()) return bad_input(where + ": expected an object");
    Tool t;
    if (!jt.contains("kind") || !jt["kind"].is_string())
      return bad_input(where + ": missing \"kind\" (flat, ball or bull)");
    const std::string kind = jt["kind"].get<std::string>();
    if (kind == "flat") {
      t.kind = ToolKind::kFlat;
    } else if (kind == "ball") {
      t.kind = ToolKind::kBall;
    } else if (kind == "bull") {
      t.kind = ToolKind::kBull;
    } else {
      return bad_input(where + ": unknown kind \"" + kind + "\" (flat, ball or bull)");
    }
    SWARF_RETURN_IF_ERROR(get_number(jt, "diameter", t.diameter_mm, where, true));
    if (t.kind == ToolKind::kBall) t.corner_radius_mm = t.radius();
    SWARF_RETURN_IF_ERROR(get_number(jt, "corner_radius", t.corner_radius_mm, where, false));
    double flutes = t.flutes, number = t.number;
    SWARF_RETURN_IF_ERROR(get_number(jt, "flutes", flutes, where, false));
    SWARF_RETURN_IF_ERROR(get_number(jt, "number", number, where, true));
    SWARF_RETURN_IF_ERROR(get_number(jt, "helix_angle", t.helix_angle_deg, where, false));
    SWARF_RETURN_IF_ERROR(get_number(jt, "flute_length", t.flute_length_mm, where, false));
    // Range first: casting an out-of-range double to int is undefined behaviour.
    if (std::abs(flutes) > 1e6 || std::abs(number) > 1e6 || flutes != std::floor(flutes) ||
        number != std::floor(number))
      return bad_input(where + ": \"flutes\" and \"number\" must be whole numbers");
    t.flutes = static_cast<int>(flutes);
    t.number = static_cast<int>(number);
    if (jt.contains("name")) {
      if (!jt["name"].is_string()) return bad_input(where + ": \"name\" must be a string");
      t.name = jt["name"].get<std::string>();
    }
    Status s = validate(t);
    if (!s.ok()) return Status{Error::kBadInput, where + ": " + s.message()};
    if (!numbers.insert(t.number).second)
      return bad_input(where + ": tool number " + std::to_string(t.number) + " appears twice");
    lib.tools.push_back(std::move(t));
  }
  if (lib.tools.empty()) return bad_input(src + ": the library holds no tools");
  return lib;
}

Result<ToolLibrary> read_tool_library(const std::string& path) {
  Result<std::string> text = read_file(path);
  if (!text.ok()) return text.status();
  return parse_tool_library(*text, path);
}

std::string tool_library_json(const ToolLibrary& library) {
  json doc;
  doc["tools"] = json::array();
  for (const Tool& t : library.tools) {
    json jt = {{"number", t.number},
               {"kind", std::string(tool_kind_name(t.kind))},
               {"diameter", t.diameter_mm},
               {"corner_radius", t.corner_radius_mm},
               {"flutes", t.flutes},
               {"helix_angle", t.helix_angle_deg},
               {"flute_length", t.flute_length_mm}};
    if (!t.name.empty()) jt["name"] = t.name;
    doc["tools"].push_back(std::move(jt));
  }
  return doc.dump(2) + "\n";
}

}  // namespace swarf
