// The toolpath: what every strategy produces and every writer, simulator and report
// consumes (STYLE.md 5). Positions are the tool tip (centre of the tool's bottom), mm;
// feeds in mm/min.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "swarf/core/vec.h"

namespace swarf {

enum class MoveKind : std::uint8_t {
  kRapid,   ///< G0 positioning, never in material
  kFeed,    ///< G1 cutting or linking move
  kPlunge,  ///< G1 straight down along the tool axis
  kRamp,    ///< G1 descending while moving sideways
  kHelix,   ///< G2/G3 with a change of height: a helical entry
  kArc,     ///< G2/G3 in one plane
};

std::string_view move_kind_name(MoveKind kind);

enum class ArcPlane : std::uint8_t { kXY, kZX, kYZ };  ///< G17, G18, G19

inline constexpr float kUnknown = std::numeric_limits<float>::quiet_NaN();

struct Move {
  MoveKind kind = MoveKind::kFeed;
  /// Tool-tip position at the end of the move; it starts where the previous move ended.
  Vec3 end;
  /// Feed rate, mm/min; ignored for rapids.
  double feed_mm_min = 0.0;
  /// Arcs and helices: the centre (its coordinates in the arc plane count), direction, plane.
  Vec3 center;
  bool clockwise = false;
  ArcPlane plane = ArcPlane::kXY;
  /// False for feed moves that link cuts through air (counted as air length).
  bool cutting = true;
  /// Annotations, NaN when unknown: radial engagement angle, degrees; peak cutting force, N.
  float engagement_deg = kUnknown;
  float force_n = kUnknown;

  bool is_arc() const { return kind == MoveKind::kArc || kind == MoveKind::kHelix; }
};

/// A move to `end` of the given kind, feed (mm/min; 0 for rapids) and cutting flag, its
/// other fields at their defaults (arcs set their centre and direction afterwards).
inline Move make_move(MoveKind kind, Vec3 end, double feed_mm_min, bool cutting) {
  Move mv;
  mv.kind = kind;
  mv.end = end;
  mv.feed_mm_min = feed_mm_min;
  mv.cutting = cutting;
  return mv;
}

enum class Coolant : std::uint8_t { kOff, kFlood, kMist };

/// One operation's moves with the tool and spindle it runs with.
struct Toolpath {
  std::string name;  ///< operation name, written as a comment
  int tool_number = 1;
  std::string tool_description;
  double tool_diameter_mm = 0.0;
  double spindle_rpm = 10000.0;
  Coolant coolant = Coolant::kFlood;
  /// Height at which rapid moves between cuts are safe (above stock and clamps), mm.
  double clearance_z_mm = 5.0;
  /// The first move starts here (a rapid from the machine's safe position).
  std::vector<Move> moves;

  bool empty() const { return moves.empty(); }

  // Builders that keep strategies short. Each appends one move.
  void rapid_to(Vec3 p);
  void feed_to(Vec3 p, double feed_mm_min, bool cutting = true);
  void plunge_to(double z, double feed_mm_min);
  void ramp_to(Vec3 p, double feed_mm_min);
  /// An arc or helix in the XY plane about `center` (only x, y used) to `end`.
  void arc_to(Vec3 end, Vec2 center, bool clockwise, double feed_mm_min);
  /// Retract straight up to the clearance plane with a rapid.
  void retract();
  /// Current tool position: the end of the last move (or the origin at clearance).
  Vec3 position() const;
};

/// Points along a move from `start`, at most `max_step_mm` apart, ending at move.end
/// (arcs and helices are subdivided; lines give just the end point).
std::vector<Vec3> sample_move(Vec3 start, const Move& move, double max_step_mm);
/// Length of a move starting at `start`, mm (exact for arcs and helices).
double move_length(Vec3 start, const Move& move);

}  // namespace swarf
