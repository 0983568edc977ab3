// G-code in four dialects, written from a Toolpath and read back into one. The writer
// knows nothing of strategies (STYLE.md 5).
#pragma once

#include <span>
#include <string>
#include <string_view>

#include "swarf/core/status.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf {

enum class Dialect {
  kIso,       ///< neutral RS-274
  kFanuc,     ///< %, O-number, G21 G90 G17 G54 start, M30, optional N-words
  kLinuxCnc,  ///< path blending G64 P<tolerance>
  kGrbl,      ///< no tool change, arcs in XY only
};

std::string_view dialect_name(Dialect dialect);
Result<Dialect> parse_dialect(std::string_view name);

struct GcodeOptions {
  Dialect dialect = Dialect::kIso;
  int program_number = 1000;  ///< Fanuc O-number
  bool line_numbers = false;  ///< N-words on every block
  int line_number_step = 10;
  int decimals = 4;                  ///< digits after the point for coordinates
  double blend_tolerance_mm = 0.01;  ///< LinuxCNC G64 P
  std::string title;                 ///< first comment
};

/// Writes a whole program: safe start block, each toolpath (tool change, spindle, coolant,
/// moves), retract to clearance, end block.
std::string write_gcode(std::span<const Toolpath> paths, const GcodeOptions& options);
std::string write_gcode(const Toolpath& path, const GcodeOptions& options);

struct GcodeReadOptions {
  /// Where the machine is before the first block, mm.
  Vec3 start{0.0, 0.0, 0.0};
  /// Machine coordinates of the program origin (the active work offset, G54): G53 blocks
  /// give machine coordinates. LinuxCNC's default is 0 (machine = program coordinates).
  Vec3 work_offset{0.0, 0.0, 0.0};
  /// The positions G28 and G30 return to, in machine coordinates (LinuxCNC parameters
  /// 5161-5163 and 5181-5183, 0 by default); G28.1 / G30.1 in the program overwrite them.
  Vec3 g28_home{0.0, 0.0, 0.0};
  Vec3 g30_home{0.0, 0.0, 0.0};
};

/// Parses a program in any of the dialects above (G0 G1 G2 G3 with I/J/K or R, G17-G19,
/// G20/G21, G90/G91, G28/G30 returns and G28.1/G30.1, G53 machine-coordinate moves, F S T M
/// words, comments, N-words, O-numbers, %). Errors name the
/// source and the line: "prog.nc:12: G2 without I, J, K or R".
Result<Toolpath> parse_gcode(std::string_view text, std::string_view source_name,
                             const GcodeReadOptions& options = {});
Result<Toolpath> read_gcode(const std::string& path, const GcodeReadOptions& options = {});

}  // namespace swarf
