// Tri-slice model, Eq. (1) offsets and the point-wise top envelope (seed 001 section 2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "swarf/mesh/generate.h"
#include "swarf/mesh/mesh.h"
#include "swarf/trislice/envelope.h"
#include "swarf/trislice/model.h"
#include "swarf/trislice/offset.h"

namespace swarf {
namespace {

// Highest z of a polygon set in a y-family slice ((u, v) = (z, x)) over the vertical line x.
double top_at(const PolygonSet& set, double x) {
  double best = -std::numeric_limits<double>::infinity();
  for (const Ring& ring : set.rings)
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
      if ((a.y <= x) == (b.y <= x)) continue;
      best = std::max(best, a.x + (x - a.y) / (b.y - a.y) * (b.x - a.x));
    }
  return best;
}

TEST(TriSliceModel, BoxSlicesHaveTheBoxCrossSections) {
  const Box3 box{{-5, -4, -3}, {5, 4, 3}};
  auto model = build_trislice(make_box(box), 0.5);
  ASSERT_TRUE(model.ok()) << model.status().to_string();
  const double expect[3] = {8.0 * 6.0, 6.0 * 10.0, 10.0 * 8.0};
  for (int a = 0; a < 3; ++a) {
    const SliceFamily& f = model->families[static_cast<std::size_t>(a)];
    EXPECT_NEAR(std::fmod(f.first_level / 0.5, 1.0), 0.0, 1e-9);  // on the lattice k * pitch
    int full = 0;
    for (std::size_t j = 0; j < f.size(); ++j) {
      const double lv = f.level(j);
      if (lv > box.min[a] + 1e-9 && lv < box.max[a] - 1e-9) {
        EXPECT_NEAR(area(f.slices[j]), expect[a], 1e-6) << a << " " << lv;
        ++full;
      }
    }
    EXPECT_GT(full, 10);
  }
  // The stock block is exact and on the same lattice.
  const TriSliceModel block = trislice_block(box, 0.5);
  for (int a = 0; a < 3; ++a)
    for (const PolygonSet& s : block.families[static_cast<std::size_t>(a)].slices)
      EXPECT_NEAR(area(s), expect[a], 1e-9);
  EXPECT_FALSE(build_trislice(make_box(box), 0.0).ok());
}

TEST(TriSliceModel, IndependentOfThreadCount) {
  const Mesh torus = make_torus({0, 0, 0}, 10, 4, 48, 24);
  Context one, many;
  one.threads = 1;
  many.threads = 3;
  auto a = build_trislice(torus, 0.5, {}, one);
  auto b = build_trislice(torus, 0.5, {}, many);
  ASSERT_TRUE(a.ok() && b.ok());
  for (int f = 0; f < 3; ++f) {
    const auto& fa = a->families[static_cast<std::size_t>(f)];
    const auto& fb = b->families[static_cast<std::size_t>(f)];
    ASSERT_EQ(fa.size(), fb.size());
    for (std::size_t j = 0; j < fa.size(); ++j)
      ASSERT_EQ(fa.slices[j].rings, fb.slices[j].rings);
  }
}

TEST(ConvolutionalOffset, BoxInflationMatchesTheRoundedBox) {
  // Faces on the lattice: Eq. (1) is exact here up to the arc tolerance.
  const Box3 box{{-5, -4, -3}, {5, 4, 3}};
  auto model = build_trislice(make_box(box), 0.25);
  ASSERT_TRUE(model.ok());
  const SliceFamily& fy = model->family(Axis::kY);
  const double r = 2.0;
  // Inside the box (y = 0): the zx rectangle 6 x 10 rounded by r.
  const PolygonSet mid = convolve_slice(fy, 0, r);
  EXPECT_NEAR(area(mid), (10 + 2 * r) * (6 + 2 * r) - (4 - kPi) * r * r, 0.05);
  // Beyond the face y = 4 by d = 1: the face offset by sqrt(r^2 - d^2).
  const double rho = std::sqrt(r * r - 1.0);
  const PolygonSet out = convolve_slice(fy, 20, r);  // level 20 * 0.25 = 5
  EXPECT_NEAR(area(out), (10 + 2 * rho) * (6 + 2 * rho) - (4 - kPi) * rho * rho, 0.05);
  EXPECT_TRUE(convolve_slice(fy, 25, r).empty());  // y = 6.25: beyond r of the box
  // Shrinking: the box shrunk by 1 at y = 2.5 is the 8 x 4 rectangle; at y = 3.5 the ball
  // no longer fits (the face is 0.5 away).
  EXPECT_NEAR(area(convolve_slice(fy, 10, -1.0)), 8.0 * 4.0, 0.02);
  EXPECT_TRUE(convolve_slice(fy, 14, -1.0).empty());
  // Whole family: inflation adds ceil(r / ds) slices at each end; the closing of a convex
  // solid is the solid itself.
  auto inflated = offset_family(fy, r);
  ASSERT_TRUE(inflated.ok());
  EXPECT_EQ(inflated->size(), fy.size() + 16);
  const PolygonSet closed = convolve_slice(*inflated, 0, -r);
  EXPECT_NEAR(area(closed), 60.0, 0.05);
}

TEST(ConvolutionalOffset, SphereInflationWithinTheStatedBound) {
  const double Rs = 10.0, r = 3.0, ds = 0.25;
  const int seg = 128;
  auto model = build_trislice(make_sphere({0, 0, 0}, Rs, seg), ds);
  ASSERT_TRUE(model.ok());
  // Facets lie inside the sphere by at most the sagitta of a cell's diagonal.
  const double sag = Rs * (1.0 - std::cos(kPi / seg * std::sqrt(2.0)));
  const double eq1 = ds * ds / (8.0 * r);  // offset.h, transversal surface (here theta ~ 90 deg)
  for (long k : {0L, 8L, 20L, 36L}) {
    const double y = k * ds;
    const double expect = std::sqrt((Rs + r) * (Rs + r) - y * y);
    const double got = std::sqrt(area(convolve_slice(model->family(Axis::kY), k, r)) / kPi);
    EXPECT_LE(got, expect + 0.002) << y;  // never beyond the exact offset (+ arc tolerance)
    EXPECT_GE(got, expect - (sag + eq1) * (Rs + r) / expect - 0.002) << y;
  }
}

TEST(ConvolutionalOffset, EnvelopeEqualsTheTopOfTheInflatedSlice) {
  // The point-wise envelope (envelope.h) is Eq. (1) restricted to the vertical line: compare
  // it with the top of the polygon that Eq. (1) builds.
  const Mesh torus = make_torus({0, 0, 2}, 10, 4, 64, 32);
  auto model = build_trislice(torus, 0.25);
  ASSERT_TRUE(model.ok());
  const SliceFamily& fy = model->family(Axis::kY);
  const SliceEnvelope env = SliceEnvelope::build(fy);
  const double r = 3.0;
  for (long k : {-40L, -22L, 0L, 13L, 50L}) {
    const PolygonSet inflated = convolve_slice(fy, k, r);
    ASSERT_FALSE(inflated.empty());
    for (double x = -16.9; x <= 17.0; x += 0.7) {
      const double poly = top_at(inflated, x);
      const double point = env.centre_height({x, k * 0.25}, r, -1e9);
      if (!std::isfinite(poly)) {
        EXPECT_EQ(point, -1e9) << x;
        continue;
      }
      // Clipper's round joins lie inside the true arcs by up to the arc tolerance (0.001 mm),
      // measured normal to the boundary: vertically 0.001 * sqrt(1 + slope^2). Where two
      // nearly parallel arcs of neighbour slices cross, the crossing of their chords moves
      // further (by tol / sin(half the crossing angle)): allow 2.5 times. The envelope is the
      // exact value the polygon approximates, never below it.
      const double h = 1e-3;
      const double slope = (env.centre_height({x + h, k * 0.25}, r, -1e9) -
                            env.centre_height({x - h, k * 0.25}, r, -1e9)) /
                           (2 * h);
      EXPECT_GE(point, poly - 2e-5) << "y " << k * 0.25 << " x " << x;
      EXPECT_LE(point - poly, 2.5 * 0.0011 * std::sqrt(1 + slope * slope) + 1e-5)
          << "y " << k * 0.25 << " x " << x;
    }
  }
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// Brute force of Eq. (1) on one family at one point: every slice within r, every edge of it,
// a disc of radius sqrt(r^2 - dq^2) dropped on the edge (its ends, and its interior where the
// disc meets it along its normal). Downward edges are included: they can never be the first
// contact, so they must not change the answer either.
double brute_envelope(const SliceFamily& fam, Vec2 p, double r) {
  const bool nx = fam.axis == Axis::kX;
  const double q = nx ? p.x : p.y, s = nx ? p.y : p.x;
  double best = -1e9;
  for (std::size_t j = 0; j < fam.size(); ++j) {
    const double dq = q - fam.level(j);
    if (dq * dq > r * r) continue;
    const double rho = std::sqrt(r * r - dq * dq);
    for (const Ring& ring : fam.slices[j].rings)
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()];
        // (along, z) of the ends in the plane's coordinates.
        const Vec2 u = nx ? a : Vec2{a.y, a.x}, v = nx ? b : Vec2{b.y, b.x};
        for (const Vec2& e : {u, v})
          if (std::fabs(s - e.x) <= rho)
            best = std::max(best, e.y + std::sqrt(rho * rho - (s - e.x) * (s - e.x)));
        const Vec2 d = v - u;
        const double len = norm(d);
        if (len <= 0.0) continue;
        Vec2 n{-d.y / len, d.x / len};  // one of the normals; take the upward one
        if (n.y < 0.0) n = n * -1.0;
        if (n.y <= 0.0) continue;
        const double qs = s - rho * n.x;
        const double t = (qs - u.x) / d.x;
        if (d.x != 0.0 && t >= 0.0 && t <= 1.0) best = std::max(best, u.y + t * d.y + rho * n.y);
      }
  }
  return best;
}

// The pruning of SliceEnvelope (bins, block and slice upper lines, segment boxes, the hint)
// must not change the answer: against brute force on the Table 2 part, at scattered points
// and along a scan line (where the hint carries over). Both bin widths that
// TriSliceTop::auto_bin_mm picks must give the same answer, to the bit (the bins only decide
// what is pruned; the winner's height is computed the same way).
TEST(ConvolutionalOffset, EnvelopePruningEqualsBruteForce) {
  auto model = build_trislice_families(make_filleted_torus_part(), 0.1, {true, true, false});
  ASSERT_TRUE(model.ok());
  for (Axis a : {Axis::kX, Axis::kY}) {
    const SliceFamily& fam = model->family(a);
    const SliceEnvelope env = SliceEnvelope::build(fam, 0.5);
    const SliceEnvelope wide = SliceEnvelope::build(fam, 1.0);
    std::uint32_t hint = SliceEnvelope::kNoHint, wide_hint = SliceEnvelope::kNoHint;
    std::size_t n = 0;
    for (double y = -39.0; y <= 39.0; y += 7.9)
      for (double x = -41.0; x <= 41.0; x += 0.37) {
        const Vec2 p{x, y};
        const double brute = brute_envelope(fam, p, 4.0);
        const double with_hint = env.centre_height(p, 4.0, -1e9, &hint);
        EXPECT_NEAR(with_hint, brute, 1e-9) << x << " " << y;
        EXPECT_NEAR(env.centre_height(p, 4.0, -1e9), brute, 1e-9) << x << " " << y;
        EXPECT_EQ(wide.centre_height(p, 4.0, -1e9, &wide_hint), with_hint) << x << " " << y;
        EXPECT_EQ(wide.centre_height(p, 4.0, -1e9), with_hint) << x << " " << y;
        ++n;
      }
    EXPECT_GT(n, 2000u);
  }
}

// Brute force over every ring edge of every xy slice: the highest z_l + sqrt(r^2 - d^2), d the
// distance from p to the edge's nearest point within r (-1e9 when none).
double brute_level_height(const SliceFamily& fam, Vec2 p, double r) {
  double brute = -1e9;
  for (std::size_t j = 0; j < fam.size(); ++j)
    for (const Ring& ring : fam.slices[j].rings)
      for (std::size_t k = 0; k < ring.size(); ++k) {
        const Vec2 a = ring[k], b = ring[(k + 1) % ring.size()], e = b - a;
        const double len2 = dot(e, e);
        const double t = len2 > 0 ? std::clamp(dot(p - a, e) / len2, 0.0, 1.0) : 0.0;
        const double d2 = norm_sq(a + e * t - p);
        if (d2 <= r * r) brute = std::max(brute, fam.level(j) + std::sqrt(r * r - d2));
      }
  return brute;
}

// The level index (cells, super-cells, highest level first) against every ring edge of every
// xy slice: z_l + sqrt(r^2 - d^2) for the nearest point of the edge within r. Both cell sizes
// that TriSliceTop::auto_level_cell_mm picks give the same answer, to the bit, with and
// without the hint.
TEST(ConvolutionalOffset, LevelEnvelopePruningEqualsBruteForce) {
  auto model = build_trislice_families(make_filleted_torus_part(), 0.25, {false, false, true});
  ASSERT_TRUE(model.ok());
  const SliceFamily& fam = model->family(Axis::kZ);
  const LevelEnvelope env = LevelEnvelope::build(fam, 1.0);
  const LevelEnvelope wide = LevelEnvelope::build(fam, 2.0);
  const double r = 4.0;
  std::size_t n = 0;
  for (double y = -43.0; y <= 43.0; y += 4.3) {
    std::uint32_t hint = SliceEnvelope::kNoHint, wide_hint = SliceEnvelope::kNoHint;
    for (double x = -43.0; x <= 43.0; x += 0.53) {
      const double brute = brute_level_height(fam, {x, y}, r);
      const double narrow = env.centre_height({x, y}, r, -1e9);
      EXPECT_NEAR(narrow, brute, 1e-9) << x << " " << y;
      EXPECT_EQ(wide.centre_height({x, y}, r, -1e9), narrow) << x << " " << y;
      // A query seeded from the previous winner, as the scan lines ask.
      const double seeded = std::max(-1e9, env.hint_height({x, y}, r, hint));
      EXPECT_EQ(env.centre_height({x, y}, r, seeded, &hint), narrow) << x << " " << y;
      const double wide_seeded = std::max(-1e9, wide.hint_height({x, y}, r, wide_hint));
      EXPECT_EQ(wide.centre_height({x, y}, r, wide_seeded, &wide_hint), narrow) << x << " " << y;
      ++n;
    }
  }
  EXPECT_GT(n, 3000u);
}

// An octagonal frustum (drafted walls: long diagonal ring edges, different on every level)
// beside an octagonal prism (vertical walls: the same ring edges on every level).
Mesh drafted_and_vertical_walls() {
  Mesh m;
  const int n = 8;
  auto ring = [&](double r, double z) {
    const std::size_t first = m.vertices.size();
    for (int k = 0; k < n; ++k) {
      const double a = 2.0 * M_PI * (k + 0.5) / n;
      m.vertices.push_back({r * std::cos(a) - 20.0, r * std::sin(a), z});
    }
    return static_cast<std::uint32_t>(first);
  };
  const std::uint32_t lo = ring(30.0, 0.0), hi = ring(24.0, 8.0);
  const auto c0 = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.push_back({-20.0, 0.0, 0.0});
  const auto c1 = static_cast<std::uint32_t>(m.vertices.size());
  m.vertices.push_back({-20.0, 0.0, 8.0});
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t k1 = (k + 1) % n;
    m.triangles.push_back({lo + k, lo + k1, hi + k1});
    m.triangles.push_back({lo + k, hi + k1, hi + k});
    m.triangles.push_back({c0, lo + k1, lo + k});
    m.triangles.push_back({c1, hi + k, hi + k1});
  }
  append(m, make_cylinder({40.0, 0.0, 0.0}, 12.0, 6.0, 8));
  return m;
}

// The level index lists each edge in the cells it crosses (not its bounding box) and leaves
// out edges repeated from the level above; neither may change an answer. Against every ring
// edge of every level, near both kinds of wall.
TEST(ConvolutionalOffset, LevelEnvelopeOnDraftedAndVerticalWallsEqualsBruteForce) {
  auto model = build_trislice_families(drafted_and_vertical_walls(), 0.1, {false, false, true});
  ASSERT_TRUE(model.ok());
  const SliceFamily& fam = model->family(Axis::kZ);
  const LevelEnvelope env = LevelEnvelope::build(fam, 1.0);
  const LevelEnvelope wide = LevelEnvelope::build(fam, 2.0);
  std::size_t ring_edges = 0;
  for (const PolygonSet& set : fam.slices)
    for (const Ring& ring : set.rings)
      ring_edges += ring.size();
  // The prism's 8 edges appear once instead of on each of its ~60 levels.
  EXPECT_LT(env.segment_count() + 400, ring_edges);
  const double r = 4.0;
  std::size_t n = 0;
  for (double y = -33.0; y <= 33.0; y += 2.9)
    for (double x = -55.0; x <= 57.0; x += 0.47) {
      const double brute = brute_level_height(fam, {x, y}, r);
      ASSERT_NEAR(env.centre_height({x, y}, r, -1e9), brute, 1e-9) << x << " " << y;
      ASSERT_EQ(wide.centre_height({x, y}, r, -1e9), env.centre_height({x, y}, r, -1e9));
      if (brute > 0.0) ++n;
    }
  EXPECT_GT(n, 1500u);
}

}  // namespace
}  // namespace swarf

namespace swarf {
namespace {

// convolve_slices (each neighbour offset once, shared by the two levels that use it) must
// give convolve_slice's result at every level, inflating and shrinking, with a stride and
// across the ends of the family.
TEST(ConvolutionalOffset, SlicesInOneGoEqualSliceBySlice) {
  const Mesh torus = make_torus({0, 0, 2}, 10, 4, 48, 24);
  auto model = build_trislice_families(torus, 0.25, {false, true, false});
  ASSERT_TRUE(model.ok());
  const SliceFamily& fy = model->family(Axis::kY);
  const long first = lattice_index(fy, 0) - 14;
  const std::size_t count = fy.size() + 28;
  for (int stride : {1, 3})
    for (double r : {3.0, -1.5}) {
      ConvolutionOptions co;
      co.neighbour_stride = stride;
      const std::vector<PolygonSet> all = convolve_slices(fy, first, count, r, co);
      ASSERT_EQ(all.size(), count);
      std::size_t nonempty = 0;
      for (std::size_t k = 0; k < count; ++k) {
        const PolygonSet one = convolve_slice(fy, first + static_cast<long>(k), r, co);
        ASSERT_EQ(all[k].rings, one.rings) << "level " << k << " r " << r << " stride " << stride;
        nonempty += !one.empty();
      }
      EXPECT_GT(nonempty, 20u);
    }
}

}  // namespace
}  // namespace swarf
