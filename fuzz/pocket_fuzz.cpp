// libFuzzer target for the pocket readers: the first byte picks JSON, SVG or DXF.
// Any input must give a Pocket or a kBadInput status, never a crash or a hang.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "swarf/pocket/pocket_input.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  swarf::CurveInputOptions opt;
  opt.arc_tolerance_mm = 0.05;
  switch (data[0] % 3) {
    case 0:
      (void)swarf::parse_pocket_json(text, "fuzz.json");
      break;
    case 1:
      (void)swarf::parse_pocket_svg(text, "fuzz.svg", opt);
      break;
    default:
      (void)swarf::parse_pocket_dxf(text, "fuzz.dxf", opt);
      break;
  }
  return 0;
}
