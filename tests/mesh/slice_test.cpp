#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "swarf/mesh/generate.h"
#include "swarf/mesh/slice.h"
#include "swarf/mesh/stl.h"

namespace swarf {
namespace {

int count_outers(const PolygonSet& s) {
  int n = 0;
  for (const Ring& r : s.rings)
    n += signed_area(r) > 0 ? 1 : 0;
  return n;
}

// Regular octahedron |x| + |y| + |z| <= 1: every axis plane through the origin passes
// through four vertices exactly.
Mesh octahedron() {
  Mesh m;
  m.vertices = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  m.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                 {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return m;
}

TEST(SliceLevels, CentredWithEqualMargins) {
  EXPECT_EQ(slice_levels(0, 1, 0.25), (std::vector<double>{0, 0.25, 0.5, 0.75, 1}));
  const std::vector<double> l = slice_levels(0, 1, 0.3);
  ASSERT_EQ(l.size(), 4u);
  EXPECT_NEAR(l[0], 0.05, 1e-12);
  EXPECT_NEAR(l[3], 0.95, 1e-12);
  EXPECT_EQ(slice_levels(0, 0.3, 0.1).size(), 4u);  // 0.3 / 0.1 is 2.9999999999999996
  EXPECT_EQ(slice_levels(2, 2, 0.1), (std::vector<double>{2}));
  EXPECT_EQ(slice_levels(0, 1, 2), (std::vector<double>{0.5}));
  EXPECT_TRUE(slice_levels(0, 1, 0).empty());
  EXPECT_TRUE(slice_levels(1, 0, 0.1).empty());
  EXPECT_TRUE(slice_levels(0, 1, std::nan("")).empty());
}

TEST(Slice, PlaneCoordinatesAreCyclicAndInvertible) {
  const Vec3 p{1, 2, 3};
  EXPECT_EQ(to_plane(p, Axis::kZ), (Vec2{1, 2}));
  EXPECT_EQ(to_plane(p, Axis::kX), (Vec2{2, 3}));
  EXPECT_EQ(to_plane(p, Axis::kY), (Vec2{3, 1}));
  for (Axis a : {Axis::kX, Axis::kY, Axis::kZ})
    EXPECT_EQ(from_plane(to_plane(p, a), p[static_cast<int>(a)], a), p);
}

TEST(Slice, BoxSectionsAreExactOnEveryAxis) {
  const Mesh box = make_box({{-1, -2, -3}, {4, 5, 6}});  // 5 x 7 x 9
  const std::vector<double> z{-3.5, -3, -1, 0, 5.999, 6, 6.5};
  const auto s = slice_mesh(box, Axis::kZ, z);
  EXPECT_TRUE(s[0].empty());
  EXPECT_TRUE(s[1].empty());  // the bottom face plane: vertices there count as above
  EXPECT_DOUBLE_EQ(area(s[2]), 35.0);
  EXPECT_DOUBLE_EQ(area(s[3]), 35.0);
  EXPECT_DOUBLE_EQ(area(s[4]), 35.0);
  EXPECT_DOUBLE_EQ(area(s[5]), 35.0);  // the top face plane: the section just below it
  EXPECT_TRUE(s[6].empty());
  ASSERT_EQ(s[3].rings.size(), 1u);
  EXPECT_EQ(s[3].rings[0].size(), 4u);
  // Other axes, in their cyclic plane coordinates, counter-clockwise.
  const auto sx = slice_mesh(box, Axis::kX, {0.0, 4.0});
  EXPECT_DOUBLE_EQ(area(sx[0]), 7.0 * 9.0);
  EXPECT_DOUBLE_EQ(area(sx[1]), 7.0 * 9.0);
  EXPECT_EQ(bounds(sx[0]).min, (Vec2{-2, -3}));  // (y, z)
  const auto sy = slice_mesh(box, Axis::kY, {1.0});
  EXPECT_DOUBLE_EQ(area(sy[0]), 9.0 * 5.0);
  EXPECT_EQ(bounds(sy[0]).min, (Vec2{-3, -1}));  // (z, x)
}

TEST(Slice, PlanesThroughVerticesAndEdgesGiveClosedLoops) {
  const Mesh m = octahedron();
  for (Axis a : {Axis::kX, Axis::kY, Axis::kZ}) {
    const auto s = slice_mesh(m, a, {0.0, 0.5, -0.5, 1.0, -1.0});
    ASSERT_EQ(s[0].rings.size(), 1u);
    EXPECT_DOUBLE_EQ(area(s[0]), 2.0);  // the square |u| + |v| <= 1
    EXPECT_DOUBLE_EQ(area(s[1]), 0.5);  // |u| + |v| <= 0.5
    EXPECT_DOUBLE_EQ(area(s[2]), 0.5);
    EXPECT_TRUE(s[3].empty());  // only the apex vertex touches the plane
    EXPECT_TRUE(s[4].empty());
  }
}

TEST(Slice, StepTopsAndFaceEdgesInThePlane) {
  // The block's top and the boss tops are planes full of vertices and edges.
  const Mesh m = make_block_with_bosses({100, 80, 20}, 10, 5);
  const auto s = slice_mesh(m, Axis::kZ, {20.0, 25.0, 22.5, 0.0});
  EXPECT_DOUBLE_EQ(area(s[0]), 100.0 * 80.0);  // just below the block top
  EXPECT_EQ(s[0].rings.size(), 1u);
  EXPECT_DOUBLE_EQ(area(s[1]), 4 * 100.0);  // just below the boss tops
  EXPECT_EQ(count_outers(s[1]), 4);
  EXPECT_DOUBLE_EQ(area(s[2]), 4 * 100.0);
  EXPECT_TRUE(s[3].empty());
  // Side planes through the boss walls [20, 30] in x: at x = 20 the section is taken just
  // below the plane (vertices on it count as above), so the boss is not in it; at x = 30
  // it is.
  const auto sx = slice_mesh(m, Axis::kX, {20.0, 30.0, 25.0});
  EXPECT_DOUBLE_EQ(area(sx[0]), 80.0 * 20);
  EXPECT_DOUBLE_EQ(area(sx[1]), 80.0 * 20 + 2 * 10.0 * 5);
  EXPECT_DOUBLE_EQ(area(sx[2]), 80.0 * 20 + 2 * 10.0 * 5);
}

TEST(Slice, CylinderSectionIsItsPolygon) {
  const int n = 48;
  const double r = 6.0;
  const Mesh m = make_cylinder({1, 1, 0}, r, 10, n);
  const auto s = slice_mesh(m, Axis::kZ, {0.0, 0.001, 5.0, 10.0});
  EXPECT_TRUE(s[0].empty());
  const double ngon = 0.5 * n * r * r * std::sin(2 * kPi / n);
  // Up to snapping to the 1e-5 mm polygon grid (about perimeter x resolution).
  const double snap = 2 * kPi * r * kPolygonResolutionMm;
  for (int i = 1; i < 4; ++i)
    EXPECT_NEAR(area(s[i]), ngon, snap);
  // Through the axis (x = 1, vertices at angles 90 and 270 degrees lie on it): rectangle
  // of height 10 and width 2 r.
  const auto sx = slice_mesh(m, Axis::kX, {1.0});
  EXPECT_NEAR(area(sx[0]), 2 * r * 10, 1e-9);
}

TEST(Slice, SphereSectionsApproachTheCircle) {
  const double R = 10.0;
  const int n = 128;
  const Mesh m = make_sphere({0, 0, 0}, R, n);
  const std::vector<double> levels = slice_levels(-9.9, 9.9, 0.9);
  for (Axis a : {Axis::kZ, Axis::kX}) {
    const auto s = slice_mesh(m, a, levels);
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const double exact = kPi * (R * R - levels[i] * levels[i]);
      // The polyhedron is inscribed in the sphere and, being convex with every face plane
      // at least R cos(2 pi / n) from the centre, contains the sphere of that radius.
      const double inner = R * std::cos(2 * kPi / n);
      EXPECT_LE(area(s[i]), exact * (1 + 1e-9));
      EXPECT_GE(area(s[i]), kPi * (inner * inner - levels[i] * levels[i])) << levels[i];
      EXPECT_NEAR(area(s[i]), exact, exact * 0.01 + 0.5) << levels[i];
      ASSERT_EQ(s[i].rings.size(), 1u);
      EXPECT_GT(signed_area(s[i].rings[0]), 0.0);
    }
  }
}

TEST(Slice, TorusGivesAnnulusWithClockwiseHole) {
  const Mesh m = make_torus({0, 0, 0}, 20, 5, 128, 64);
  for (Axis a : {Axis::kZ}) {
    const auto s = slice_mesh(m, a, {0.0, 3.0});
    ASSERT_EQ(s[0].rings.size(), 2u);
    const double outer = std::max(signed_area(s[0].rings[0]), signed_area(s[0].rings[1]));
    const double hole = std::min(signed_area(s[0].rings[0]), signed_area(s[0].rings[1]));
    EXPECT_GT(outer, 0);
    EXPECT_LT(hole, 0);
    EXPECT_NEAR(area(s[0]), kPi * (25.0 * 25.0 - 15.0 * 15.0), 0.01 * kPi * 400);
    const double w = std::sqrt(25.0 - 9.0);
    EXPECT_NEAR(area(s[1]), kPi * ((20 + w) * (20 + w) - (20 - w) * (20 - w)), 0.01 * kPi * 400);
  }
  // Through the axis: two disks of radius 5.
  const auto sx = slice_mesh(m, Axis::kX, {0.0});
  EXPECT_EQ(count_outers(sx[0]), 2);
  EXPECT_NEAR(area(sx[0]), 2 * kPi * 25, 0.01 * 2 * kPi * 25);
}

TEST(Slice, ResultsDoNotDependOnThreads) {
  const Mesh m = make_filleted_torus_part({});
  const std::vector<double> levels = slice_levels(-10, 20, 0.37);
  Context one, four;
  one.threads = 1;
  four.threads = 4;
  for (Axis a : {Axis::kX, Axis::kZ}) {
    const auto s1 = slice_mesh(m, a, levels, {}, one);
    const auto s4 = slice_mesh(m, a, levels, {}, four);
    ASSERT_EQ(s1.size(), s4.size());
    for (std::size_t i = 0; i < s1.size(); ++i) {
      ASSERT_EQ(s1[i].rings.size(), s4[i].rings.size());
      for (std::size_t r = 0; r < s1[i].rings.size(); ++r)
        EXPECT_EQ(s1[i].rings[r], s4[i].rings[r]);
    }
  }
}

// The per-level triangle lists are built from the levels sorted: levels given out of order,
// repeated, on vertices, outside the part or not finite must each get the section that a call
// with that level alone gives, on every axis of the three-axis call.
TEST(Slice, ThreeAxisCallEqualsOneLevelAtATime) {
  const Mesh m = make_filleted_torus_part({});
  const std::vector<double> base = {3.0,  -7.25, 0.0,  12.5, 3.0,         1e9,
                                    -1e9, 5.125, 20.0, -0.5, std::nan("")};
  std::array<std::vector<double>, 3> levels = {base, base, base};
  levels[2] = {0.0, 2.0, 0.5, 2.0, 1.0, -3.0, 4.0};  // z: plate top, fillet, ring
  const auto all = slice_mesh_axes(m, levels);
  for (std::size_t a = 0; a < 3; ++a) {
    ASSERT_EQ(all[a].size(), levels[a].size());
    for (std::size_t i = 0; i < levels[a].size(); ++i) {
      const auto one = slice_mesh(m, static_cast<Axis>(a), {levels[a][i]});
      ASSERT_EQ(one.size(), 1u);
      EXPECT_EQ(all[a][i].rings, one[0].rings) << "axis " << a << " level " << levels[a][i];
    }
  }
  EXPECT_FALSE(all[0][0].empty());
  EXPECT_TRUE(all[0][5].empty());   // beyond the part
  EXPECT_TRUE(all[0][10].empty());  // NaN
}

TEST(Slice, OpenMeshChainsAreJoinedOrClosed) {
  const Mesh box = make_box({{0, 0, 0}, {2, 3, 4}});
  // Unweld the +x face: its two triangles get their own vertex copies at the same place.
  Mesh split = box;
  for (auto& t : split.triangles) {
    bool on_face = true;
    for (int k = 0; k < 3; ++k)
      on_face &= split.vertices[t[k]].x == 2.0;
    if (!on_face) continue;
    for (int k = 0; k < 3; ++k) {
      split.vertices.push_back(split.vertices[t[k]]);
      t[k] = static_cast<std::uint32_t>(split.vertices.size() - 1);
    }
  }
  EXPECT_FALSE(check_mesh(split).closed());
  EXPECT_DOUBLE_EQ(area(slice_mesh(split, Axis::kZ, {1.0})[0]), 6.0);
  // Remove a side face entirely: the open chain is closed by its chord, same section.
  Mesh open = box;
  std::erase_if(open.triangles, [&](const auto& t) {
    return open.vertices[t[0]].y == 0 && open.vertices[t[1]].y == 0 && open.vertices[t[2]].y == 0;
  });
  EXPECT_EQ(open.size(), 10u);
  EXPECT_DOUBLE_EQ(area(slice_mesh(open, Axis::kZ, {1.0})[0]), 6.0);
}

TEST(Slice, RealPocketPart) {
  const Result<StlFile> f =
      read_stl(std::string(SWARF_TEST_DATA_DIR) + "/mesh/kirimoto_pocket-test.stl");
  ASSERT_TRUE(f.ok());
  const auto s = slice_mesh(f->mesh, Axis::kZ, {5.0, 10.0, 15.0, 18.0});
  EXPECT_DOUBLE_EQ(area(s[0]), 100.0 * 100);
  EXPECT_DOUBLE_EQ(area(s[1]), 100.0 * 100);  // the pocket floor plane: section below it
  EXPECT_DOUBLE_EQ(area(s[2]), 100.0 * 100 - 40.0 * 40);
  EXPECT_EQ(s[2].rings.size(), 2u);
  EXPECT_FALSE(contains(s[2], {0, 0}));
  EXPECT_DOUBLE_EQ(area(s[3]), 100.0 * 100 - 40.0 * 40);
}

// Cavalieri: the integral of the section area along an axis is the volume, which
// check_mesh computes independently by the divergence theorem.
double cavalieri_volume(const Mesh& m, Axis axis, int n) {
  const Box3 b = bounds(m);
  const double lo = b.min[static_cast<int>(axis)], hi = b.max[static_cast<int>(axis)];
  const double pitch = (hi - lo) / n;
  const std::vector<double> levels = slice_levels(lo + 0.5 * pitch, hi - 0.5 * pitch, pitch);
  double v = 0.0;
  for (const PolygonSet& s : slice_mesh(m, axis, levels))
    v += area(s) * pitch;
  return v;
}

TEST(Slice, SectionAreasIntegrateToTheVolumeOfRealParts) {
  for (const char* name : {"opencamlib_ktoolcav.stl", "openscad_bad-stl-pcbvicebar.stl"}) {
    const Result<StlFile> f = read_stl(std::string(SWARF_TEST_DATA_DIR) + "/mesh/" + name);
    ASSERT_TRUE(f.ok()) << f.status().to_string();
    const double v = std::abs(f->check.volume_mm3);
    for (Axis a : {Axis::kX, Axis::kY, Axis::kZ})
      EXPECT_NEAR(cavalieri_volume(f->mesh, a, 300), v, 0.005 * v)
          << name << " axis " << static_cast<int>(a);
  }
}

TEST(Slice, SectionAreasIntegrateToTheVolumeOfTheTorusPart) {
  const Mesh m = make_filleted_torus_part({});
  const double v = check_mesh(m).volume_mm3;
  for (Axis a : {Axis::kX, Axis::kZ})
    EXPECT_NEAR(cavalieri_volume(m, a, 300), v, 0.002 * v);
}

TEST(Slice, OpenSurfacesGiveNormalizedSections) {
  // opencamlib's demo scene: open domes and a torus surface over a base plane.
  const Result<StlFile> f =
      read_stl(std::string(SWARF_TEST_DATA_DIR) + "/mesh/opencamlib_demo.stl");
  ASSERT_TRUE(f.ok());
  const auto s = slice_mesh(f->mesh, Axis::kZ, slice_levels(0.05, 1.95, 0.1));
  int non_empty = 0;
  for (const PolygonSet& p : s) {
    non_empty += p.empty() ? 0 : 1;
    EXPECT_LE(area(p), 100.0 + 1e-9);
    EXPECT_NEAR(area(normalized(p)), area(p), 1e-9);
    for (const Ring& r : p.rings)
      EXPECT_GE(r.size(), 3u);
  }
  EXPECT_GT(non_empty, 10);
}

TEST(Slice, EmptyInputs) {
  EXPECT_TRUE(slice_mesh(Mesh{}, Axis::kZ, {0.0})[0].empty());
  EXPECT_TRUE(slice_mesh(make_box({{0, 0, 0}, {1, 1, 1}}), Axis::kZ, {}).empty());
  EXPECT_TRUE(slice_mesh(make_box({{0, 0, 0}, {1, 1, 1}}), Axis::kZ, {std::nan("")})[0].empty());
}

}  // namespace
}  // namespace swarf
