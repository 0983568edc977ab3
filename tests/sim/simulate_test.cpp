// End-to-end simulation: removal, engagement and forces together against closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/sim_test_util.h"
#include "swarf/sim/simulate.h"

namespace swarf::sim {
namespace {

using testing::al7075;

Tool flat10() {
  Tool t = flat_mill(10.0);
  t.flutes = 4;
  t.helix_angle_deg = 30.0;
  t.flute_length_mm = 10.0;
  return t;
}

// A slot 2 mm deep along +x through the block's x = 0 face, ending at x = 40.
Toolpath slot_path(double feed) {
  Toolpath p;
  p.spindle_rpm = 3000.0;
  p.rapid_to({-10, 20, 25});
  p.rapid_to({-10, 20, 18});
  p.feed_to({40, 20, 18}, feed);
  p.rapid_to({40, 20, 25});
  return p;
}

Stock block() {
  return std::move(Stock::block({{0, 0, 0}, {60, 40, 20}}, 0.1)).value();
}

TEST(Simulate, SlotVolumeAndMeanForceMatchClosedForms) {
  Stock stock = block();
  const double feed = 0.1 * 3000 * 4;  // 0.1 mm per tooth
  SimulationOptions opt;
  const auto r = simulate(stock, slot_path(feed), flat10(), al7075(), opt);
  ASSERT_TRUE(r.ok()) << r.status().to_string();
  EXPECT_TRUE(r->collisions.empty());
  const double want_v = 2.0 * (10.0 * 40.0 + kPi * 25.0 / 2.0);
  EXPECT_NEAR(r->removed_mm3, want_v, 0.005 * want_v);
  EXPECT_NEAR(r->moves[2].removed_mm3, want_v, 0.005 * want_v);
  // Mean force over the steady part of the slot (x in 15..35) against Altintas' slotting
  // mean: Fx = -N a ft Krc / 4 - N a Kre / π, Fy = N a ft Ktc / 4 + N a Kte / π.
  const double n = 4, a = 2, ft = 0.1;
  const CuttingCoefficients k = al7075();
  const Vec3 want{-n * a * ft * k.krc_n_mm2 / 4 - n * a * k.kre_n_mm / kPi,
                  n * a * ft * k.ktc_n_mm2 / 4 + n * a * k.kte_n_mm / kPi,
                  -n * a / (2 * kPi) * (2 * k.kac_n_mm2 * ft + k.kae_n_mm * kPi)};
  const double t_in = r->moves[2].t_start_s + 25.0 / feed * 60.0;
  const double t_out = r->moves[2].t_start_s + 45.0 / feed * 60.0;
  Vec3 sum;
  int count = 0;
  for (const ForceSample& s : r->samples) {
    if (s.t_s < t_in || s.t_s >= t_out) continue;
    sum += s.force_n;
    ++count;
  }
  ASSERT_GT(count, 1000);
  const Vec3 mean = sum / count;
  const double scale = norm(want);
  EXPECT_NEAR(mean.x, want.x, 0.02 * scale);
  EXPECT_NEAR(mean.y, want.y, 0.02 * scale);
  EXPECT_NEAR(mean.z, want.z, 0.02 * scale);
  // Annotations: the cutting move carries its peak force and a 180° engaged arc (slot).
  EXPECT_NEAR(r->annotated.moves[2].force_n, r->moves[2].peak_force_n, 1e-3);
  EXPECT_NEAR(r->moves[2].engaged_arc_deg, 180.0, 2.0);
  EXPECT_TRUE(std::isnan(r->annotated.moves[0].force_n));
  // The floor of the slot is at 18, the untouched top at 20.
  const HeightMap hm = stock.height_map(0.5);
  EXPECT_NEAR(hm.top[static_cast<std::size_t>(40) * hm.nx + 40], 18.0, 1e-6);  // (20.25, 20.25)
  EXPECT_NEAR(hm.top[static_cast<std::size_t>(70) * hm.nx + 40], 20.0, 1e-6);  // (20.25, 35.25)
}

TEST(Simulate, SideCutEngagedArcAndMeanForceMatchDownMilling) {
  // 2 mm radial depth into the block's y = 40 face, 3 mm deep, feed +x: material on -y of
  // the axis, i.e. down milling from θ = π - acos(1 - 2/5) to π (θ clockwise from +y).
  Stock stock = block();
  const double feed = 0.1 * 3000 * 4;
  Toolpath p;
  p.spindle_rpm = 3000.0;
  p.rapid_to({-10, 43, 25});
  p.rapid_to({-10, 43, 17});
  p.feed_to({50, 43, 17}, feed);
  const auto r = simulate(stock, p, flat10(), al7075(), {});
  ASSERT_TRUE(r.ok());
  const double st = kPi - std::acos(1.0 - 2.0 / 5.0);
  EXPECT_NEAR(r->moves[2].engaged_arc_deg, rad_to_deg(kPi - st), 1.5);
  const CuttingCoefficients k = al7075();
  const Vec3 want = testing::altintas_mean(k, 4, 3.0, 0.1, st, kPi);
  Vec3 sum;
  int count = 0;
  const double t0 = r->moves[2].t_start_s;
  for (const ForceSample& s : r->samples) {
    if (s.t_s < t0 + 20.0 / feed * 60.0 || s.t_s >= t0 + 40.0 / feed * 60.0) continue;
    sum += s.force_n;
    ++count;
  }
  ASSERT_GT(count, 1000);
  const Vec3 mean = sum / count;
  EXPECT_NEAR(mean.x, want.x, 0.02 * norm(want));
  EXPECT_NEAR(mean.y, want.y, 0.02 * norm(want));
  EXPECT_NEAR(mean.z, want.z, 0.02 * norm(want));
  // The strip y 38..40 cut off the face from x = 0 to 50, plus the part of the end disk
  // (centre (50, 43), radius 5) inside the strip: the integral of sqrt(25 - u^2), u 3..5.
  auto prim = [](double u) { return u / 2 * std::sqrt(25 - u * u) + 12.5 * std::asin(u / 5); };
  const double want_v = 3.0 * (2.0 * 50.0 + prim(5) - prim(3));
  EXPECT_NEAR(r->removed_mm3, want_v, 0.005 * want_v);
}

// A circular pocket: plunge at the centre, out to a 6 mm circle, round it, as arcs or as a
// run of tiny G1 chords; the pocket is a disk of radius 6 + 5, 3 mm deep either way.
Toolpath circle_pocket(bool chords) {
  Toolpath p;
  p.spindle_rpm = 3000.0;
  const Vec3 c{30, 20, 17};
  p.rapid_to(c + Vec3{0, 0, 8});
  p.plunge_to(c.z, 300.0);
  p.feed_to(c + Vec3{6, 0, 0}, 800.0);
  if (chords) {
    const int n = 754;  // 0.05 mm chords
    for (int i = 1; i <= n; ++i) {
      const double a = 2 * kPi * i / n;
      p.feed_to(c + Vec3{6 * std::cos(a), 6 * std::sin(a), 0}, 800.0);
    }
  } else {
    p.arc_to(c + Vec3{-6, 0, 0}, c.xy(), false, 800.0);
    p.arc_to(c + Vec3{6, 0, 0}, c.xy(), false, 800.0);
  }
  p.rapid_to(c + Vec3{6, 0, 8});
  return p;
}

TEST(Simulate, CircularPocketFromArcsAndFromTinyMoves) {
  const double want = kPi * 11 * 11 * 3;
  for (bool chords : {false, true}) {
    Stock stock = block();
    SimulationOptions opt;
    opt.sample_stride = 50;
    const auto r = simulate(stock, circle_pocket(chords), flat10(), al7075(), opt);
    ASSERT_TRUE(r.ok());
    EXPECT_NEAR(r->removed_mm3, want, 0.005 * want) << (chords ? "chords" : "arcs");
    double per_move = 0.0;
    for (const MoveResult& m : r->moves)
      per_move += m.removed_mm3;
    EXPECT_NEAR(per_move, r->removed_mm3, 1e-6 * want);
    EXPECT_TRUE(r->collisions.empty());
    EXPECT_NEAR(stock.volume_mm3(), 60.0 * 40 * 20 - want, 0.005 * want);
  }
}

TEST(Simulate, HeightMapMeshIsAClosedSolidOfTheStock) {
  Stock stock = block();
  const Vec3 tips[2] = {{10, 20, 18}, {40, 20, 18}};
  stock.remove(ToolSolid{5, 0}, tips);
  const HeightMap hm = stock.height_map(0.5);
  const Mesh m = height_map_mesh(hm, 0.0);
  const MeshCheck c = check_mesh(m);
  EXPECT_TRUE(c.closed());
  EXPECT_EQ(c.inconsistent_edges, 0u);
  // Through the cell centres: the block less a half cell on each side, less the slot.
  const double block_v = (60.0 - 0.5) * (40.0 - 0.5) * 20.0;
  const double slot_v = 2.0 * (10.0 * 30.0 + kPi * 25.0);
  EXPECT_NEAR(c.volume_mm3, block_v - slot_v, 0.01 * slot_v);
}

TEST(Simulate, RapidIntoMaterialIsACollision) {
  Stock stock = block();
  Toolpath p;
  p.spindle_rpm = 3000;
  p.rapid_to({10, 10, 25});
  p.rapid_to({10, 10, 15});  // plunges 5 mm at rapid
  const auto r = simulate(stock, p, flat10(), al7075(), {});
  ASSERT_TRUE(r.ok());
  ASSERT_EQ(r->collisions.size(), 1u);
  EXPECT_TRUE(r->moves[1].collision);
  EXPECT_NEAR(r->moves[1].removed_mm3, kPi * 25 * 5, 0.005 * kPi * 25 * 5);
}

TEST(Simulate, ScheduledFeedKeepsThePeakUnderTheLimit) {
  const double feed = 0.1 * 3000 * 4;
  Stock s1 = block();
  SimulationOptions opt;
  opt.sample_stride = 10;
  const auto r1 = simulate(s1, slot_path(feed), flat10(), al7075(), opt);
  ASSERT_TRUE(r1.ok());
  const double limit = 0.6 * r1->peak_force_n;
  FeedScheduleOptions fo;
  fo.max_force_n = limit;
  const FeedSchedule fs = schedule_feed(slot_path(feed), *r1, fo);
  EXPECT_LT(fs.path.moves[2].feed_mm_min, feed);
  EXPECT_GT(fs.time_after_s, fs.time_before_s);
  // A chip-load limit caps every cutting feed.
  FeedScheduleOptions chip = fo;
  chip.max_force_n = 1e6;
  chip.max_chip_mm = 0.05;
  chip.spindle_rpm = 3000.0;
  chip.flutes = 4;
  EXPECT_NEAR(schedule_feed(slot_path(feed), *r1, chip).path.moves[2].feed_mm_min, 600.0, 1e-9);
  // Re-simulated with the new feeds on fresh stock, the peak meets the limit.
  Stock s2 = block();
  const auto r2 = simulate(s2, fs.path, flat10(), al7075(), opt);
  ASSERT_TRUE(r2.ok());
  EXPECT_LT(r2->peak_force_n, 1.02 * limit);
  EXPECT_GT(r2->peak_force_n, 0.9 * limit);
}

TEST(Simulate, SameResultOnOneThreadAndOnAll) {
  SimulationOptions opt;
  opt.sample_stride = 7;
  Context one, all;
  one.threads = 1;
  all.threads = 0;
  Toolpath p;  // a diagonal entry and an arc: every family and the batching take part
  p.spindle_rpm = 3000.0;
  p.rapid_to({-6, 5, 25});
  p.rapid_to({-6, 5, 18});
  p.feed_to({10, 12, 18}, 1200.0);
  p.arc_to({20, 12, 18}, {15, 12}, true, 1200.0);
  Stock s1 = block(), s2 = block();
  const auto r1 = simulate(s1, p, flat10(), al7075(), opt, one);
  const auto r2 = simulate(s2, p, flat10(), al7075(), opt, all);
  ASSERT_TRUE(r1.ok() && r2.ok());
  EXPECT_EQ(r1->removed_mm3, r2->removed_mm3);
  ASSERT_EQ(r1->samples.size(), r2->samples.size());
  for (std::size_t i = 0; i < r1->samples.size(); ++i) {
    ASSERT_EQ(r1->samples[i].force_n, r2->samples[i].force_n) << i;
  }
  EXPECT_EQ(forces_csv(*r1), forces_csv(*r2));
}

TEST(Simulate, MissingFeedIsAnError) {
  Stock stock = block();
  Toolpath p;
  p.rapid_to({10, 10, 25});
  p.feed_to({20, 10, 25}, 0.0);
  EXPECT_EQ(simulate(stock, p, flat10(), al7075(), {}).status().code(), Error::kBadInput);
}

}  // namespace
}  // namespace swarf::sim
