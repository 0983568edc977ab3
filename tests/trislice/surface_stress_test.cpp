// Cases found by the surface stress set (bench/surface_stress.sh, issue #4): parts nobody
// tuned for, where the tri-slice scan left the exact drop-cutter or the truth.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "swarf/mesh/generate.h"
#include "swarf/trislice/envelope.h"
#include "swarf/trislice/surface_paths.h"

namespace swarf {
namespace {

Mesh plate_with_pin(double pin_x, double pin_y) {
  Mesh m = make_box({{0, 0, 0}, {20, 20, 2}});
  // A thin tall pin standing in the plate (the shells overlap; the slices unite them).
  const Mesh pin = make_cylinder({pin_x, pin_y, 1.0}, 0.1, 7.0, 16);
  const auto base = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.insert(m.vertices.end(), pin.vertices.begin(), pin.vertices.end());
  for (const auto& t : pin.triangles)
    m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  return m;
}

// The largest amount by which a line of `adaptive`, linearly interpolated, comes below the
// uniform line's CL points (the path would cut into what the uniform grid says is material).
double worst_gouge(const std::vector<std::vector<Vec3>>& uniform,
                   const std::vector<std::vector<Vec3>>& adaptive, Axis dir) {
  double worst = 0.0;
  const auto along = [dir](const Vec3& q) { return dir == Axis::kX ? q.x : q.y; };
  for (std::size_t i = 0; i < uniform.size(); ++i) {
    const std::vector<Vec3>&u = uniform[i], &a = adaptive[i];
    std::size_t k = 0;
    for (const Vec3& q : u) {
      while (k + 2 < a.size() && along(a[k + 1]) <= along(q))
        ++k;
      const double t = (along(q) - along(a[k])) / (along(a[k + 1]) - along(a[k]));
      worst = std::max(worst, q.z - (a[k].z + t * (a[k + 1].z - a[k].z)));
    }
  }
  return worst;
}

// A feature just inside the ball's reach from a scan line makes a bump in that line as narrow
// as one likes (a pin at lateral distance d from the line holds the ball up over a stretch
// 2 sqrt((r + pin radius)^2 - d^2) long) and as tall as the feature. The adaptive sampling
// along the line alone misses it between its samples, so its path cuts through the pin (the
// gear-and-text part of the stress set: 2.6 mm below the CL between two samples 0.4 mm
// apart). The neighbouring line nearer to the feature sees a wide bump and is refined there;
// the adaptive scan must then look at the same places in this line.
TEST(TriSliceStress, AdaptiveScanDoesNotMissANarrowBumpNearTheBallRim) {
  const double r = 1.5;
  for (Axis dir : {Axis::kX, Axis::kY}) {
    // Lines every 0.5 mm from 0; the line at 8.0 passes 1.595 mm from the pin's axis, so its
    // bump is ~0.25 mm long and lies between the first pass's samples (multiples of 0.4 mm).
    const Mesh part = dir == Axis::kX ? plate_with_pin(10.2, 9.595) : plate_with_pin(9.595, 10.2);
    auto model = build_trislice(part, 0.05);
    ASSERT_TRUE(model.ok());
    const TriSliceTop top = TriSliceTop::build(*model);
    ScanParams p;
    p.direction = dir;
    p.stepover_mm = 0.5;
    p.sampling_mm = 0.05;
    p.adaptive = false;
    auto uniform = scan_cl_lines(top, model->bounds, r, 0.0, p);
    p.adaptive = true;
    auto adaptive = scan_cl_lines(top, model->bounds, r, 0.0, p);
    ASSERT_TRUE(uniform.ok() && adaptive.ok());
    ASSERT_EQ(uniform->size(), adaptive->size());
    // The bump is there on the uniform grid: the pin's top holds the ball well above the plate.
    const std::vector<Vec3>& line = (*uniform)[16];
    ASSERT_NEAR(dir == Axis::kX ? line[0].y : line[0].x, 8.0, 1e-12);
    double top_z = 0.0;
    for (const Vec3& q : line)
      top_z = std::max(top_z, q.z);
    EXPECT_GT(top_z, 6.0);
    EXPECT_LE(worst_gouge(*uniform, *adaptive, dir), p.adaptive_tolerance_mm + 1e-9);
    std::size_t nu = 0, na = 0;
    for (std::size_t i = 0; i < uniform->size(); ++i) {
      nu += (*uniform)[i].size();
      na += (*adaptive)[i].size();
    }
    EXPECT_LT(na, nu / 3) << "the plate needs few points";
  }
}

}  // namespace
}  // namespace swarf
