// Channels a little wider than the tool: the ramp that enters one keeps to a wall and runs
// the channel's length, and AdaptiveParams::channel_plunge plunges along a wall and
// side-mills the strip left where the path would loop along a channel, if that is no slower.
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

// A chamber with such a channel off it, scaled to the tool (d = 8: a 30 mm square and a
// channel 8.8 x 40; the entry is a helix in the chamber, and the path loops along the
// channel, with 0.1 d of room beside the tool).
Pocket chamber_and_channel(double d) {
  const double s = d / 8.0;
  return make_pocket({{0, 0},
                      {30 * s, 0},
                      {30 * s, 10.6 * s},
                      {70 * s, 10.6 * s},
                      {70 * s, 19.4 * s},
                      {30 * s, 19.4 * s},
                      {30 * s, 30 * s},
                      {0, 30 * s}},
                     {}, "chamber and channel, d " + std::to_string(static_cast<int>(d)))
      .value();
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
// it left one strip of 0.8 mm, but the ramp reached only 4 R from its start and the tight
// loops took the rest of the channel: 33.3 % (57 %). Now the ramp runs the channel's length
// and its strip is one pass in the band.
TEST(AdaptiveChannel, RampRunsTheChannelAlongAWall) {
  const Pocket p = channel();
  const Outcome o = run_channel(p, 8.0, params_3mm_deep(0.8));
  expect_correct(p, o, -1.0);
  const auto& mv = o.result.toolpath.moves;
  double x_lo = 1e9, x_hi = -1e9;
  for (const Move& m : mv) {
    if (m.kind != MoveKind::kRamp) continue;
    // On the offset of the wall at y = 0 or of that at y = 8.8 (4 mm + 2 um off it).
    EXPECT_NEAR(std::min(std::abs(m.end.y - 4.002), std::abs(m.end.y - 4.798)), 0.0, 1e-3)
        << m.end.x << " " << m.end.y;
    x_lo = std::min(x_lo, m.end.x);
    x_hi = std::max(x_hi, m.end.x);
  }
  // From end to end: the tool 4 mm and 2 um off the end walls.
  EXPECT_NEAR(x_lo, 4.002, 1e-2);
  EXPECT_NEAR(x_hi, 35.998, 1e-2);
  EXPECT_GE(o.sweep.within_20pct, 0.75);
  EXPECT_EQ(o.result.channels, 0);  // no loops left to replace
}

// In the channel off a chamber the path loops (a tenth of a millimetre across, the contact
// swinging from nothing to half the tool on each); channel_plunge makes them plunges along
// one wall, a climb pass taking the strip left along the other in the band, and a pass
// taking the cusps between the holes.
TEST(AdaptiveChannel, ChannelPlungesSideMillTheStripInTheBand) {
  const Pocket p = chamber_and_channel(8.0);
  for (const double stepover : {0.8, 0.4}) {
    AdaptiveParams on = params_3mm_deep(stepover);
    AdaptiveParams off = on;
    off.channel_plunge = false;
    const Outcome loops = run_channel(p, 8.0, off);
    const Outcome plunged = run_channel(p, 8.0, on);
    expect_correct(p, plunged, -1.0);
    EXPECT_EQ(loops.result.channels, 0);
    EXPECT_EQ(plunged.result.channels, 1);
    EXPECT_GE(plunged.result.channel_plunges, 10);
    EXPECT_GE(plunged.sweep.within_20pct, loops.sweep.within_20pct + 0.05) << stepover;
    EXPECT_GE(plunged.sweep.climb_share, loops.sweep.climb_share + 0.05) << stepover;
    EXPECT_LE(3 * plunged.sweep.reversals, loops.sweep.reversals) << stepover;
    EXPECT_LT(compute_metrics(plunged.result.toolpath).machining_time_s,
              compute_metrics(loops.result.toolpath).machining_time_s)
        << stepover;
    // The plunges and passes keep the tool off the walls exactly (2 um, the passes' margin).
    EXPECT_LE(plunged.sweep.max_gouge_mm, 1e-6);
  }
}

// A run is plunged only where that is no slower at the feeds than its loops: a ø4 in the
// same shape plunges 1 mm deep (2 mm a plunge, from 1 mm above the layer's top), where
// that is faster, and not 6 mm deep, where the path is the loops', move for move.
TEST(AdaptiveChannel, ChannelPlungesOnlyWhereNoSlower) {
  const Pocket p = chamber_and_channel(4.0);
  for (const double depth : {1.0, 6.0}) {
    AdaptiveParams on = params_3mm_deep(0.4);
    on.depth_mm = depth;
    AdaptiveParams off = on;
    off.channel_plunge = false;
    const auto a = adaptive_pocket(p, flat_mill(4.0), on);
    const auto b = adaptive_pocket(p, flat_mill(4.0), off);
    ASSERT_TRUE(a.ok() && b.ok());
    const double t_on = compute_metrics(a->toolpath).machining_time_s;
    const double t_off = compute_metrics(b->toolpath).machining_time_s;
    std::printf("  depth %.0f: channels %d, %.1f s on, %.1f s off\n", depth, a->channels, t_on,
                t_off);
    if (depth < 2.0) {
      EXPECT_EQ(a->channels, 1);
      EXPECT_LT(t_on, t_off);
    } else {
      EXPECT_EQ(a->channels, 0);
      EXPECT_EQ(a->toolpath.moves.size(), b->toolpath.moves.size());
      EXPECT_DOUBLE_EQ(t_on, t_off);
    }
  }
}

// A run's loops may reach beyond what replaces them: random pocket 2440 (ø20 at 1.6 mm), whose
// first run's loops went round into the corridor at the channel's end, left 1.4 mm^2 there
// by this sweep. Such runs keep their loops: the sweep's residual with channel plunges is
// within crumbs of the loops' own.
TEST(AdaptiveChannel, ChannelPlungesLeaveNothingTheLoopsTook) {
  const Pocket p = testing::load_test_pocket("random_seed2440.json");
  AdaptiveParams on = params_3mm_deep(1.6);
  on.depth_mm = 6.0;
  AdaptiveParams off = on;
  off.channel_plunge = false;
  const Outcome loops = run_channel(p, 20.0, off);
  const Outcome plunged = run_channel(p, 20.0, on);
  expect_correct(p, plunged, -1.0);
  EXPECT_GE(plunged.result.channels, 1);  // the other run is replaced
  EXPECT_LE(plunged.sweep.residual_mm2, loops.sweep.residual_mm2 + 0.1);
}

}  // namespace
}  // namespace swarf
