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
  const Mesh b = make_box(block);
  const auto base = static_cast<std::uint32_t>(part.vertices.size());
  part.vertices.insert(part.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) {
    for (auto& v : t)
      v += base;
    part.triangles.push_back(t);
  }
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
