#include <gtest/gtest.h>

#include <cmath>

#include "swarf/voxel/voxel.h"
#include "voxel/voxel_test_util.h"

namespace swarf {
namespace {

using voxel_test::heightfield;
using voxel_test::linspace;

int crossings(const VoxelModel& m, int i, int j) {
  return static_cast<int>(m.offsets[m.column(i, j) + 1] - m.offsets[m.column(i, j)]);
}

TEST(Voxelize, RaysThroughVerticesAndEdgesCountOnce) {
  // A 10 x 10 x 5 box whose triangulated faces have their vertices and diagonals exactly on
  // the column centres (cell 1 mm, centres at integer + 0.5 ... moved onto integers by the
  // stock margin), and a pyramid roof with its apex on a ray.
  const Mesh roof = heightfield(
      linspace(0, 10, 10), linspace(0, 10, 10),
      [](double x, double y) {
        return 5.0 + 0.3 * std::min({x, 10 - x, y, 10 - y});
      },
      0.0);
  VoxelizeOptions o;
  o.cell_mm = 1.0;
  o.layer_mm = 1.0;
  o.stock = Box3{{-0.5, -0.5, 0.0}, {10.5, 10.5, 8.0}};  // centres at integers 0..10
  auto m = voxelize(roof, o);
  ASSERT_TRUE(m.ok()) << m.status().to_string();
  ASSERT_EQ(m->nx, 11);
  EXPECT_DOUBLE_EQ(m->centre(0, 0).x, 0.0);
  for (int j = 0; j < m->ny; ++j) {
    for (int i = 0; i < m->nx; ++i) {
      const int n = crossings(*m, i, j);
      EXPECT_EQ(n % 2, 0) << i << "," << j;
      if (i > 0 && i < 10 && j > 0 && j < 10) {
        // Strictly inside the footprint: one solid interval from the bottom to the roof,
        // although every ray passes through vertices or diagonals of the triangulation.
        ASSERT_EQ(n, 2) << i << "," << j;
        const double roof_z = 5.0 + 0.3 * std::min({i, 10 - i, j, 10 - j});
        EXPECT_NEAR(m->crossings[m->offsets[m->column(i, j)]], 0.0, 1e-12);
        EXPECT_NEAR(m->centre_top(i, j), roof_z, 1e-12);
      }
    }
  }
}

TEST(Voxelize, VolumeOfAWavyHeightfieldMatchesItsIntegral) {
  auto f = [](double x, double y) { return 20.0 + 8.0 * std::sin(x / 9.0) * std::cos(y / 7.0); };
  const Mesh part = heightfield(linspace(0, 60, 120), linspace(0, 60, 120), f, 0.0);
  VoxelizeOptions o;
  o.cell_mm = 1.0;
  o.layer_mm = 0.5;
  auto m = voxelize(part, o);
  ASSERT_TRUE(m.ok());
  double vox = 0.0, exact = 0.0;
  for (int j = 0; j < m->ny; ++j) {
    for (int i = 0; i < m->nx; ++i) {
      for (int k = 0; k < m->layers; ++k)
        vox += m->filled(i, j, k) ? 0.5 : 0.0;
      const Vec2 c = m->centre(i, j);
      exact += f(c.x, c.y);  // midpoint rule, 1 mm^2 per column
    }
  }
  // Layer rounding adds at most one layer per column above the surface.
  EXPECT_GE(vox, exact - 1e-6);
  EXPECT_LE(vox, exact + 0.5 * m->nx * m->ny + 1e-6);
}

TEST(Voxelize, CellTopIsTheExactMaximumOverTheSquare) {
  // A tilted plane z = 10 + 0.5 x + 0.25 y: the top over a square is at its (max x, max y)
  // corner, clipped to the part.
  const Mesh part = heightfield(
      linspace(0, 20, 3), linspace(0, 20, 3),
      [](double x, double y) { return 10 + 0.5 * x + 0.25 * y; }, 0);
  VoxelizeOptions o;
  o.cell_mm = 3.0;
  o.layer_mm = 1.0;
  o.margin_mm = 2.0;
  auto m = voxelize(part, o);
  ASSERT_TRUE(m.ok());
  for (int j = 0; j < m->ny; ++j) {
    for (int i = 0; i < m->nx; ++i) {
      const Vec2 c = m->centre(i, j);
      const double x1 = std::min(c.x + 1.5, 20.0), y1 = std::min(c.y + 1.5, 20.0);
      const bool touches = c.x + 1.5 >= 0 && c.x - 1.5 <= 20 && c.y + 1.5 >= 0 && c.y - 1.5 <= 20;
      if (touches) {
        EXPECT_NEAR(m->cell_top[m->column(i, j)], 10 + 0.5 * x1 + 0.25 * y1, 1e-9);
      } else {
        EXPECT_TRUE(std::isinf(m->cell_top[m->column(i, j)]));
      }
    }
  }
}

TEST(Voxelize, OpenMeshIsRejectedOrRepairedWithAWarning) {
  Mesh part = heightfield(
      linspace(0, 10, 4), linspace(0, 10, 4), [](double, double) { return 5.0; }, 0.0);
  part.triangles.erase(part.triangles.begin());  // a hole in the top face
  VoxelizeOptions o;
  o.cell_mm = 1.0;
  auto rejected = voxelize(part, o);
  ASSERT_FALSE(rejected.ok());
  EXPECT_EQ(rejected.status().code(), Error::kOpenMesh);
  o.repair_open = true;
  auto repaired = voxelize(part, o);
  ASSERT_TRUE(repaired.ok());
  EXPECT_FALSE(repaired->warnings.empty());
  // A hole in a vertical wall is crossed by no column ray: parity holds, nothing to repair.
  Mesh walled = heightfield(
      linspace(0, 10, 4), linspace(0, 10, 4), [](double, double) { return 5.0; }, 0.0);
  walled.triangles.pop_back();
  o.repair_open = false;
  auto fine = voxelize(walled, o);
  ASSERT_TRUE(fine.ok());
  EXPECT_TRUE(fine->warnings.empty());
  EXPECT_EQ(check_edges(walled).open_edges, 3u);
  const EdgeCheck e = check_edges(part);
  EXPECT_EQ(e.open_edges, 3u);
}

TEST(Voxelize, IdenticalForAnyThreadCount) {
  auto f = [](double x, double y) { return 5.0 + 3.0 * std::sin(x / 4.0 + y / 5.0); };
  const Mesh part = heightfield(linspace(0, 40, 50), linspace(0, 30, 40), f, 0.0);
  VoxelizeOptions o;
  o.cell_mm = 0.7;
  Context one, many;
  one.threads = 1;
  many.threads = 4;
  auto a = voxelize(part, o, one), b = voxelize(part, o, many);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->offsets, b->offsets);
  EXPECT_EQ(a->crossings, b->crossings);
  EXPECT_EQ(a->cell_top, b->cell_top);
}

}  // namespace
}  // namespace swarf
