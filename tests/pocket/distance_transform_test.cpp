// The exact distance transform and the disk dilation against brute force on small random
// images: the pocket's clearance map, material set-up and plunge point rest on them.
#include "pocket/distance_transform.h"

#include <gtest/gtest.h>

#include <random>

namespace swarf::pocket {
namespace {

// Random blobs (so that the set has long boundaries and interiors) plus scattered pixels.
BitImage random_blobs(int w, int h, unsigned seed) {
  BitImage img(w, h);
  std::mt19937 rng(seed);
  for (int b = 0; b < 6; ++b) {
    const double cx = rng() % static_cast<unsigned>(w), cy = rng() % static_cast<unsigned>(h);
    const double r = 2.0 + static_cast<double>(rng() % 9);
    for (int j = 0; j < h; ++j)
      for (int i = 0; i < w; ++i)
        if ((i - cx) * (i - cx) + (j - cy) * (j - cy) <= r * r) img.set(i, j, true);
  }
  for (int k = 0; k < 25; ++k)
    img.set(static_cast<int>(rng() % static_cast<unsigned>(w)),
            static_cast<int>(rng() % static_cast<unsigned>(h)), true);
  return img;
}

// Smallest squared distance from (i, j) to a pixel whose bit is `value`; -1 if none.
long brute_sq(const BitImage& img, int i, int j, bool value) {
  long best = -1;
  for (int q = 0; q < img.height(); ++q)
    for (int p = 0; p < img.width(); ++p)
      if (img.get(p, q) == value) {
        const long d = static_cast<long>(p - i) * (p - i) + static_cast<long>(q - j) * (q - j);
        if (best < 0 || d < best) best = d;
      }
  return best;
}

TEST(DistanceTransform, ExactSquaredDistancesToTheNearestFeature) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const BitImage img = random_blobs(70 + static_cast<int>(seed), 45, seed);
    for (bool value : {true, false}) {
      const std::vector<float> d = squared_distance_transform(img, value);
      for (int j = 0; j < img.height(); ++j)
        for (int i = 0; i < img.width(); ++i) {
          const long want = brute_sq(img, i, j, value);
          ASSERT_EQ(static_cast<long>(
                        d[static_cast<std::size_t>(j) * static_cast<std::size_t>(img.width()) +
                          static_cast<std::size_t>(i)]),
                    want)
              << "seed " << seed << " value " << value << " at " << i << "," << j;
        }
    }
  }
}

// The rows are transformed run by run between features: rows with none, features only at
// the row's ends, or a single free pixel between two, against brute force.
TEST(DistanceTransform, RowsWithFeaturesAtTheirEndsOrNoneAtAll) {
  BitImage img(9, 5);
  img.set(0, 1, true);
  img.set(8, 1, true);  // row 1: features at both ends
  img.set(3, 2, true);
  img.set(5, 2, true);  // row 2: one free pixel between two features
  for (int i = 0; i < 9; ++i)
    img.set(i, 4, i != 6);  // row 4: a single free pixel; rows 0 and 3 have no feature
  const std::vector<float> d = squared_distance_transform(img, true);
  for (int j = 0; j < 5; ++j)
    for (int i = 0; i < 9; ++i)
      ASSERT_EQ(static_cast<long>(d[static_cast<std::size_t>(j) * 9 + static_cast<std::size_t>(i)]),
                brute_sq(img, i, j, true))
          << i << "," << j;
  // No feature anywhere: every pixel is far (the transform's infinity), none is 0.
  const std::vector<float> none = squared_distance_transform(BitImage(7, 3), true);
  for (float v : none)
    EXPECT_GT(v, 1e19f);
}

TEST(DistanceTransform, DiskDilationIsTheThresholdedTransform) {
  for (unsigned seed : {4u, 5u}) {
    // Width not a multiple of 64 and more than one word: the word-wise boundary test sees
    // the carries between words and the padding past the width.
    const BitImage img = random_blobs(150, 60, seed);
    const std::vector<float> d = squared_distance_transform(img, true);
    for (double r : {0.0, 1.0, 1.5, 4.0, 7.3, 12.0}) {
      const BitImage dil = dilate_by_disk(img, r);
      int inside = 0;
      for (int j = 0; j < img.height(); ++j)
        for (int i = 0; i < img.width(); ++i) {
          const bool want =
              static_cast<double>(
                  d[static_cast<std::size_t>(j) * 150 + static_cast<std::size_t>(i)]) <= r * r;
          ASSERT_EQ(dil.get(i, j), want)
              << "seed " << seed << " r " << r << " at " << i << "," << j;
          inside += want ? 1 : 0;
        }
      EXPECT_EQ(dil.count_all(), static_cast<std::size_t>(inside)) << "bits past the width";
    }
  }
}

// The one-pixel question the link search asks instead of dilating its window: the same
// answer as dilating the image cut down to the window, at every pixel in and round it.
TEST(DistanceTransform, OnePixelNearTestAgreesWithTheDilatedWindow) {
  const BitImage img = random_blobs(150, 60, 6u);
  const int x0 = 20, y0 = 9, x1 = 131, y1 = 47;
  BitImage window(img.width(), img.height());
  for (int j = y0; j <= y1; ++j)
    for (int i = x0; i <= x1; ++i)
      window.set(i, j, img.get(i, j));
  for (double r : {0.0, 1.5, 4.0, 7.3}) {
    const BitImage dil = dilate_by_disk(window, r);
    const std::vector<int> half = disk_half_widths(r);
    int near = 0;
    for (int j = 0; j < img.height(); ++j)
      for (int i = 0; i < img.width(); ++i) {
        ASSERT_EQ(near_set_pixel(img, half, i, j, x0, y0, x1, y1), dil.get(i, j))
            << "r " << r << " at " << i << "," << j;
        near += dil.get(i, j) ? 1 : 0;
      }
    EXPECT_GT(near, 0);
    EXPECT_LT(near, img.width() * img.height());
  }
  EXPECT_TRUE(disk_half_widths(-1.0).empty());
}

}  // namespace
}  // namespace swarf::pocket
