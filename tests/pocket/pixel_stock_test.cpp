// The pixel stock's counts against brute force, and the same answers from the portable and
// the POPCNT/SSE4.1 code paths (pixel_stock.cpp chooses at run time).
#include "pocket/pixel_stock.h"

#include <gtest/gtest.h>

#include <random>

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
