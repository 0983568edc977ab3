// libFuzzer target: parse_gcode must never crash, hang or read out of bounds, whatever the
// bytes; what it accepts must also survive the writer and metrics.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "swarf/gcode/gcode.h"
#include "swarf/toolpath/metrics.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const auto path = swarf::parse_gcode(text, "fuzz.nc");
  if (!path.ok()) return 0;
  (void)swarf::compute_metrics(*path);
  // Sampling and linearising scale with arc size (a 10^9 mm arc is a million lines by
  // design), so the writer is exercised on machine-sized inputs only.
  for (const swarf::Move& m : path->moves) {
    if (!(std::abs(m.end.x) < 1e4 && std::abs(m.end.y) < 1e4 && std::abs(m.end.z) < 1e4 &&
          std::abs(m.center.x) < 1e4 && std::abs(m.center.y) < 1e4 && std::abs(m.center.z) < 1e4)) {
      return 0;
    }
  }
  if (path->moves.size() > 200) return 0;
  for (const swarf::Move& m : path->moves) {
    if (m.is_arc()) (void)swarf::sample_move(path->moves.front().end, m, 1.0);
  }
  swarf::GcodeOptions options;
  options.dialect = swarf::Dialect::kGrbl;  // linearises helices: the heaviest writer path
  (void)swarf::write_gcode(*path, options);
  return 0;
}
