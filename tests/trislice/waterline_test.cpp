// Waterlines (contour_paths) against a part whose distance field is known exactly: two
// axis-aligned boxes, one's top between two slice levels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "swarf/mesh/generate.h"
#include "swarf/trislice/model.h"
#include "swarf/trislice/surface_paths.h"

namespace swarf {
namespace {

double box_distance(const Box3& b, Vec3 p) {
  const double dx = std::max({b.min.x - p.x, 0.0, p.x - b.max.x});
  const double dy = std::max({b.min.y - p.y, 0.0, p.y - b.max.y});
  const double dz = std::max({b.min.z - p.z, 0.0, p.z - b.max.z});
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// A plate and a block on it whose top (z = 9.13) lies between the 0.25 mm slice levels. A
// waterline whose ball centre is above that top touches the block's top edges; the slice
// below them is up to a pitch lower, which let the ball 0.02 to 0.04 mm into the block. With
// the mesh's critical heights (horizontal edges, peaks) sliced too, every point of every
// ring keeps the ball radius from the part, to the arc tolerance.
TEST(TriSliceWaterline, StepTopBetweenTwoSliceLevelsIsExact) {
  const Box3 plate{{0, 0, 0}, {30, 30, 3}}, block{{7.33, 8.21, 0}, {17.77, 19.69, 9.13}};
  Mesh part = make_box(plate);
  append(part, make_box(block));
  auto model = build_trislice(part, 0.25);
  ASSERT_TRUE(model.ok()) << model.status().to_string();
  const Tool ball = parse_tool_spec("ball:3").value();
  const double r = 1.5;
  ContourParams cp;
  cp.top_z_mm = 8.4;  // centres at 9.9, 9.4 and 8.9: above the top, and beside the block
  cp.bottom_z_mm = 7.4;
  cp.stepdown_mm = 0.5;
  auto worst = [&](const ContourParams& params, double& lo, double& hi) {
    auto tp = contour_paths(*model, ball, params);
    ASSERT_TRUE(tp.ok()) << tp.status().to_string();
    lo = 1e9;
    hi = -1e9;
    for (const Move& m : tp->moves) {
      if (m.kind != MoveKind::kFeed) continue;
      const Vec3 c = m.end + Vec3{0, 0, r};
      const double d = std::min(box_distance(plate, c), box_distance(block, c));
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
  };
  double lo = 0, hi = 0;
  worst(cp, lo, hi);
  EXPECT_LT(lo, r - 0.01);  // the fault: the ball inside the block
  cp.critical_mesh = &part;
  worst(cp, lo, hi);
  EXPECT_GE(lo, r - 0.0015);
  EXPECT_LE(hi, r + 0.0015);  // and it touches all round
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// Closest point of triangle abc to p (Voronoi regions of the vertices, edges and face).
Vec3 closest_on_triangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + ab * (d1 / (d1 - d3));
  const Vec3 cp = p - c;
  const double d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0)
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  const double den = 1.0 / (va + vb + vc);
  return a + ab * (vb * den) + ac * (vc * den);
}

// A roof whose sharp ridge rises 0.5 mm over 20 mm: 0.25 mm slices cross it 10 mm apart, so
// between them the slices alone let the ball sink into the ridge. Points along slowly rising
// sharp edges keep it out, to about a micrometre.
TEST(TriSliceWaterline, SlowlyRisingSharpRidgeKeepsTheBallOut) {
  Mesh roof;
  // A triangular prism (base 10, height 5) pushed up 0.5 mm along its 20 mm: planar faces.
  roof.vertices = {{0, -5, 0}, {0, 5, 0}, {0, 0, 5}, {20, -5, 0.5}, {20, 5, 0.5}, {20, 0, 5.5}};
  roof.triangles = {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3},
                    {0, 3, 5}, {0, 5, 2}, {1, 2, 5}, {1, 5, 4}};
  auto model = build_trislice(roof, 0.25);
  ASSERT_TRUE(model.ok()) << model.status().to_string();
  const Tool ball = parse_tool_spec("ball:3").value();
  const double r = 1.5;
  ContourParams cp;
  cp.top_z_mm = 4.6;
  cp.bottom_z_mm = 3.6;
  cp.stepdown_mm = 0.25;
  auto nearest = [&](const ContourParams& params) {
    auto tp = contour_paths(*model, ball, params);
    EXPECT_TRUE(tp.ok()) << tp.status().to_string();
    double lo = 1e9;
    for (const Move& m : tp->moves) {
      if (m.kind != MoveKind::kFeed) continue;
      const Vec3 c = m.end + Vec3{0, 0, r};
      for (std::size_t t = 0; t < roof.triangles.size(); ++t) {
        lo = std::min(lo, norm(c - closest_on_triangle(c, roof.corner(t, 0), roof.corner(t, 1),
                                                       roof.corner(t, 2))));
      }
    }
    return lo;
  };
  EXPECT_LT(nearest(cp), r - 0.005);  // the fault: into the ridge between the slices
  cp.critical_mesh = &roof;
  EXPECT_GE(nearest(cp), r - 0.0015);
}

}  // namespace
}  // namespace swarf
