// The adaptive pocket's engagement picture: one pixel per simulation pixel, north up, and for
// maps larger than the size limit one pixel per block in which a residue never vanishes.
#include <gtest/gtest.h>

#include "swarf/report/pocket_picture.h"

namespace swarf {
namespace {

// A map of w x h cells: walls (0) round the edge, everything inside cut by step 0 (cell 3)
// except one cell of material left at (mi, mj).
AdaptiveResult map_with_residue(int w, int h, int mi, int mj) {
  AdaptiveResult r;
  r.target_engagement_deg = 40.0;
  r.steps.push_back({});
  r.steps[0].engagement_deg = 40.0;  // the target: mid-scale colour
  r.cut_map.width = w;
  r.cut_map.height = h;
  r.cut_map.cells.assign(static_cast<std::size_t>(w) * h, 3);
  for (int i = 0; i < w; ++i) {
    r.cut_map.cells[static_cast<std::size_t>(i)] = 0;
    r.cut_map.cells[static_cast<std::size_t>(h - 1) * w + i] = 0;
  }
  r.cut_map.cells[static_cast<std::size_t>(mj) * w + mi] = 1;
  return r;
}

bool is_residue(const Rgb& c) {
  return c.r == 150 && c.g == 60 && c.b == 40;
}

TEST(PocketPicture, OnePixelPerCellNorthUp) {
  const AdaptiveResult r = map_with_residue(30, 20, 4, 15);
  const Image img = pocket_engagement_picture(r, 4096);
  ASSERT_EQ(img.width, 30);
  ASSERT_EQ(img.height, 20);
  EXPECT_TRUE(is_residue(img.at(4, 20 - 1 - 15)));  // row 0 of the picture is the top (max y)
  EXPECT_FALSE(is_residue(img.at(4, 15)));
  const Rgb cut = img.at(10, 10), wall = img.at(10, 0);
  EXPECT_EQ(cut.r, heat_color(0.5).r);
  EXPECT_EQ(cut.g, heat_color(0.5).g);
  EXPECT_EQ(wall.r, 40);
}

TEST(PocketPicture, LargeMapsAreShownByBlocksAndKeepTheirResidue) {
  // 1000 x 600 cells at most 256 pixels on a side: blocks of 4 x 4 cells, 250 x 150 pixels.
  // The one cell of residue is off its block's centre and must still show.
  const AdaptiveResult r = map_with_residue(1000, 600, 401, 298);
  const Image img = pocket_engagement_picture(r, 256);
  ASSERT_EQ(img.width, 250);
  ASSERT_EQ(img.height, 150);
  int residue = 0;
  for (const Rgb& c : img.pixels)
    residue += is_residue(c) ? 1 : 0;
  EXPECT_EQ(residue, 1);
  EXPECT_TRUE(is_residue(img.at(401 / 4, 150 - 1 - 298 / 4)));
}

}  // namespace
}  // namespace swarf
