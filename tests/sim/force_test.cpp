// The force model against independent truths: Altintas' closed-form mean forces of a
// cylindrical end mill, and a direct numerical integration of the ball-end model written
// here in Altintas' own conventions (immersion angle clockwise from +y).
#include <gtest/gtest.h>

#include <cmath>

#include "sim/sim_test_util.h"
#include "swarf/sim/force.h"

namespace swarf::sim {
namespace {

using testing::al7075;

// Altintas' immersion angle of a point relative to the tool axis, in [0, 2π).
double immersion(Vec3 p) {
  double t = std::atan2(p.x, p.y);
  if (t < 0.0) t += 2.0 * kPi;
  return t;
}

struct Cut {
  double start_rad, exit_rad;
};

Vec3 closed_form_mean(const CuttingCoefficients& k, int flutes, double axial, double ft, Cut c) {
  return testing::altintas_mean(k, flutes, axial, ft, c.start_rad, c.exit_rad);
}

void expect_close(Vec3 got, Vec3 want, double rel) {
  const double scale = std::max({std::abs(want.x), std::abs(want.y), std::abs(want.z)});
  EXPECT_NEAR(got.x, want.x, rel * scale);
  EXPECT_NEAR(got.y, want.y, rel * scale);
  EXPECT_NEAR(got.z, want.z, rel * scale);
}

class FlatMeanForce : public ::testing::TestWithParam<Cut> {};

TEST_P(FlatMeanForce, MatchesClosedFormWithinOnePercent) {
  const Cut cut = GetParam();
  CutterGeometry g;
  g.kind = ToolKind::kFlat;
  g.radius_mm = 5.0;
  g.corner_radius_mm = 0.0;
  g.flutes = 4;
  g.helix_deg = 30.0;
  g.edge_length_mm = 20.0;
  const auto model = ForceModel::create(g, al7075(), {0.1, 1.0});
  ASSERT_TRUE(model.ok()) << model.status().to_string();
  const double axial = 3.0, ft = 0.1;
  const ElementTable t = element_table(*model, ft, {1, 0, 0}, [&](std::size_t, Vec3 p) {
    const double th = immersion(p);
    return p.z <= axial && th >= cut.start_rad && th <= cut.exit_rad;
  });
  expect_close(mean_force(*model, t), closed_form_mean(al7075(), 4, axial, ft, cut), 0.01);
  // The time average of the waveform over one revolution is the same mean.
  Vec3 avg;
  for (long i = 0; i < model->steps_per_rev(); ++i)
    avg += total_force(*model, t, i);
  avg = avg / model->steps_per_rev();
  expect_close(avg, closed_form_mean(al7075(), 4, axial, ft, cut), 0.01);
}

const double kUp2 = std::acos(1.0 - 2.0 / 5.0);  // radial depth 2 mm on ø10
INSTANTIATE_TEST_SUITE_P(Immersions, FlatMeanForce,
                         ::testing::Values(Cut{0.0, kPi},          // slotting
                                           Cut{0.0, kUp2},         // up milling, 2 mm radial
                                           Cut{kPi - kUp2, kPi},   // down milling, 2 mm radial
                                           Cut{0.0, 0.5 * kPi},    // half immersion up
                                           Cut{0.5 * kPi, kPi}));  // half immersion down

// Direct integration of Altintas' ball-end model along the edge (fine steps in κ), the
// helix lag ψ = z tanβ / R, slotting to depth `axial` with feed along +x.
Vec3 ball_integral(const CuttingCoefficients& k, double radius, int flutes, double helix_deg,
                   double axial, double ft, double theta_tip) {
  Vec3 f;
  const int n = 20000;
  const double top = axial;  // integrate by height z in [0, top]
  const double tb = std::tan(deg_to_rad(helix_deg));
  for (int i = 0; i < n; ++i) {
    const double z0 = top * i / n, z1 = top * (i + 1) / n;
    double kappa, db;
    double z = 0.5 * (z0 + z1);
    if (z1 <= radius) {
      const double k0 = std::acos((radius - z0) / radius), k1 = std::acos((radius - z1) / radius);
      kappa = 0.5 * (k0 + k1);
      db = radius * (k1 - k0);
      z = radius * (1 - std::cos(kappa));
    } else {
      kappa = 0.5 * kPi;
      db = z1 - z0;
    }
    const double psi = z * tb / radius;
    for (int j = 0; j < flutes; ++j) {
      double th = std::fmod(theta_tip + j * 2 * kPi / flutes - psi, 2 * kPi);
      if (th < 0) th += 2 * kPi;
      if (th > kPi) continue;  // slot: material on θ in [0, π]
      const double h = ft * std::sin(th) * std::sin(kappa);
      if (h <= 0) continue;
      const double dft = (k.ktc_n_mm2 * h + k.kte_n_mm) * db;
      const double dfr = (k.krc_n_mm2 * h + k.kre_n_mm) * db;
      const double dfa = (k.kac_n_mm2 * h + k.kae_n_mm) * db;
      const double sk = std::sin(kappa), ck = std::cos(kappa);
      f.x += -dfr * sk * std::sin(th) - dft * std::cos(th) - dfa * ck * std::sin(th);
      f.y += -dfr * sk * std::cos(th) + dft * std::sin(th) - dfa * ck * std::cos(th);
      f.z += dfr * ck - dfa * sk;
    }
  }
  return f;
}

class BallWaveform : public ::testing::TestWithParam<double> {};

TEST_P(BallWaveform, MatchesDirectIntegration) {
  const double axial = GetParam();
  CutterGeometry g;  // the paper's ø8 ball, helix 30°, two flutes
  const auto model = ForceModel::create(g, al7075(), {0.02, 1.0});
  ASSERT_TRUE(model.ok());
  const double ft = 200.0 / (3600.0 * 2);
  const ElementTable t = element_table(*model, ft, {1, 0, 0}, [&](std::size_t, Vec3 p) {
    return p.z <= axial + 1e-9 && immersion(p) <= kPi;
  });
  double peak = 0.0, worst = 0.0;
  for (long i = 0; i < model->steps_per_rev(); i += 5) {
    // Step i puts flute 0's tip at φ = -i dθ, i.e. Altintas' θ = π/2 + i dθ.
    const Vec3 want =
        ball_integral(al7075(), 4.0, 2, 30.0, axial, ft, 0.5 * kPi + i * model->angle_step_rad());
    const Vec3 got = total_force(*model, t, i);
    peak = std::max(peak, norm(want));
    worst = std::max(worst, norm(got - want));
  }
  ASSERT_GT(peak, 1.0);
  EXPECT_LT(worst, 0.01 * peak) << "peak " << peak;
}

INSTANTIATE_TEST_SUITE_P(Depths, BallWaveform, ::testing::Values(2.0, 5.0));

TEST(ForceModel, BullNoseLimitsAreFlatAndBall) {
  const CuttingCoefficients k = al7075();
  CutterGeometry ball;  // ø8 ball
  CutterGeometry bull = ball;
  bull.kind = ToolKind::kBull;
  bull.corner_radius_mm = 4.0 - 1e-9;
  CutterGeometry flat = ball;
  flat.kind = ToolKind::kFlat;
  CutterGeometry bull0 = flat;
  bull0.kind = ToolKind::kBull;
  bull0.corner_radius_mm = 1e-9;
  auto slot = [](std::size_t, Vec3 p) { return p.z <= 3.0 && immersion(p) <= kPi; };
  auto mean = [&](const CutterGeometry& g) {
    const auto m = ForceModel::create(g, k, {0.1, 1.0});
    EXPECT_TRUE(m.ok());
    return mean_force(*m, element_table(*m, 0.05, {1, 0, 0}, slot));
  };
  expect_close(mean(bull), mean(ball), 1e-6);
  expect_close(mean(bull0), mean(flat), 1e-6);
}

TEST(ForceModel, EdgeLengthOfBallElementsSumsToArc) {
  CutterGeometry g;
  g.edge_length_mm = 4.0;  // just the hemisphere
  const auto m = ForceModel::create(g, {}, {0.1, 1.0});
  ASSERT_TRUE(m.ok());
  double s = 0.0;
  for (const EdgeLevel& lv : m->levels())
    s += lv.db_mm;
  EXPECT_NEAR(s, 0.5 * kPi * 4.0, 1e-9);  // quarter circle of radius 4
}

TEST(ForceModel, RejectsBadParameters) {
  CutterGeometry g;
  g.flutes = 0;
  EXPECT_EQ(ForceModel::create(g, {}).status().code(), Error::kBadParameter);
  g = {};
  EXPECT_EQ(ForceModel::create(g, {}, {0.0, 1.0}).status().code(), Error::kBadParameter);
  g.corner_radius_mm = 5.0;
  g.kind = ToolKind::kBull;
  EXPECT_EQ(ForceModel::create(g, {}).status().code(), Error::kBadParameter);
}

}  // namespace
}  // namespace swarf::sim
