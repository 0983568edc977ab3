// Toolpath builders, move lengths and sampling.
#include "swarf/toolpath/toolpath.h"

#include <algorithm>
#include <cmath>

#include "toolpath/arc_geometry.h"

namespace swarf {

std::string_view move_kind_name(MoveKind kind) {
  switch (kind) {
    case MoveKind::kRapid:
      return "rapid";
    case MoveKind::kFeed:
      return "feed";
    case MoveKind::kPlunge:
      return "plunge";
    case MoveKind::kRamp:
      return "ramp";
    case MoveKind::kHelix:
      return "helix";
    case MoveKind::kArc:
      return "arc";
  }
  return "unknown";
}

Vec3 Toolpath::position() const {
  if (moves.empty()) return {0.0, 0.0, clearance_z_mm};
  return moves.back().end;
}

void Toolpath::rapid_to(Vec3 p) {
  Move m;
  m.kind = MoveKind::kRapid;
  m.end = p;
  m.cutting = false;
  moves.push_back(m);
}

void Toolpath::feed_to(Vec3 p, double feed_mm_min, bool cutting) {
  Move m;
  m.kind = MoveKind::kFeed;
  m.end = p;
  m.feed_mm_min = feed_mm_min;
  m.cutting = cutting;
  moves.push_back(m);
}

void Toolpath::plunge_to(double z, double feed_mm_min) {
  Move m;
  m.kind = MoveKind::kPlunge;
  m.end = position();
  m.end.z = z;
  m.feed_mm_min = feed_mm_min;
  moves.push_back(m);
}

void Toolpath::ramp_to(Vec3 p, double feed_mm_min) {
  Move m;
  m.kind = MoveKind::kRamp;
  m.end = p;
  m.feed_mm_min = feed_mm_min;
  moves.push_back(m);
}

void Toolpath::arc_to(Vec3 end, Vec2 center, bool clockwise, double feed_mm_min) {
  const Vec3 start = position();
  Move m;
  m.kind = end.z != start.z ? MoveKind::kHelix : MoveKind::kArc;
  m.end = end;
  // The centre's height is the start's: only its x, y count for an XY arc.
  m.center = {center.x, center.y, start.z};
  m.clockwise = clockwise;
  m.plane = ArcPlane::kXY;
  m.feed_mm_min = feed_mm_min;
  moves.push_back(m);
}

void Toolpath::retract() {
  Vec3 p = position();
  p.z = clearance_z_mm;
  rapid_to(p);
}

double move_length(Vec3 start, const Move& move) {
  if (!move.is_arc()) return distance(start, move.end);
  return detail::arc_geometry(start, move).length();
}

std::vector<Vec3> sample_move(Vec3 start, const Move& move, double max_step_mm) {
  if (!move.is_arc()) return {move.end};
  const detail::ArcGeometry g = detail::arc_geometry(start, move);
  // A cap on the count keeps a silly step (0, NaN, 1e-12) from exhausting memory.
  constexpr double kMaxSamples = 1 << 20;
  double n = 1.0;
  if (max_step_mm > 0.0) n = std::clamp(std::ceil(g.length() / max_step_mm), 1.0, kMaxSamples);
  if (!(n >= 1.0)) n = 1.0;  // NaN length
  const auto count = static_cast<std::size_t>(n);
  std::vector<Vec3> out;
  out.reserve(count);
  for (std::size_t i = 1; i < count; ++i) {
    out.push_back(detail::arc_point(g, static_cast<double>(i) / static_cast<double>(count)));
  }
  out.push_back(move.end);
  return out;
}

}  // namespace swarf
