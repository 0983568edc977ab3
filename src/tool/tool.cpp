#include "swarf/tool/tool.h"

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace swarf {

std::string_view tool_kind_name(ToolKind kind) {
  switch (kind) {
    case ToolKind::kFlat:
      return "flat";
    case ToolKind::kBall:
      return "ball";
    case ToolKind::kBull:
      return "bull";
  }
  return "unknown";
}

double Tool::height_at(double r) const {
  const double big_r = radius();
  r = std::abs(r);
  if (r > big_r) return std::numeric_limits<double>::infinity();
  const double rc = corner_radius_mm;
  const double flat_r = big_r - rc;  // radius of the flat bottom
  if (r <= flat_r || rc <= 0.0) return 0.0;
  // Torus corner: centre of the corner circle at (flat_r, rc).
  const double dr = r - flat_r;
  return rc - std::sqrt(std::max(0.0, rc * rc - dr * dr));
}

double Tool::width_at(double h) const {
  const double rc = corner_radius_mm;
  if (h <= 0.0) return radius() - rc;
  if (h >= rc) return radius();
  const double dz = rc - h;
  return radius() - rc + std::sqrt(std::max(0.0, rc * rc - dz * dz));
}

std::string Tool::description() const {
  std::ostringstream s;
  s << "D" << diameter_mm << " ";
  switch (kind) {
    case ToolKind::kFlat:
      s << "flat end mill";
      break;
    case ToolKind::kBall:
      s << "ball end mill";
      break;
    case ToolKind::kBull:
      s << "bull-nose end mill R" << corner_radius_mm;
      break;
  }
  s << ", " << flutes << " flutes";
  if (!name.empty()) s << " (" << name << ")";
  return s.str();
}

Status validate(const Tool& tool) {
  auto fail = [](const std::string& m) { return bad_parameter("tool: " + m); };
  if (!std::isfinite(tool.diameter_mm) || tool.diameter_mm <= 0.0)
    return fail("diameter must be a positive number of mm");
  if (tool.diameter_mm > 200.0) return fail("diameter above 200 mm is not an end mill");
  if (!std::isfinite(tool.corner_radius_mm) || tool.corner_radius_mm < 0.0)
    return fail("corner radius must be >= 0 mm");
  const double r = tool.radius();
  switch (tool.kind) {
    case ToolKind::kFlat:
      if (tool.corner_radius_mm != 0.0)
        return fail("a flat end mill has no corner radius (use bull:D:R)");
      break;
    case ToolKind::kBall:
      if (std::abs(tool.corner_radius_mm - r) > 1e-9)
        return fail("a ball end mill's corner radius is half its diameter");
      break;
    case ToolKind::kBull:
      if (tool.corner_radius_mm <= 0.0 || tool.corner_radius_mm >= r) {
        std::ostringstream m;
        m << "bull-nose corner radius " << tool.corner_radius_mm
          << " mm must be above 0 and below the tool radius " << r << " mm";
        return fail(m.str());
      }
      break;
  }
  if (tool.flutes < 1 || tool.flutes > 16) return fail("flute count must be 1 to 16");
  if (!std::isfinite(tool.helix_angle_deg) || tool.helix_angle_deg < 0.0 ||
      tool.helix_angle_deg >= 80.0)
    return fail("helix angle must be in [0, 80) degrees");
  if (!std::isfinite(tool.flute_length_mm) || tool.flute_length_mm <= 0.0)
    return fail("flute length must be a positive number of mm");
  if (tool.number < 0 || tool.number > 9999) return fail("tool number must be 0 to 9999");
  return {};
}

Tool ball_mill(double diameter_mm) {
  Tool t;
  t.kind = ToolKind::kBall;
  t.diameter_mm = diameter_mm;
  t.corner_radius_mm = diameter_mm * 0.5;
  return t;
}

Tool flat_mill(double diameter_mm) {
  Tool t;
  t.kind = ToolKind::kFlat;
  t.diameter_mm = diameter_mm;
  return t;
}

namespace {

bool parse_number(std::string_view s, double& out) {
  if (s.empty()) return false;
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

}  // namespace

Result<Tool> parse_tool_spec(std::string_view spec) {
  std::vector<std::string_view> parts;
  std::size_t start = 0;
  while (true) {
    const std::size_t colon = spec.find(':', start);
    parts.push_back(spec.substr(start, colon == std::string_view::npos ? colon : colon - start));
    if (colon == std::string_view::npos) break;
    start = colon + 1;
  }
  const std::string quoted = "tool '" + std::string(spec) + "'";
  if (parts.size() < 2 || parts.size() > 3)
    return bad_parameter(quoted + ": expected KIND:DIAMETER[:CORNER_RADIUS], e.g. flat:10");
  Tool t;
  if (parts[0] == "flat") {
    t.kind = ToolKind::kFlat;
  } else if (parts[0] == "ball") {
    t.kind = ToolKind::kBall;
  } else if (parts[0] == "bull") {
    t.kind = ToolKind::kBull;
  } else {
    return bad_parameter(quoted + ": unknown kind '" + std::string(parts[0]) +
                         "' (flat, ball or bull)");
  }
  if (!parse_number(parts[1], t.diameter_mm))
    return bad_parameter(quoted + ": diameter '" + std::string(parts[1]) + "' is not a number");
  if (parts.size() == 3) {
    if (!parse_number(parts[2], t.corner_radius_mm))
      return bad_parameter(quoted + ": corner radius '" + std::string(parts[2]) +
                           "' is not a number");
    if (t.kind == ToolKind::kBall && std::abs(t.corner_radius_mm - t.radius()) > 1e-9)
      return bad_parameter(quoted + ": a ball end mill's corner radius is half its diameter");
  } else if (t.kind == ToolKind::kBall) {
    t.corner_radius_mm = t.radius();
  } else if (t.kind == ToolKind::kBull) {
    return bad_parameter(quoted + ": a bull-nose tool needs a corner radius, e.g. bull:10:1");
  }
  Status s = validate(t);
  if (!s.ok()) return s.with_context(quoted);
  return t;
}

}  // namespace swarf
