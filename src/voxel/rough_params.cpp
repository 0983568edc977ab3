// Seed 003: strategy names, parameter validation and the orientation study (3.1.1).
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>

#include "swarf/voxel/rough.h"

namespace swarf {

std::string_view rough_sequence_name(RoughSequence s) {
  switch (s) {
    case RoughSequence::kZigzag:
      return "zigzag";
    case RoughSequence::kTrappedArea:
      return "none";
    case RoughSequence::kGa:
      return "ga";
  }
  return "?";
}

Result<RoughSequence> parse_rough_sequence(std::string_view name) {
  if (name == "zigzag") return RoughSequence::kZigzag;
  if (name == "none" || name == "ta") return RoughSequence::kTrappedArea;
  if (name == "ga") return RoughSequence::kGa;
  return bad_parameter("unknown sequence '" + std::string(name) + "' (zigzag, none or ga)");
}

Status validate(const RoughParams& p) {
  if (!(p.tool_diameter_mm > 0.0)) return bad_parameter("tool diameter must be > 0 mm");
  if (!(p.stepover_mm > 0.0) || p.stepover_mm > p.tool_diameter_mm) {
    return bad_parameter("stepover " + std::to_string(p.stepover_mm) +
                         " mm must be in (0, tool diameter " + std::to_string(p.tool_diameter_mm) +
                         " mm]: wider lines leave ridges");
  }
  if (!(p.stepdown_mm > 0.0)) return bad_parameter("stepdown must be > 0 mm");
  if (!(p.stock_to_leave_mm >= 0.0)) return bad_parameter("stock to leave must be >= 0 mm");
  if (!(p.margin_mm >= 0.0) || !(p.top_margin_mm >= 0.0)) {
    return bad_parameter("stock margins must be >= 0 mm");
  }
  if (!(p.clearance_mm > 0.0)) return bad_parameter("clearance must be > 0 mm");
  if (!(p.feed_mm_min > 0.0) || !(p.plunge_feed_mm_min > 0.0)) {
    return bad_parameter("feed rates must be > 0 mm/min");
  }
  if (!(p.lift_penalty_mm >= 0.0)) return bad_parameter("lift penalty must be >= 0 mm");
  return validate(p.ga);
}

Result<OrientationResult> rough_orientations(const Mesh& part, const RoughParams& p,
                                             const std::vector<double>& angles_deg,
                                             const Context& ctx) {
  if (angles_deg.empty()) return bad_parameter("orientation study: no angle given");
  OrientationResult out;
  for (double a : angles_deg) {
    if (!std::isfinite(a)) return bad_parameter("orientation study: angle is not finite");
    RoughParams q = p;
    q.zigzag_angle_deg = a;
    auto r = rough(part, q, ctx);
    if (!r.ok()) {
      if (angles_deg.size() == 1 && a == 0.0) return r.status();
      char what[48];
      std::snprintf(what, sizeof what, "feed angle %g deg", a);
      return r.status().with_context(what);
    }
    out.angles_deg.push_back(a);
    out.metrics.push_back(r->metrics);
    const bool better = out.metrics.size() == 1 ||
                        r->metrics.total_length_mm < out.metrics[out.best].total_length_mm;
    if (better) {
      out.best = out.metrics.size() - 1;
      out.best_result = std::move(r).value();
    }
  }
  return out;
}

}  // namespace swarf
