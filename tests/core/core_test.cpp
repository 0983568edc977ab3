#include <gtest/gtest.h>

#include <atomic>
#include <numeric>
#include <stdexcept>
#include <vector>

#include "swarf/core/parallel.h"
#include "swarf/core/status.h"
#include "swarf/core/vec.h"

namespace swarf {
namespace {

TEST(Vec, RotationKeepsLengthAndTurnsCounterClockwise) {
  const Vec2 v = rotated({2.0, 0.0}, deg_to_rad(90.0));
  EXPECT_NEAR(v.x, 0.0, 1e-12);
  EXPECT_NEAR(v.y, 2.0, 1e-12);
  EXPECT_GT(cross(Vec2{1, 0}, v), 0.0);
  EXPECT_NEAR(norm(rotated({3.0, 4.0}, 1.234)), 5.0, 1e-12);
}

TEST(Vec, CrossProductIsRightHanded) {
  const Vec3 z = cross(Vec3{1, 0, 0}, Vec3{0, 1, 0});
  EXPECT_EQ(z, (Vec3{0, 0, 1}));
}

TEST(Box, EmptyUntilAPointIsAdded) {
  Box3 b;
  EXPECT_TRUE(b.empty());
  b.add({1, 2, 3});
  b.add({-1, 0, 5});
  EXPECT_FALSE(b.empty());
  EXPECT_EQ(b.size(), (Vec3{2, 2, 2}));
  EXPECT_TRUE(b.contains({0, 1, 4}));
  EXPECT_FALSE(b.contains({0, 1, 6}));
}

TEST(Status, CarriesCodeMessageAndContext) {
  const Status s = bad_input("triangle 3: NaN coordinate").with_context("part.stl");
  EXPECT_FALSE(s.ok());
  EXPECT_EQ(s.code(), Error::kBadInput);
  EXPECT_EQ(s.to_string(), "bad input: part.stl: triangle 3: NaN coordinate");
}

TEST(Result, HoldsValueOrFailure) {
  Result<int> good = 4;
  Result<int> bad = Status{Error::kToolTooLarge, "ø20 tool in a 10 mm slot"};
  ASSERT_TRUE(good.ok());
  EXPECT_EQ(*good, 4);
  EXPECT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().code(), Error::kToolTooLarge);
}

TEST(ParallelFor, VisitsEveryIndexOnceWhateverTheThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    std::vector<std::atomic<int>> hits(1000);
    parallel_for(hits.size(), threads, [&](std::size_t i) { hits[i]++; });
    for (const auto& h : hits)
      ASSERT_EQ(h.load(), 1);
  }
}

TEST(ParallelFor, ResultsDoNotDependOnThreads) {
  auto run = [](int threads) {
    std::vector<double> out(5000);
    parallel_for(out.size(), threads, [&](std::size_t i) { out[i] = std::sqrt(double(i)) * 3.0; });
    return out;
  };
  EXPECT_EQ(run(1), run(4));
}

TEST(ParallelFor, RethrowsTheWorkersException) {
  EXPECT_THROW(parallel_for(100, 4,
                            [](std::size_t i) {
                              if (i == 57) throw std::runtime_error("boom");
                            }),
               std::runtime_error);
}

}  // namespace
}  // namespace swarf
