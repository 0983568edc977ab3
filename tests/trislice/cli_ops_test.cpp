// The surface, dropcut and rest operations end to end through the swarf executable.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "cli/cli_test_util.h"
#include "swarf/mesh/generate.h"
#include "swarf/mesh/stl.h"

namespace swarf {
namespace {

using testing::run_swarf;
using testing::TempDir;

// CL points of a "line,x,y,z" CSV.
std::vector<Vec3> read_cl(const std::string& csv) {
  std::vector<Vec3> out;
  std::istringstream in(csv);
  std::string row;
  std::getline(in, row);
  while (std::getline(in, row)) {
    double l = 0, x = 0, y = 0, z = 0;
    if (std::sscanf(row.c_str(), "%lf,%lf,%lf,%lf", &l, &x, &y, &z) == 4) out.push_back({x, y, z});
  }
  return out;
}

// CL points of `swarf dropcut` (the exact reference) on the tests' grid: ø6 ball, lines 1 mm
// apart, points 0.25 mm apart.
std::vector<Vec3> dropcut_grid(const TempDir& dir, const std::string& stl) {
  const auto b =
      run_swarf("dropcut " + dir.file(stl) + " --tool ball:6 --stepover 1 --sampling 0.25 --csv " +
                dir.file("d.csv"));
  EXPECT_EQ(b.status, 0) << b.out;
  return read_cl(testing::read_file(dir.file("d.csv")));
}

// An open surface (a dome without its base, as a relief or a broken export comes) has no
// inside for the tri-slice model: scanning falls back to the exact drop-cutter (the same CL
// points as `swarf dropcut`, stock to leave as a larger ball), contour paths are refused.
TEST(TriSliceCli, OpenMeshScansWithTheExactDropCutterAndRefusesContours) {
  TempDir dir;
  const Mesh sphere = make_sphere({0, 0, 0}, 8.0, 64);
  Mesh dome;
  dome.vertices = sphere.vertices;
  for (const auto& t : sphere.triangles)
    if (sphere.vertices[t[0]].z >= -1e-9 && sphere.vertices[t[1]].z >= -1e-9 &&
        sphere.vertices[t[2]].z >= -1e-9)
      dome.triangles.push_back(t);
  ASSERT_FALSE(check_mesh(dome).closed());
  ASSERT_TRUE(write_stl(dir.file("dome.stl"), dome).ok());
  const std::string scan = "surface " + dir.file("dome.stl") +
                           " --tool ball:6 --pattern scan --stepover 1 --sampling 0.25 ";
  const auto a = run_swarf(scan + "--zigzag -o " + dir.file("s.nc") + " --csv " +
                           dir.file("s.csv") + " --report " + dir.file("rep"));
  ASSERT_EQ(a.status, 0) << a.out;
  const std::vector<Vec3> s = read_cl(testing::read_file(dir.file("s.csv")));
  const std::vector<Vec3> d = dropcut_grid(dir, "dome.stl");
  ASSERT_EQ(s.size(), d.size());
  ASSERT_GT(s.size(), 1000u);
  for (std::size_t k = 0; k < s.size(); ++k)
    ASSERT_NEAR(s[k].z, d[k].z, 1e-9) << "at " << s[k].x << ", " << s[k].y;
  EXPECT_NE(testing::read_file(dir.file("rep/summary.json")).find("open_mesh"), std::string::npos);
  // 0.5 mm to leave: over the apex the tip stands 0.5 mm above the dome.
  const auto c = run_swarf(scan + "--stock-to-leave 0.5 -o " + dir.file("t.nc") + " --csv " +
                           dir.file("t.csv"));
  ASSERT_EQ(c.status, 0) << c.out;
  bool apex = false;
  for (const Vec3& q : read_cl(testing::read_file(dir.file("t.csv"))))
    if (std::fabs(q.x) < 1e-9 && std::fabs(q.y) < 1e-9) {
      apex = true;
      EXPECT_NEAR(q.z, 8.5, 2e-3);  // the facets sit up to 1.0e-3 below the sphere
    }
  EXPECT_TRUE(apex);
  const auto w = run_swarf("surface " + dir.file("dome.stl") +
                           " --tool ball:6 --pattern contour -o " + dir.file("w.nc"));
  EXPECT_EQ(w.status, 2);
  EXPECT_NE(w.out.find("not a closed solid"), std::string::npos) << w.out;
  EXPECT_FALSE(std::ifstream(dir.file("w.nc")).good());
}

TEST(TriSliceCli, SurfaceScanMatchesDropcutOnTheSameGrid) {
  TempDir dir;
  ASSERT_TRUE(write_stl(dir.file("dome.stl"), make_sphere({0, 0, 0}, 8.0, 96)).ok());
  const auto a =
      run_swarf("surface " + dir.file("dome.stl") +
                " --tool ball:6 --pattern scan --uniform --stepover 1 --sampling 0.25 --pitch "
                "0.1 -o " +
                dir.file("s.nc") + " --csv " + dir.file("s.csv") + " --report " + dir.file("rep"));
  ASSERT_EQ(a.status, 0) << a.out;
  const std::vector<Vec3> s = read_cl(testing::read_file(dir.file("s.csv")));
  const std::vector<Vec3> d = dropcut_grid(dir, "dome.stl");
  ASSERT_EQ(s.size(), d.size());
  ASSERT_GT(s.size(), 1000u);
  std::size_t close = 0;
  for (std::size_t k = 0; k < s.size(); ++k) {
    ASSERT_NEAR(s[k].x, d[k].x, 1e-9);
    ASSERT_NEAR(s[k].y, d[k].y, 1e-9);
    close += std::fabs(s[k].z - d[k].z) <= 0.005;
  }
  // Steep rims aside (vertical deviations there measure the slope), the grids agree.
  EXPECT_GT(static_cast<double>(close) / static_cast<double>(s.size()), 0.97);
  EXPECT_NE(testing::read_file(dir.file("s.nc")).find("G1"), std::string::npos);
  EXPECT_NE(testing::read_file(dir.file("rep/summary.json")).find("cl_points"), std::string::npos);
  // Without --uniform the CL points are sampled adaptively: a subset of the uniform grid,
  // each one equal to the uniform point at its x, y, and far fewer on a block's flat top.
  ASSERT_TRUE(write_stl(dir.file("block.stl"), make_box({{0, 0, 0}, {20, 10, 5}})).ok());
  const std::string block =
      "surface " + dir.file("block.stl") +
      " --tool ball:6 --pattern scan --stepover 1 --sampling 0.1 --pitch 0.1 ";
  const auto u =
      run_swarf(block + "--uniform -o " + dir.file("u.nc") + " --csv " + dir.file("u.csv"));
  const auto c = run_swarf(block + "-o " + dir.file("a.nc") + " --csv " + dir.file("a.csv"));
  ASSERT_EQ(u.status, 0) << u.out;
  ASSERT_EQ(c.status, 0) << c.out;
  const std::vector<Vec3> un = read_cl(testing::read_file(dir.file("u.csv")));
  const std::vector<Vec3> ad = read_cl(testing::read_file(dir.file("a.csv")));
  ASSERT_GT(ad.size(), 100u);
  EXPECT_LT(ad.size(), un.size() / 2);
  std::size_t k = 0;
  for (const Vec3& q : ad) {
    while (k < un.size() && (std::fabs(un[k].x - q.x) > 1e-9 || std::fabs(un[k].y - q.y) > 1e-9))
      ++k;
    ASSERT_LT(k, un.size()) << q.x << " " << q.y;
    EXPECT_EQ(un[k].z, q.z);
  }
}

TEST(TriSliceCli, RestWritesMapAndPointsAndRejectsFlatTools) {
  TempDir dir;
  // Two boxes side by side with a 2 mm slot: a ø8 ball leaves the slot's material behind.
  Mesh m = make_box({{0, 0, 0}, {10, 10, 5}});
  append(m, make_box({{12, 0, 0}, {22, 10, 5}}));
  append(m, make_box({{0, 0, -3}, {22, 10, 0}}));
  ASSERT_TRUE(write_stl(dir.file("slot.stl"), m).ok());
  const auto r = run_swarf("rest " + dir.file("slot.stl") + " --tool ball:8 --pitch 0.5 --report " +
                           dir.file("rep") + " --csv " + dir.file("rest.csv"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(testing::read_file(dir.file("rep/rest_map.png")).substr(1, 3), "PNG");
  EXPECT_EQ(testing::read_file(dir.file("rep/rest_points.ply")).rfind("ply\n", 0), 0u);
  // Residue cells lie in the slot (10 < x < 12).
  const std::string csv = testing::read_file(dir.file("rest.csv"));
  std::istringstream in(csv);
  std::string row;
  std::getline(in, row);
  int cells = 0;
  while (std::getline(in, row)) {
    double x = 0, y = 0, t = 0;
    ASSERT_EQ(std::sscanf(row.c_str(), "%lf,%lf,%lf", &x, &y, &t), 3);
    EXPECT_GT(x, 9.5);
    EXPECT_LT(x, 12.5);
    ++cells;
  }
  EXPECT_GT(cells, 10);
  EXPECT_EQ(run_swarf("rest " + dir.file("slot.stl") + " --tool flat:8").status, 2);
}

}  // namespace
}  // namespace swarf
