// The independent sweep itself, against closed forms: what it counts as cut and as left.
#include <gtest/gtest.h>

#include "pocket/sweep_checker.h"
#include "swarf/core/vec.h"

namespace swarf {
namespace {

Move move_to(MoveKind kind, Vec3 end) {
  Move m;
  m.kind = kind;
  m.end = end;
  m.feed_mm_min = kind == MoveKind::kRapid ? 0.0 : 300.0;
  m.cutting = kind != MoveKind::kRapid;
  return m;
}

// A straight plunge and straight back up, no move along the floor: the disk where the tool
// reached the floor is cut. The sweep used to read only moves along the floor and counted
// such a plunge as cutting nothing. A 20 mm square and a ø10 tool: the tool reaches the
// square less its four corners (4 (1 - pi / 4) 25 mm^2), and the plunge at the middle takes
// a disk of 25 pi.
TEST(SweepChecker, AStraightPlungeCutsItsDisk) {
  const PolygonSet square{{Ring{{0, 0}, {20, 0}, {20, 20}, {0, 20}}}};
  Toolpath tp;
  tp.moves = {move_to(MoveKind::kRapid, {10, 10, 5}), move_to(MoveKind::kPlunge, {10, 10, -1}),
              move_to(MoveKind::kRapid, {10, 10, 5})};
  const auto s = testing::sweep_check(square, 5.0, tp, 36.87, 0.05, 0.0);
  // Cells are counted whole: within half a 0.05 mm cell along the 80 mm of walls.
  const double reach = 400.0 - 4.0 * (1.0 - kPi / 4.0) * 25.0, pixel_band = 80.0 * 0.05 / 2;
  EXPECT_NEAR(s.unreachable_mm2, 400.0 - reach, pixel_band);
  EXPECT_NEAR(s.residual_mm2, reach - kPi * 25.0, pixel_band);
  EXPECT_EQ(s.max_gouge_mm, 0.0);
  EXPECT_EQ(s.cutting_length_mm, 0.0);  // a plunge is part of an entry, not a floor pass
}

}  // namespace
}  // namespace swarf
