// Where the adaptive path resumes once a front it was cutting runs out of cutting moves,
// judged by the independent sweep.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>
#include <tuple>

#include "pocket/adaptive_test_util.h"

namespace swarf {
namespace {

testing::SweptPath run(const std::string& file, double tool_d, double stepover_mm) {
  const Pocket p = testing::load_test_pocket(file);
  AdaptiveParams ap = testing::params_3mm_deep(stepover_mm);
  ap.depth_mm = 6.0;
  auto r = adaptive_pocket(p, testing::flat_mill(tool_d), ap);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  if (!r.ok()) return {};
  const testing::SweptPath out = testing::swept(p, tool_d, *r);
  std::printf("  %s: lifts %zu, machining %.0f s, within20 %.1f %%, residual %.2f mm2\n",
              file.c_str(), out.metrics.lift_offs, out.metrics.machining_time_s,
              100 * out.sweep.within_20pct, out.sweep.residual_mm2);
  return out;
}

// A channel a millimetre or two wider than the tool is cleared from its ends by crescents,
// one from each resume a step behind the front. The crescents leave slivers at the walls
// beside the front, and a resume point only half a step behind it still had a few of them
// in its disk: none was found near the front, the tool followed the boundary of the cut
// round to the channel's other front, and back, a crescent at each with a retract between
// (pocket 2446, a ring channel round a boss: 23 lifts and 167 s; pocket 1046, the two ends
// of a C-shaped region: 11 lifts and 173 s). Where only such crumbs hold the point back, a
// step or a step and a half behind the front is tried too. And the material at the front
// the tool has just cut from is not left given up (pocket 2440, channels 1.25 mm wider than
// a ø20 at 8 %: the material at both fronts had been given up by earlier sessions, no
// resume was looked for there, and the tool walked 50 to 60 mm from one front to the
// other 55 times: 11.6 m in the air and 270 s).
TEST(AdaptiveResume, AChannelIsClearedFromOneFrontAtATimeNotInTurns) {
  for (const auto& [file, d, so, most_lifts, most_s] :
       {std::tuple{"random_seed2446.json", 12.0, 3.6, 2U, 130.0},
        {"random_seed1046.json", 20.0, 6.0, 7U, 165.0},
        {"random_seed2440.json", 20.0, 1.6, 5U, 180.0}}) {
    const testing::SweptPath r = run(file, d, so);
    EXPECT_LE(r.metrics.lift_offs, most_lifts) << file;
    EXPECT_LE(r.metrics.machining_time_s, most_s) << file;
    EXPECT_LE(r.sweep.max_gouge_mm, 1e-6) << file;
    EXPECT_LE(r.sweep.residual_mm2, 0.5) << file;
    EXPECT_EQ(r.sweep.slot_length_mm, 0.0) << file;
  }
}

}  // namespace
}  // namespace swarf
