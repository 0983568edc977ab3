// Ball-end paths from the tri-slice model against the exact drop-cutter and closed forms
// (seed 001 section 3.1 and Table 3), and unmachinable regions (section 3.2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "swarf/dropcut/dropcut.h"
#include "swarf/mesh/generate.h"
#include "swarf/trislice/envelope.h"
#include "swarf/trislice/rest.h"
#include "swarf/trislice/surface_paths.h"

namespace swarf {
namespace {

struct Stats {
  double max_um = 0.0;
  double within1 = 0.0;
  std::size_t n = 0;
};

// Deviation of tri-slice CL points from the exact drop-cutter on the same mesh, over the
// points where `use` holds.
template <class Use>
Stats compare(const Mesh& mesh, double pitch, double r, double step, Use use) {
  auto model = build_trislice(mesh, pitch);
  EXPECT_TRUE(model.ok());
  const TriSliceTop top = TriSliceTop::build(*model);
  auto dc = DropCutter::build(mesh, CutterShape{r, r});
  EXPECT_TRUE(dc.ok());
  const Box2 b = model->bounds.xy();
  Stats st;
  std::size_t ok1 = 0;
  for (double y = b.min.y; y <= b.max.y; y += step) {
    ScanHint hint;
    for (double x = b.min.x; x <= b.max.x; x += step) {
      const DropResult exact = dc->drop({x, y});
      if (!exact.hit() || !use(Vec2{x, y})) continue;
      const double tri = top.centre_height({x, y}, r, Axis::kY, &hint) - r;
      const double dev = std::fabs(exact.tip_z - tri) * 1e3;
      st.max_um = std::max(st.max_um, dev);
      ok1 += dev <= 1.0;
      ++st.n;
    }
  }
  st.within1 = st.n ? static_cast<double>(ok1) / static_cast<double>(st.n) : 0.0;
  return st;
}

TEST(TriSliceAccuracy, SphereAgainstDropCutterAndClosedForm) {
  const double Rs = 10.0, r = 4.0;
  const Mesh sphere = make_sphere({0, 0, 0}, Rs, 128);
  // Contacts up to 60 degrees from the top: beyond, a vertical deviation is a slope artefact.
  auto cap = [&](Vec2 p) { return norm(p) < (Rs + r) * std::sin(deg_to_rad(60.0)); };
  const Stats coarse = compare(sphere, 0.25, r, 0.37, cap);
  const Stats fine = compare(sphere, 0.05, r, 0.37, cap);
  EXPECT_GT(fine.n, 1000u);
  // Eq. (1) bound (offset.h): ds^2 / (8 r sin^2(theta) n_z) with theta >= 45 deg (two
  // families) and n_z >= 1/2: 4 ds^2 / (8 r) = 6 um at 0.25 mm, 0.25 um at 0.05 mm; the
  // vertices of the mesh add a little.
  EXPECT_LT(coarse.max_um, 10.0);
  EXPECT_LT(fine.max_um, 2.0);
  EXPECT_GT(fine.within1, 0.99);
  EXPECT_LT(fine.max_um, coarse.max_um);
  // The drop-cutter itself against the closed form z = sqrt((Rs + r)^2 - d^2) - r, within
  // the facets' sagitta.
  auto dc = DropCutter::build(sphere, CutterShape{r, r});
  const double sag = Rs * (1.0 - std::cos(kPi / 128 * std::sqrt(2.0)));
  for (double x = -11.0; x <= 11.0; x += 1.3) {
    const double d = std::fabs(x);
    const double closed = std::sqrt((Rs + r) * (Rs + r) - d * d) - r;
    const double got = dc->drop_z({x, 0.3});
    const double cl = std::sqrt((Rs + r) * (Rs + r) - d * d - 0.09) - r;
    EXPECT_LE(got, cl + 1e-9);
    EXPECT_GE(got, closed - 2.0 * sag - 0.01);
  }
}

TEST(TriSliceAccuracy, TorusAgainstDropCutter) {
  const double R = 15.0, rt = 5.0, r = 4.0;
  const Mesh torus = make_torus({0, 0, 0}, R, rt, 128, 64);
  // Top of the tube within 60 degrees of vertical.
  auto cap = [&](Vec2 p) { return std::fabs(norm(p) - R) < (rt + r) * std::sin(deg_to_rad(60.0)); };
  const Stats st = compare(torus, 0.05, r, 0.53, cap);
  EXPECT_GT(st.n, 1000u);
  EXPECT_LT(st.max_um, 2.0);
  EXPECT_GT(st.within1, 0.99);
}

Tool ball8() {
  Tool t = ball_mill(8.0);
  return t;
}

TEST(TriSlicePaths, ScanNeverCutsIntoTheOffsetAndZigzagLinksStayOnTheSurface) {
  const Mesh torus = make_torus({0, 0, 5}, 12, 5, 64, 32);
  auto model = build_trislice(torus, 0.2);
  ASSERT_TRUE(model.ok());
  const TriSliceTop top = TriSliceTop::build(*model);
  const Tool tool = ball8();
  ScanParams p;
  p.stepover_mm = 1.5;
  p.sampling_mm = 0.2;
  p.zigzag = true;
  p.stock_to_leave_mm = 0.3;
  auto fin = scan_finishing(*model, top, tool, p);
  ASSERT_TRUE(fin.ok()) << fin.status().to_string();
  // The ball centre (tip + r) must stay r + stock from the part, up to the sampling error
  // measured along the normal (offset.h: ds^2 / (8 r sin^2 theta) ~ 2.5 um here, plus up to
  // phi * ds / 2 at the mesh's creases of dihedral angle phi ~ 5.6 deg: ~10 um): it clears a
  // ball of radius R - eps dropped exactly. A vertical check would fail where the ball grazes
  // a wall: there the height changes by millimetres over micrometres of x.
  const double R = 4.0 + 0.3, eps = 0.012;
  auto dc_in = DropCutter::build(torus, CutterShape{R - eps, R - eps});
  // Upper check: a ball grown by the 1e-5 mm grid of the polygons (3e-5 in 3D), since where
  // the ball grazes a ring the rounding is amplified by R / sqrt(R^2 - d^2).
  const double grid = 3e-5;
  auto dc = DropCutter::build(torus, CutterShape{R + grid, R + grid});
  ASSERT_TRUE(dc.ok() && dc_in.ok());
  std::size_t feeds = 0;
  for (const Move& m : fin->moves) {
    if (m.kind != MoveKind::kFeed) continue;
    ++feeds;
    const DropResult in = dc_in->drop(m.end.xy());
    if (in.hit()) {
      EXPECT_GE(m.end.z + 4.0, in.tip_z + R - eps - 1e-9) << m.end.x << " " << m.end.y;
    }
    // Never above the exact CL (the slices are part of the solid) but for the 1e-5 mm grid.
    const DropResult d = dc->drop(m.end.xy());
    if (d.hit()) {
      EXPECT_LE(m.end.z + 4.0, d.tip_z + R + grid + 1e-9) << m.end.x << " " << m.end.y;
    }
  }
  EXPECT_GT(feeds, 100u);
  // Zig-zag: one retract at the end only (links stay down).
  std::size_t rapids_up = 0;
  for (const Move& m : fin->moves)
    rapids_up += m.kind == MoveKind::kRapid && m.end.z == fin->clearance_z_mm;
  EXPECT_LE(rapids_up, 3u);
}

TEST(TriSlicePaths, RoughingLayersFollowTable1) {
  const Mesh torus = make_torus({0, 0, 5}, 12, 5, 64, 32);
  auto model = build_trislice(torus, 0.25);
  ASSERT_TRUE(model.ok());
  const TriSliceTop top = TriSliceTop::build(*model);
  ScanParams p;
  p.sampling_mm = 0.25;
  RoughingParams rough;  // Table 1: 5 layers, 2 mm deep, 2 mm apart, 0.1 mm margin
  rough.stock_top_mm = 14.0;
  auto tp = scan_roughing(*model, top, ball8(), p, rough);
  ASSERT_TRUE(tp.ok()) << tp.status().to_string();
  const double eps = 0.012, R = 4.1;  // margin 0.1 kept up to the sampling error (see above)
  auto dc = DropCutter::build(torus, CutterShape{R - eps, R - eps});
  double lowest = 1e9;
  for (const Move& m : tp->moves) {
    if (m.kind != MoveKind::kFeed) continue;
    EXPECT_LE(m.end.z, 14.0 + 1e-9);  // never above the stock top while cutting
    const DropResult d = dc->drop(m.end.xy());
    if (d.hit()) {
      EXPECT_GE(m.end.z + 4.0, d.tip_z + R - eps - 1e-9);  // keeps the margin
    }
    lowest = std::min(lowest, m.end.z);
  }
  EXPECT_LE(lowest, 1e-9);  // the last layer reaches the floor beside the torus
  ScanParams bad = p;
  bad.stepover_mm = -1;
  EXPECT_FALSE(scan_finishing(*model, top, ball8(), bad).ok());
  EXPECT_FALSE(scan_finishing(*model, top, flat_mill(8), p).ok());
}

// On a fine model roughing reads every 5th slice (min_pitch 0.25 mm): the margin is kept
// against the exact drop-cutter up to that pitch's error (28 um at the worst crease of this
// part for r = 4, offset.h), and the path is that of a model sliced at 0.25 mm.
TEST(TriSlicePaths, RoughingOnAFineModelReadsACoarserOneAndKeepsTheMargin) {
  const Mesh part = make_filleted_torus_part();
  auto fine = build_trislice(part, 0.05);
  auto coarse = build_trislice(part, 0.25);
  ASSERT_TRUE(fine.ok() && coarse.ok());
  ScanParams p;
  RoughingParams rough;  // Table 1
  rough.stock_top_mm = 20.0;
  auto tp = scan_roughing(*fine, TriSliceTop::build(*fine), ball8(), p, rough);
  auto tc = scan_roughing(*coarse, TriSliceTop::build(*coarse), ball8(), p, rough);
  ASSERT_TRUE(tp.ok() && tc.ok());
  ASSERT_EQ(tp->moves.size(), tc->moves.size());
  for (std::size_t i = 0; i < tp->moves.size(); ++i)
    EXPECT_NEAR(tp->moves[i].end.z, tc->moves[i].end.z, 1e-9);
  const double eps = 0.03, R = 4.1;
  auto dc = DropCutter::build(part, CutterShape{R - eps, R - eps});
  ASSERT_TRUE(dc.ok());
  std::size_t n = 0;
  for (const Move& m : tp->moves) {
    if (m.kind != MoveKind::kFeed) continue;
    const DropResult d = dc->drop(m.end.xy());
    if (d.hit() && m.end.z < 20.0 - 1e-9) {  // at the stock top it cuts nothing
      EXPECT_GE(m.end.z + 4.0, d.tip_z + R - eps - 1e-9) << m.end.x << " " << m.end.y;
    }
    ++n;
  }
  EXPECT_GT(n, 1000u);
}

TEST(TriSlicePaths, ContourRingsTouchButDoNotCutThePart) {
  const Mesh sphere = make_sphere({0, 0, 0}, 10, 128);
  auto model = build_trislice(sphere, 0.2);
  ASSERT_TRUE(model.ok());
  ContourParams cp;
  cp.stepdown_mm = 2.5;
  // Levels from the top down to the equator's tip height; below it the ring is the shank
  // tangent to the equator, where a drop from above is ill-conditioned (tested apart).
  cp.bottom_z_mm = -4.0;
  auto tp = contour_paths(*model, ball8(), cp);
  ASSERT_TRUE(tp.ok()) << tp.status().to_string();
  auto dc = DropCutter::build(sphere, CutterShape{4.0, 4.0});
  std::size_t n = 0;
  double closest = 1e9;
  for (const Move& m : tp->moves) {
    if (m.kind != MoveKind::kFeed) continue;
    const DropResult d = dc->drop(m.end.xy());
    ASSERT_TRUE(d.hit());
    // The tool may stand there (the drop is not above it, up to the sampling error: see the
    // scan test: creases of 2.8 deg add up to 5 um here) and it touches somewhere.
    EXPECT_LE(d.tip_z, m.end.z + 0.012) << m.end.x << " " << m.end.y << " " << m.end.z;
    closest = std::min(closest, m.end.z - d.tip_z);
    ++n;
  }
  EXPECT_GT(n, 100u);
  EXPECT_LT(closest, 0.005);
  // Below the equator (an undercut for a 3-axis tool) the ring is the shank around the
  // widest section: radius 10 + 4, never inside it.
  cp.top_z_mm = -6.0;
  cp.bottom_z_mm = -6.0;
  auto low = contour_paths(*model, ball8(), cp);
  ASSERT_TRUE(low.ok());
  for (const Move& m : low->moves)
    if (m.kind == MoveKind::kFeed) {
      EXPECT_GE(norm(m.end.xy()), 14.0 - 0.002);
    }
}

TEST(TriSliceRest, InnerFilletShowsAndOuterDoesNot) {
  // seed 001 Fig. 11/12: a ø8 ball fits the 4 mm outer fillet but not the 3 mm inner one.
  auto model = build_trislice(make_filleted_torus_part(), 0.25);
  ASSERT_TRUE(model.ok());
  RestOptions o;
  o.tool_radius_mm = 4.0;
  o.families = {false, true, false};
  o.region = Box3{{-50, -0.3, -50}, {50, 0.3, 50}};  // the slices through the axis
  auto rest = unmachinable_regions(*model, o);
  ASSERT_TRUE(rest.ok()) << rest.status().to_string();
  const ThicknessMap map = thickness_map(*rest, 0.25);
  auto band_max = [&](double lo, double hi) {
    double m = 0.0;
    for (double x = lo; x <= hi; x += 0.05)
      m = std::max({m, map.at({x, 0.01}), map.at({-x, 0.01})});
    return m;
  };
  // Inner fillet: touches the plate at radius 25 - 2 sqrt(30) = 14.05.
  EXPECT_GT(band_max(13.0, 17.0), 0.2);
  // Outer fillet (touches the plate at 25 + 2 sqrt(40) = 37.6) and the rest of the plate.
  EXPECT_LT(band_max(30.0, 40.0), 0.02);
  EXPECT_LT(band_max(0.0, 11.0), 1e-9);
  // The picture and the points come out.
  const Image img = thickness_image(map, o.min_thickness_mm);
  EXPECT_EQ(img.width, map.nx);
  const std::string ply = residue_points_ply(*rest, 0.1);
  EXPECT_EQ(ply.rfind("ply\n", 0), 0u);
  EXPECT_NE(ply.find("element vertex "), std::string::npos);
}

// A torus R 12 / r 5 sliced at 0.25 mm, as the scan-line tests read it.
struct SmallTorus {
  TriSliceModel model;
  TriSliceTop top;
};
SmallTorus small_torus() {
  const Mesh torus = make_torus({0, 0, 5}, 12, 5, 48, 24);
  auto model = build_trislice(torus, 0.25);
  EXPECT_TRUE(model.ok()) << model.status().to_string();
  SmallTorus t{model.value(), {}};
  t.top = TriSliceTop::build(t.model);
  return t;
}

TEST(TriSlicePaths, ScanLinesIndependentOfThreadCount) {
  const SmallTorus torus = small_torus();
  const TriSliceTop& top = torus.top;
  const Box3& bounds = torus.model.bounds;
  ScanParams p;
  p.stepover_mm = 0.7;
  p.sampling_mm = 0.3;
  Context one, many;
  one.threads = 1;
  many.threads = 3;
  auto a = scan_cl_lines(top, bounds, 4.0, 0.0, p, one);
  auto b = scan_cl_lines(top, bounds, 4.0, 0.0, p, many);
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(*a, *b);
}

// Adaptive sampling along the scan lines against the uniform grid on the Table 2 part: the
// adaptive path, linearly interpolated, is neither below a uniform CL point by more than the
// tolerance (a gouge) nor above it (material left), from fewer queries (one per kept point;
// the ring's curved flanks need the 0.1 mm spacing for 1 um, the plate does not).
// The adaptive lines, linearly interpolated, against every point of the uniform grid on the
// same model: how far below and above it they come, and how many queries they took.
// With `exact` (the drop-cutter on the same grid, in the same order) also how far each path
// comes below and above the exact CL.
struct AdaptiveVsUniform {
  double below = 0.0, above = 0.0;
  std::size_t na = 0, nu = 0;
  double uniform_below_exact = 0.0, uniform_above_exact = 0.0;
  double adaptive_below_exact = 0.0, adaptive_above_exact = 0.0;
};
AdaptiveVsUniform adaptive_vs_uniform(const TriSliceTop& top, const Box3& bounds, ScanParams p,
                                      const std::vector<Vec3>* exact = nullptr) {
  AdaptiveVsUniform r;
  p.stepover_mm = 0.5;
  p.sampling_mm = 0.1;
  p.adaptive = false;
  auto uniform = scan_cl_lines(top, bounds, 4.0, 0.0, p);
  p.adaptive = true;
  auto adaptive = scan_cl_lines(top, bounds, 4.0, 0.0, p);
  EXPECT_TRUE(uniform.ok() && adaptive.ok());
  if (!uniform.ok() || !adaptive.ok()) return r;
  EXPECT_EQ(uniform->size(), adaptive->size());
  for (std::size_t i = 0; i < uniform->size() && i < adaptive->size(); ++i) {
    const std::vector<Vec3>& u = (*uniform)[i];
    const std::vector<Vec3>& a = (*adaptive)[i];
    EXPECT_GE(a.size(), 2u);
    if (a.size() < 2) continue;
    r.nu += u.size();
    r.na += a.size();
    EXPECT_EQ(a.front(), u.front());
    EXPECT_EQ(a.back(), u.back());
    std::size_t k = 0;
    for (std::size_t j = 0; j < u.size(); ++j) {
      const Vec3& q = u[j];
      while (k + 2 < a.size() && a[k + 1].x <= q.x)
        ++k;
      const double t = (q.x - a[k].x) / (a[k + 1].x - a[k].x);
      EXPECT_GE(t, -1e-9);
      EXPECT_LE(t, 1.0 + 1e-9);
      const double z = a[k].z + t * (a[k + 1].z - a[k].z);
      r.below = std::max(r.below, q.z - z);
      r.above = std::max(r.above, z - q.z);
      if (exact != nullptr) {
        const Vec3& e = (*exact)[i * u.size() + j];
        EXPECT_NEAR(e.x, q.x, 1e-9);
        EXPECT_NEAR(e.y, q.y, 1e-9);
        r.uniform_below_exact = std::max(r.uniform_below_exact, e.z - q.z);
        r.uniform_above_exact = std::max(r.uniform_above_exact, q.z - e.z);
        r.adaptive_below_exact = std::max(r.adaptive_below_exact, e.z - z);
        r.adaptive_above_exact = std::max(r.adaptive_above_exact, z - e.z);
      }
    }
  }
  return r;
}

TEST(TriSlicePaths, AdaptiveScanStaysWithinToleranceOfTheUniformGrid) {
  auto model = build_trislice(make_filleted_torus_part(), 0.125);
  ASSERT_TRUE(model.ok());
  const TriSliceTop top = TriSliceTop::build(*model);
  ScanParams p;
  p.adaptive_model_fraction = 0.0;  // the 1 um as given (the model's bound here is 1.27 um)
  p.refine_steep = false;           // the lattice walk alone (its steep stretches: below)
  const AdaptiveVsUniform r = adaptive_vs_uniform(top, model->bounds, p);
  EXPECT_LE(r.below, p.adaptive_tolerance_mm + 1e-9);
  EXPECT_LE(r.above, p.adaptive_tolerance_mm + 1e-9);
  EXPECT_LT(static_cast<double>(r.na), 0.8 * static_cast<double>(r.nu)) << r.na << " of " << r.nu;
  std::printf("adaptive: %zu of %zu queries, at most %.2f um below, %.2f um above\n", r.na, r.nu,
              r.below * 1e3, r.above * 1e3);
}

// At a coarse pitch the default tolerance follows the model's own error bound (offset.h at
// theta = 54.7 deg): 3 sqrt(3) ds^2 / (16 R) = 5.07 um at ds = 0.25 mm, R = 4 mm. Against the
// exact drop-cutter on the 0.1 mm grid the path then loses nothing that matters: it comes no
// further below the exact CL than the uniform grid of the same model does (the model's error,
// 28 um at a crease here), and no more than the tolerance above it. It keeps within the
// tolerance below the uniform grid (gouge side); above it (material left), the facet ridges
// of a 0.25 mm model can add a little more (measured 5.8 um), never above the exact CL by more
// than the tolerance.
TEST(TriSlicePaths, AdaptiveToleranceFollowsTheModelBoundAtCoarsePitch) {
  EXPECT_NEAR(trislice_height_error_bound_mm(0.25, 4.0),
              0.25 * 0.25 / (8.0 * 4.0 * (2.0 / 3.0) / std::sqrt(3.0)), 1e-15);
  ScanParams p;
  EXPECT_DOUBLE_EQ(effective_adaptive_tolerance_mm(p, 0.05, 4.0), 0.001);  // 0.2 um < 1 um
  const double tol = effective_adaptive_tolerance_mm(p, 0.25, 4.0);
  EXPECT_NEAR(tol, 0.005074, 1e-6);
  const Mesh part = make_filleted_torus_part();
  auto model = build_trislice(part, 0.25);
  ASSERT_TRUE(model.ok());
  const TriSliceTop top = TriSliceTop::build(*model);
  EXPECT_DOUBLE_EQ(top.pitch_mm(), 0.25);
  auto dc = DropCutter::build(part, CutterShape{4.0, 4.0});
  ASSERT_TRUE(dc.ok());
  auto exact = drop_grid(*dc, ClGrid{bounds(part).xy(), Axis::kX, 0.5, 0.1}, bounds(part).min.z);
  ASSERT_TRUE(exact.ok());
  const AdaptiveVsUniform r = adaptive_vs_uniform(top, model->bounds, p, &*exact);
  EXPECT_LE(r.below, tol + 1e-9);
  EXPECT_LE(r.adaptive_below_exact, r.uniform_below_exact + 1e-9);
  EXPECT_LE(r.adaptive_above_exact, tol + 1e-9);
  EXPECT_GT(r.uniform_below_exact, 0.01);  // the model's own error dwarfs the tolerance
  p.adaptive_model_fraction = 0.0;
  const AdaptiveVsUniform fine = adaptive_vs_uniform(top, model->bounds, p);
  EXPECT_LT(static_cast<double>(r.na), 0.95 * static_cast<double>(fine.na))
      << r.na << " vs " << fine.na;
  std::printf(
      "model-bound tolerance %.2f um: %zu (1 um: %zu) of %zu queries; against the uniform "
      "grid %.2f um below, %.2f um above; against the exact CL %.2f um below (uniform "
      "%.2f), %.2f um above (uniform %.2f)\n",
      tol * 1e3, r.na, fine.na, r.nu, r.below * 1e3, r.above * 1e3, r.adaptive_below_exact * 1e3,
      r.uniform_below_exact * 1e3, r.adaptive_above_exact * 1e3, r.uniform_above_exact * 1e3);
}

// Adaptive lines of any length (the last stretch of a line is not a power of two): strictly
// increasing along the line, both ends kept, every point equal to the uniform grid's there.
TEST(TriSlicePaths, AdaptiveLinesAreSubsetsOfTheUniformGridForAnyLength) {
  const SmallTorus torus = small_torus();
  const TriSliceTop& top = torus.top;
  const Box3& bounds = torus.model.bounds;
  for (double sampling : {0.1, 0.13, 0.3, 0.7})
    for (double width : {20.0, 20.3, 21.1}) {
      ScanParams p;
      p.refine_steep = false;  // lattice points only (MovesAcrossAWallDoNotCutIntoIt: below it)
      p.stepover_mm = 3.0;
      p.sampling_mm = sampling;
      p.region = Box2{{-10.0, -10.0}, {-10.0 + width, 10.0}};
      p.adaptive = false;
      auto u = scan_cl_lines(top, bounds, 4.0, 0.0, p);
      p.adaptive = true;
      auto a = scan_cl_lines(top, bounds, 4.0, 0.0, p);
      ASSERT_TRUE(u.ok() && a.ok());
      ASSERT_EQ(u->size(), a->size());
      for (std::size_t i = 0; i < u->size(); ++i) {
        const std::vector<Vec3>&ul = (*u)[i], &al = (*a)[i];
        ASSERT_FALSE(al.empty());
        EXPECT_EQ(al.front(), ul.front());
        EXPECT_EQ(al.back(), ul.back());
        std::size_t k = 0;
        for (std::size_t j = 0; j < al.size(); ++j) {
          if (j > 0) {
            EXPECT_GT(al[j].x, al[j - 1].x) << sampling << " " << width;
          }
          while (k < ul.size() && ul[k].x != al[j].x)
            ++k;
          ASSERT_LT(k, ul.size());
          EXPECT_EQ(ul[k], al[j]);
        }
      }
    }
}

}  // namespace
}  // namespace swarf
