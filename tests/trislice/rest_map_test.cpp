// The top-view thickness map of the unmachinable regions (swarf/trislice/rest.h), on residues
// built by hand so that the answer is known exactly.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>

#include "swarf/mesh/generate.h"
#include "swarf/trislice/model.h"
#include "swarf/trislice/rest.h"

namespace swarf {
namespace {

Ring rect(double u0, double v0, double u1, double v1) {
  return {{u0, v0}, {u1, v0}, {u1, v1}, {u0, v1}};
}

// A part 8 x 8 mm from (-4, -4), pitch 0.1 mm: the vertical families' levels fall on the
// map's cell edges (up to rounding), as they do for any part whose bounds sit on the lattice.
RestRegions empty_rest() {
  RestRegions r;
  r.pitch_mm = 0.1;
  r.bounds = Box3{{-4, -4, 0}, {4, 4, 4}};
  for (Axis a : {Axis::kX, Axis::kY, Axis::kZ}) {
    SliceFamily& f = r.families[static_cast<std::size_t>(a)];
    f.axis = a;
    f.pitch_mm = 0.1;
    f.first_level = a == Axis::kZ ? 0.05 : -4.0;
    f.slices.resize(a == Axis::kZ ? 40 : 81);
  }
  return r;
}

// The xy family has residue in the slab 0 < z < 1 over the middle 6 x 6 mm.
void add_xy_slab(RestRegions& r) {
  SliceFamily& fz = r.families[static_cast<std::size_t>(Axis::kZ)];
  for (std::size_t l = 0; l < 10; ++l)
    fz.slices[l].rings = {rect(-3, -3, 3, 3)};
}

// Every cell is read by every vertical family: where they hold no residue the map is empty,
// whatever the xy family says. Cells that no slice of a family was assigned to (levels
// floored onto cells) showed the xy family's residue there, as stripes.
TEST(TriSliceRestMap, EveryCellIsReadByEachVerticalFamily) {
  RestRegions r = empty_rest();
  add_xy_slab(r);
  const ThicknessMap map = thickness_map(r, 0.1);
  EXPECT_EQ(map.nx, 80);
  EXPECT_EQ(map.ny, 80);
  EXPECT_EQ(map.max(), 0.0);
}

// Residue counts where the families agree on the same heights (superposition, seed 001
// section 2.1), not where each has some residue at heights of its own.
TEST(TriSliceRestMap, FamiliesMustAgreeOnTheHeights) {
  RestRegions r = empty_rest();
  add_xy_slab(r);
  // Vertical families: residue 2 < z < 3 only, in (u, v) = (y, z) and (z, x) planes.
  for (std::size_t j = 0; j < 81; ++j) {
    r.families[0].slices[j].rings = {rect(-3, 2, 3, 3)};
    r.families[1].slices[j].rings = {rect(2, -3, 3, 3)};
  }
  EXPECT_EQ(thickness_map(r, 0.1).max(), 0.0);
  EXPECT_NE(residue_points_ply(r, 0.1).find("element vertex 0\n"), std::string::npos);
  // Now they agree with the xy slab on 0.5 < z < 1: that much is left, and only over the
  // square all three see.
  for (std::size_t j = 0; j < 81; ++j) {
    r.families[0].slices[j].rings = {rect(-2, 0.5, 2, 3)};
    r.families[1].slices[j].rings = {rect(0.5, -2, 3, 2)};
  }
  const ThicknessMap map = thickness_map(r, 0.1);
  EXPECT_NEAR(map.at({0.0, 0.0}), 0.5, 1e-9);
  EXPECT_NEAR(map.at({1.95, -1.95}), 0.5, 1e-9);
  EXPECT_EQ(map.at({2.5, 0.0}), 0.0);
  EXPECT_EQ(map.at({0.0, -2.5}), 0.0);
  // The points a viewer shows are the same residue: 40 x 40 columns, z = 0.5 .. 1.0.
  const std::string ply = residue_points_ply(r, 0.1);
  std::istringstream in(ply.substr(ply.find("end_header\n") + 11));
  double x = 0, y = 0, z = 0;
  int n = 0;
  while (in >> x >> y >> z) {
    ++n;
    EXPECT_LE(std::abs(x), 2.0);
    EXPECT_LE(std::abs(y), 2.0);
    EXPECT_GE(z, 0.5 - 1e-9);
    EXPECT_LE(z, 1.0 + 1e-9);
  }
  EXPECT_EQ(n, 40 * 40 * 6);
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// A block on a plate: residue only along the block's foot (a ø4 ball cannot reach into the
// concave right angle there). The families analysed with and without pruning, for the checks
// that they give the same map and points.
struct PrunedAndFull {
  RestRegions pruned, full;
};
PrunedAndFull block_on_plate_rest(std::array<bool, 3> families) {
  Mesh part = make_box(Box3{{0, 0, 0}, {40, 40, 3}});
  append(part, make_box(Box3{{15.2, 16.1, 0}, {24.9, 23.7, 8}}));
  auto model = build_trislice(part, 0.25);
  EXPECT_TRUE(model.ok()) << model.status().to_string();
  if (!model.ok()) return {};
  RestOptions o;
  o.tool_radius_mm = 2.0;
  o.families = families;
  auto pruned = unmachinable_regions(*model, o);
  o.prune_by_xy_residue = false;
  auto full = unmachinable_regions(*model, o);
  EXPECT_TRUE(pruned.ok() && full.ok());
  if (!pruned.ok() || !full.ok()) return {};
  return {std::move(pruned).value(), std::move(full).value()};
}

// The x and y families analysed only over the xy family's residue give the same map and
// points as the full analysis.
TEST(TriSliceRestMap, PruningByTheXyResidueChangesNothing) {
  const auto [pruned, full] = block_on_plate_rest({true, true, true});
  EXPECT_LT(pruned.families[0].size(), full.families[0].size() / 2);
  const ThicknessMap a = thickness_map(pruned, 0.25), c = thickness_map(full, 0.25);
  EXPECT_GT(a.max(), 0.5);  // the foot of the block: about r (sqrt 2 - 1) across the corner
  EXPECT_EQ(a.mm, c.mm);
  EXPECT_EQ(residue_points_ply(pruned, 0.25), residue_points_ply(full, 0.25));
  // Nothing away from the block.
  EXPECT_EQ(a.at({5.0, 5.0}), 0.0);
  EXPECT_EQ(a.at({35.0, 20.0}), 0.0);
}

// The y family is analysed only where the x family (and the xy family, when analysed) hold
// residue. With the xy family off, the x family is analysed whole and its residue, at the
// foot of the block, limits the y family to the block's surroundings: same map and points.
TEST(TriSliceRestMap, PruningTheYFamilyByTheXResidueChangesNothing) {
  const auto [pruned, full] = block_on_plate_rest({true, true, false});
  EXPECT_EQ(pruned.families[0].size(), full.families[0].size());
  EXPECT_LT(pruned.families[1].size(), full.families[1].size() / 2);
  const ThicknessMap a = thickness_map(pruned, 0.25), c = thickness_map(full, 0.25);
  EXPECT_GT(a.max(), 0.5);
  EXPECT_EQ(a.mm, c.mm);
  EXPECT_EQ(residue_points_ply(pruned, 0.25), residue_points_ply(full, 0.25));
}

}  // namespace
}  // namespace swarf
