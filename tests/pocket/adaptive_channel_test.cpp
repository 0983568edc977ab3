// Channels a little wider than the tool: the ramp that enters one keeps to a wall, and
// AdaptiveParams::channel_plunge plunges along a wall and side-mills the strip left.
// Judged by the independent sweep of tests/pocket/sweep_checker.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "pocket/adaptive_test_util.h"
#include "pocket/sweep_checker.h"
#include "swarf/pocket/adaptive.h"

namespace swarf {
namespace {

using testing::expect_correct;
using testing::flat_mill;
using testing::Outcome;
using testing::params_3mm_deep;

// A channel 8.8 x 40 mm, the "channel barely wider than the tool" for a ø8 at 10 %
// (0.8 mm of stepover, 37 degrees): 0.8 mm of room beside the tool, one band-deep strip.
Pocket channel() {
  return make_pocket({{0, 0}, {40, 0}, {40, 8.8}, {0, 8.8}}, {}, "channel 8.8 x 40").value();
}

// The channel generated with `ap` and swept (the result is kept: its entry and channels).
Outcome run_channel(const Pocket& p, double tool_d, const AdaptiveParams& ap) {
  auto r = adaptive_pocket(p, flat_mill(tool_d), ap);
  EXPECT_TRUE(r.ok()) << r.status().to_string();
  Outcome o{r.value(), testing::swept(p, tool_d, r.value()).sweep};
  const auto& s = o.sweep;
  std::printf(
      "  %s, channel plunges %s: gouge %.3f mm, residual %.2f mm2, cutting %.0f mm, within20 "
      "%.1f %%, climb %.1f %%, reversals %d, channels %d (%d plunges)\n",
      p.source.c_str(), ap.channel_plunge ? "on" : "off", s.max_gouge_mm, s.residual_mm2,
      s.cutting_length_mm, 100 * s.within_20pct, 100 * s.climb_share, s.reversals,
      o.result.channels, o.result.channel_plunges);
  return o;
}

// The entry's ramp down a channel with 0.8 mm of room ran down its middle and left a strip of
// 0.4 mm on each side, each taken later at 26 degrees (37 targeted): 22.5 % of the cut in the
// band by this sweep (45 % by bench/swarf_pocket_sweep's finer one). Along one wall's offset
// it leaves one strip of 0.8 mm: 33.3 % (57 %).
TEST(AdaptiveChannel, RampKeepsToAWallOfAChannel) {
  const Pocket p = channel();
  const Outcome o = run_channel(p, 8.0, params_3mm_deep(0.8));
  expect_correct(p, o, -1.0);
  const auto& mv = o.result.toolpath.moves;
  bool ramp = false;
  for (const Move& m : mv) {
    if (m.kind != MoveKind::kRamp) continue;
    ramp = true;
    // On the offset of the wall at y = 0 or of that at y = 8.8 (4 mm + 2 um off it).
    EXPECT_NEAR(std::min(std::abs(m.end.y - 4.002), std::abs(m.end.y - 4.798)), 0.0, 1e-3)
        << m.end.x << " " << m.end.y;
  }
  EXPECT_TRUE(ramp);
  EXPECT_GE(o.sweep.within_20pct, 0.28);
}

// With channel_plunge the loops along the channel (a tenth of a millimetre across, the
// contact swinging from nothing to half the tool on each) become plunges along one wall, a
// climb pass taking the strip left along the other in the band, and a pass taking the cusps
// between the holes. This sweep: 33 -> 67 % of the cut in the band at 0.8 mm of stepover
// and 17 -> 62 % at 0.4, climb 53 -> 91 % and 50 -> 61 %, 316 -> 11 and 469 -> 29
// reversals.
TEST(AdaptiveChannel, ChannelPlungesSideMillTheStripInTheBand) {
  const Pocket p = channel();
  for (const double stepover : {0.8, 0.4}) {
    AdaptiveParams off = params_3mm_deep(stepover);
    AdaptiveParams on = off;
    on.channel_plunge = true;
    const Outcome loops = run_channel(p, 8.0, off);
    const Outcome plunged = run_channel(p, 8.0, on);
    expect_correct(p, plunged, -1.0);
    EXPECT_EQ(loops.result.channels, 0);
    EXPECT_GE(plunged.result.channels, 1);
    EXPECT_GE(plunged.result.channel_plunges, 4);
    EXPECT_GE(plunged.sweep.within_20pct, loops.sweep.within_20pct + 0.05) << stepover;
    EXPECT_GE(plunged.sweep.climb_share, loops.sweep.climb_share + 0.05) << stepover;
    EXPECT_LE(5 * plunged.sweep.reversals, loops.sweep.reversals) << stepover;
    // The plunges and passes keep the tool off the walls exactly (2 um, the passes' margin).
    EXPECT_LE(plunged.sweep.max_gouge_mm, 1e-6);
  }
}

}  // namespace
}  // namespace swarf
