// The pixel stock's counts against brute force, and the same answers from the portable and
// the POPCNT/SSE4.1 code paths (pixel_stock.cpp chooses at run time).
#include "pocket/pixel_stock.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <random>
#include <vector>

#include "pocket/distance_transform.h"
#include "swarf/pocket/adaptive.h"

namespace swarf::pocket {
namespace {

struct Fixture {
  Grid grid;
  BitImage material, forbidden;
};

// A 300 x 260 image, random material (60 %), forbidden pixels in a frame 4 wide.
Fixture random_image(unsigned seed) {
  Fixture f;
  f.grid.origin = {0.0, 0.0};
  f.grid.h = 0.1;
  f.grid.width = 300;
  f.grid.height = 260;
  f.material = BitImage(f.grid.width, f.grid.height);
  f.forbidden = BitImage(f.grid.width, f.grid.height);
  std::mt19937 rng(seed);
  for (int j = 0; j < f.grid.height; ++j)
    for (int i = 0; i < f.grid.width; ++i) {
      const bool frame = i < 4 || j < 4 || i >= f.grid.width - 4 || j >= f.grid.height - 4;
      if (frame)
        f.forbidden.set(i, j, true);
      else
        f.material.set(i, j, rng() % 10 < 6);
    }
  return f;
}

// Pixel centres (i, j) with (i - cx)^2 + (j - cy)^2 <= r^2, in pixel units.
bool in_disk(int i, int j, Vec2 c, double r) {
  const double dx = i - c.x, dy = j - c.y;
  return dx * dx + dy * dy <= r * r;
}

TEST(PixelStock, ProbeAndCutCountTheCrescentExactly) {
  Fixture f = random_image(7);
  const double r_mm = 2.5;  // 25 pixels
  PixelStock stock(f.grid, f.material, f.forbidden, r_mm);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int t = 0; t < 60; ++t) {
    // Centre rows on the 1/64-pixel lattice the stock snaps to; columns anywhere.
    const Vec2 a{3.5 + 23.0 * u(rng), 3.5 + std::round(64.0 * 19.0 * u(rng)) / 64.0};
    const double ang = 6.283 * u(rng);
    const Vec2 b{a.x + 0.4 * std::cos(ang), a.y + std::round(64.0 * 0.4 * std::sin(ang)) / 64.0};
    const Vec2 pa = a / f.grid.h, pb = b / f.grid.h;
    int expect = 0;
    bool gouge = false;
    for (int j = 0; j < f.grid.height; ++j)
      for (int i = 0; i < f.grid.width; ++i)
        if (in_disk(i, j, pb, 25.0) && !in_disk(i, j, pa, 25.0)) {
          expect += stock.material().get(i, j) ? 1 : 0;
          gouge = gouge || f.forbidden.get(i, j);
        }
    const int got = stock.probe(a, b);
    if (gouge) {
      EXPECT_EQ(got, PixelStock::kGouge) << "probe " << t;
      continue;
    }
    EXPECT_EQ(got, expect) << "probe " << t;
    PixelStock::allow_cpu_features(false);
    EXPECT_EQ(stock.probe(a, b), expect) << "portable probe " << t;
    PixelStock::allow_cpu_features(true);
    EXPECT_EQ(stock.cut(a, b), expect) << "cut " << t;
    EXPECT_EQ(stock.probe(a, b), 0) << "after the cut " << t;
  }
}

// cut_tagging (the re-simulation's cut map) writes its tag into exactly the pixels the cut
// removes, by brute force, and leaves every other cell alone; on both CPU paths.
TEST(PixelStock, CutTaggingMarksExactlyThePixelsItRemoves) {
  for (const bool hw : {true, false}) {
    Fixture f = random_image(5);
    const double r_mm = 2.5;  // 25 pixels
    PixelStock stock(f.grid, f.material, f.forbidden, r_mm);
    std::vector<std::uint32_t> cells(static_cast<std::size_t>(f.grid.width) * f.grid.height, 1u);
    std::vector<std::uint32_t> expect = cells;
    BitImage truth = f.material;
    PixelStock::allow_cpu_features(hw);
    std::mt19937 rng(13);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    Vec2 a{15.0, 13.0};
    int removed = 0;
    for (std::uint32_t tag = 2; tag < 40; ++tag) {
      const double ang = 6.283 * u(rng);
      const Vec2 b{std::clamp(a.x + 0.4 * std::cos(ang), 3.5, 26.5),
                   std::clamp(a.y + std::round(64.0 * 0.4 * std::sin(ang)) / 64.0, 3.5, 22.5)};
      const Vec2 pa = a / f.grid.h, pb = b / f.grid.h;
      int n = 0;
      for (int j = 0; j < f.grid.height; ++j)
        for (int i = 0; i < f.grid.width; ++i)
          if (in_disk(i, j, pb, 25.0) && !in_disk(i, j, pa, 25.0) && truth.get(i, j)) {
            truth.set(i, j, false);
            expect[f.grid.index(i, j)] = tag;
            ++n;
          }
      const int got = stock.cut_tagging(a, b, cells.data(), f.grid.width, tag);
      EXPECT_EQ(got, n) << "cut " << tag << (hw ? "" : " (portable)");
      removed += got;
      a = b;
    }
    PixelStock::allow_cpu_features(true);
    EXPECT_GT(removed, 1000);  // the cuts did meet material
    EXPECT_TRUE(cells == expect) << (hw ? "" : "portable");
    EXPECT_EQ(stock.material().count_all(), truth.count_all());
  }
}

TEST(BitImage, FirstLastSetAndBlockOccupancyMatchBruteForce) {
  std::mt19937 rng(5);
  BitImage img(203, 45);
  for (int t = 0; t < 300; ++t)
    img.set(static_cast<int>(rng() % 203), static_cast<int>(rng() % 45), true);
  for (int t = 0; t < 2000; ++t) {
    const int j = static_cast<int>(rng() % 45);
    int x0 = static_cast<int>(rng() % 203), x1 = static_cast<int>(rng() % 203);
    if (x0 > x1) std::swap(x0, x1);
    int first = -1, last = -1;
    for (int i = x0; i <= x1; ++i)
      if (img.get(i, j)) {
        if (first < 0) first = i;
        last = i;
      }
    ASSERT_EQ(img.first_set(j, x0, x1), first) << j << " " << x0 << " " << x1;
    ASSERT_EQ(img.last_set(j, x0, x1), last) << j << " " << x0 << " " << x1;
  }
  const BitImage blocks = block_occupancy(img);
  ASSERT_EQ(blocks.height(), (45 + 7) / 8);
  ASSERT_GE(blocks.width(), (203 + 7) / 8);
  for (int b = 0; b < blocks.height(); ++b)
    for (int k = 0; k < blocks.width(); ++k) {
      bool any = false;
      for (int j = 8 * b; j < std::min(45, 8 * b + 8); ++j)
        for (int i = 8 * k; i < std::min(203, 8 * k + 8); ++i)
          any = any || img.get(i, j);
      ASSERT_EQ(blocks.get(k, b), any) << "block " << k << " " << b;
    }
}

// Sparse material (the case the block occupancy skips rows and columns for), a long run of
// cuts that empties blocks, and every count checked against brute force after each cut:
// with and without the clearance map (the two probe branches), disks and crescents.
TEST(PixelStock, CountsStayExactWhileCutsEmptyTheBlocks) {
  Fixture f = random_image(3);
  f.grid.h = 0.125;  // pixel coordinates of the probes below are exact binary fractions
  f.material = BitImage(f.grid.width, f.grid.height);
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int blob = 0; blob < 12; ++blob) {  // discs and thin strips of material
    const Vec2 c{20.0 + 260.0 * u(rng), 20.0 + 220.0 * u(rng)};
    const double r = 2.0 + 14.0 * u(rng);
    for (int j = 4; j < f.grid.height - 4; ++j)
      for (int i = 4; i < f.grid.width - 4; ++i)
        if (in_disk(i, j, c, r) || (blob % 3 == 0 && std::abs(j - c.y) < 1.0))
          f.material.set(i, j, true);
  }
  for (int isle = 0; isle < 3; ++isle) {  // small forbidden squares inside
    const int i0 = 30 + static_cast<int>(rng() % 230), j0 = 30 + static_cast<int>(rng() % 190);
    for (int j = j0; j < j0 + 5; ++j)
      for (int i = i0; i < i0 + 5; ++i) {
        f.forbidden.set(i, j, true);
        f.material.set(i, j, false);
      }
  }
  const std::vector<float> clearance = squared_distance_transform(f.forbidden, true);
  const double r_px = 25.0;
  for (const std::vector<float>* cl :
       {static_cast<const std::vector<float>*>(nullptr), &clearance}) {
    PixelStock stock(f.grid, f.material, f.forbidden, r_px * f.grid.h, cl);
    BitImage truth = f.material;  // the material, cut by brute force alongside
    int checked_material = 0;
    for (int t = 0; t < 250; ++t) {
      // In pixels: centres anywhere in x, on the stock's 1/64 pixel lattice in y.
      const Vec2 pa{26.0 + 248.0 * u(rng), 26.0 + std::round(64.0 * 208.0 * u(rng)) / 64.0};
      const double ang = 6.283 * u(rng);
      const Vec2 pb{pa.x + 6.0 * std::cos(ang),
                    pa.y + std::round(64.0 * 6.0 * std::sin(ang)) / 64.0};
      const Vec2 a = pa * f.grid.h, b = pb * f.grid.h;
      // probe's contract: the tool has been at `a`, so its disk holds no forbidden pixel.
      bool a_free = true;
      for (int j = 0; j < f.grid.height; ++j)
        for (int i = 0; i < f.grid.width; ++i)
          a_free = a_free && !(in_disk(i, j, pa, r_px) && f.forbidden.get(i, j));
      if (!a_free) continue;
      int crescent = 0, disk = 0;
      bool gouge = pb.x - r_px < 0 || pb.y - r_px < 0 || pb.x + r_px > f.grid.width - 1 ||
                   pb.y + r_px > f.grid.height - 1;
      bool disk_gouge = gouge;
      for (int j = 0; j < f.grid.height; ++j)
        for (int i = 0; i < f.grid.width; ++i) {
          if (!in_disk(i, j, pb, r_px)) continue;
          disk += truth.get(i, j) ? 1 : 0;
          disk_gouge = disk_gouge || f.forbidden.get(i, j);
          if (in_disk(i, j, pa, r_px)) continue;
          crescent += truth.get(i, j) ? 1 : 0;
          gouge = gouge || f.forbidden.get(i, j);
        }
      ASSERT_EQ(stock.gouges(b), disk_gouge) << "gouges " << t;
      ASSERT_EQ(stock.material_in_disk(b, r_px * f.grid.h), disk) << "material_in_disk " << t;
      ASSERT_EQ(stock.probe(a, b), gouge ? PixelStock::kGouge : crescent) << "probe " << t;
      if (!disk_gouge) {
        ASSERT_EQ(stock.probe_disk(b), disk) << "probe_disk " << t;
      }
      if (gouge) continue;
      checked_material += crescent;
      ASSERT_EQ(stock.cut(a, b), crescent) << "cut " << t;
      for (int j = 0; j < f.grid.height; ++j)
        for (int i = 0; i < f.grid.width; ++i)
          if (in_disk(i, j, pb, r_px) && !in_disk(i, j, pa, r_px)) truth.set(i, j, false);
    }
    EXPECT_GT(checked_material, 2000);  // the cuts did meet material
    EXPECT_EQ(stock.material().count_all(), truth.count_all());
  }
}

TEST(PixelStock, AdaptivePocketDoesNotDependOnTheCpuPath) {
  const Pocket p = make_pocket({{0, 0}, {40, 0}, {40, 30}, {20, 30}, {20, 18}, {0, 18}},
                               {{{8, 6}, {12, 6}, {12, 10}, {8, 10}}}, "L with a square island")
                       .value();
  Tool tool;
  tool.diameter_mm = 6.0;
  AdaptiveParams ap;
  ap.stepover_mm = 0.9;
  ap.depth_mm = 2.0;
  auto fast = adaptive_pocket(p, tool, ap);
  PixelStock::allow_cpu_features(false);
  auto portable = adaptive_pocket(p, tool, ap);
  PixelStock::allow_cpu_features(true);
  ASSERT_TRUE(fast.ok() && portable.ok());
  ASSERT_EQ(fast->toolpath.moves.size(), portable->toolpath.moves.size());
  for (std::size_t k = 0; k < fast->toolpath.moves.size(); ++k)
    ASSERT_EQ(fast->toolpath.moves[k].end, portable->toolpath.moves[k].end) << "move " << k;
  ASSERT_EQ(fast->steps.size(), portable->steps.size());
  for (std::size_t k = 0; k < fast->steps.size(); ++k)
    ASSERT_EQ(fast->steps[k].engagement_px, portable->steps[k].engagement_px) << "step " << k;
}

}  // namespace
}  // namespace swarf::pocket
