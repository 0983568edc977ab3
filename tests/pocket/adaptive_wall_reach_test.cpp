// The path's reach to the walls (src/pocket/wall_reach.cpp) on pockets where the region of
// tool centres ends in a tip the pixel model lets the chooser pass, judged by the
// independent sweep's exact distances to the walls.
#include <gtest/gtest.h>

#include <cstdio>

#include "pocket/adaptive_test_util.h"
#include "swarf/pocket/adaptive.h"

namespace swarf {
namespace {

// Pocket 5421 of bench/pocket_random.sh (ø8 at 30 %): a rounded rectangle whose top wall
// and the corner of a bar drawn across the right wall are 7.944 mm apart, less than the
// tool. The region of tool centres ends there in a tip of about 9 degrees, and the
// chooser's pixels (which hold the disk to about a fifth of a pixel of the walls) let a
// session end 0.34 mm past it. Pushed out of the walls, that point found no place clear of
// both and kept the one that gouged least: 0.042 mm into the top wall by the bench sweep.
// Such a point now goes back along the path to the last place clear of the walls.
TEST(AdaptiveWallReach, APointPastTheTipOfTheCentresGoesBackWhereTheToolFits) {
  const Pocket p = testing::load_test_pocket("random_seed5421.json");
  auto r = adaptive_pocket(p, testing::flat_mill(8.0), testing::params_3mm_deep(2.4));
  ASSERT_TRUE(r.ok()) << r.status().to_string();
  const testing::SweepReport s = testing::swept(p, 8.0, *r).sweep;
  std::printf("  gouge %.4f mm, residual %.2f mm2, within20 %.1f %%\n", s.max_gouge_mm,
              s.residual_mm2, 100 * s.within_20pct);
  EXPECT_LE(s.max_gouge_mm, 1e-6);
  EXPECT_LE(s.residual_mm2, 0.5);
}

}  // namespace
}  // namespace swarf
