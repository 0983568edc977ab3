// Coefficient identification: recover known coefficients from synthetic test cuts.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sim/sim_test_util.h"
#include "swarf/sim/coefficients.h"

namespace swarf::sim {
namespace {

// The closed-form means (Altintas) are an independent generator of flat-end-mill "measurements".
using testing::altintas_mean;

// Box-Muller on a fixed-seed engine: the same noise on every platform.
double gauss(std::mt19937& rng) {
  const double u1 = (rng() + 1.0) / 4294967297.0, u2 = (rng() + 1.0) / 4294967297.0;
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * kPi * u2);
}

TEST(CoefficientFit, RecoversFlatEndMillCoefficientsFromNoisyCuts) {
  const CuttingCoefficients truth = testing::al7075();
  CutterGeometry g;
  g.kind = ToolKind::kFlat;
  g.radius_mm = 5.0;
  g.corner_radius_mm = 0.0;
  g.flutes = 4;
  std::mt19937 rng(12345);
  std::vector<TestCut> cuts;
  const double rpm = 3000.0;
  for (double ft : {0.05, 0.1, 0.15}) {
    for (CutMode mode : {CutMode::kSlot, CutMode::kUp, CutMode::kDown}) {
      TestCut c;
      c.spindle_rpm = rpm;
      c.feed_mm_min = ft * rpm * 4;
      c.axial_depth_mm = 3.0;
      c.radial_depth_mm = mode == CutMode::kSlot ? 10.0 : 3.0;
      c.mode = mode;
      const double ex = std::acos(1.0 - 3.0 / 5.0);
      const double st = mode == CutMode::kSlot ? 0.0 : (mode == CutMode::kUp ? 0.0 : kPi - ex);
      const double en = mode == CutMode::kSlot ? kPi : (mode == CutMode::kUp ? ex : kPi);
      c.mean_force_n = altintas_mean(truth, 4, 3.0, ft, st, en);
      c.mean_force_n += Vec3{gauss(rng), gauss(rng), gauss(rng)} * 2.0;  // 2 N noise
      cuts.push_back(c);
    }
  }
  const auto fit = fit_coefficients(cuts, g, {0.1, 0.5});
  ASSERT_TRUE(fit.ok()) << fit.status().to_string();
  const CuttingCoefficients& k = fit->coefficients;
  EXPECT_NEAR(k.ktc_n_mm2, truth.ktc_n_mm2, 0.03 * truth.ktc_n_mm2);
  EXPECT_NEAR(k.krc_n_mm2, truth.krc_n_mm2, 0.05 * truth.krc_n_mm2);
  EXPECT_NEAR(k.kac_n_mm2, truth.kac_n_mm2, 0.05 * truth.kac_n_mm2);
  EXPECT_NEAR(k.kte_n_mm, truth.kte_n_mm, 0.1 * truth.kte_n_mm);
  EXPECT_NEAR(k.kre_n_mm, truth.kre_n_mm, 0.1 * truth.kre_n_mm);
  EXPECT_NEAR(k.kae_n_mm, truth.kae_n_mm, 1.0);
  // The residuals are the noise: about 2 N rms, not more.
  EXPECT_LT(fit->rms_residual_n, 4.0);
  EXPECT_GT(fit->rms_residual_n, 0.5);
}

TEST(CoefficientFit, PaperTable5CutsRecoverTable4Coefficients) {
  // Table 5's nine cuts with a ø8 ball; "measurements" made with the model and Table 4's
  // coefficients plus 1% noise: the fit must return Table 4's cutting terms.
  const CuttingCoefficients truth;  // Table 4
  CutterGeometry g;                 // ø8 ball, helix 30°, 2 flutes
  ForceModelOptions opt{0.1, 1.0};
  std::mt19937 rng(7);
  std::vector<TestCut> cuts;
  const double depths[3][2] = {{8.0, 1.5}, {5.0, 3.0}, {2.0, 7.0}};
  for (double feed : {100.0, 200.0, 300.0}) {
    for (const auto& d : depths) {
      TestCut c;
      c.feed_mm_min = feed;
      c.axial_depth_mm = d[0];
      c.radial_depth_mm = d[1];
      CutterGeometry gg = g;
      gg.edge_length_mm = d[0];
      const auto m = ForceModel::create(gg, truth, opt);
      ASSERT_TRUE(m.ok());
      const Vec3 f = predicted_mean_force(*m, c);
      c.mean_force_n = f + Vec3{gauss(rng), gauss(rng), gauss(rng)} * (0.01 * norm(f));
      cuts.push_back(c);
    }
  }
  const auto fit = fit_coefficients(cuts, g, opt);
  ASSERT_TRUE(fit.ok()) << fit.status().to_string();
  EXPECT_NEAR(fit->coefficients.ktc_n_mm2, truth.ktc_n_mm2, 0.03 * truth.ktc_n_mm2);
  EXPECT_NEAR(fit->coefficients.krc_n_mm2, truth.krc_n_mm2, 0.06 * truth.krc_n_mm2);
}

TEST(CoefficientFit, OneFeedCannotSeparateEdgeTerms) {
  CutterGeometry g;
  g.kind = ToolKind::kFlat;
  g.corner_radius_mm = 0.0;
  std::vector<TestCut> cuts(3);
  for (auto& c : cuts) {
    c.mode = CutMode::kSlot;
    c.radial_depth_mm = 8.0;
    c.mean_force_n = {-100, 200, 0};
  }
  EXPECT_EQ(fit_coefficients(cuts, g).status().code(), Error::kBadInput);
}

TEST(CoefficientFit, ParsesCsvAndNamesBadLines) {
  const std::string csv =
      "# Table 5\n"
      "spindle_rpm,feed_mm_min,axial_depth_mm,radial_depth_mm,fx_n,fy_n,fz_n,mode\n"
      "3600,100,8,1.5,-10,20,3,up\n"
      "3600,200,2,8,-11,21,4,\n";
  const auto cuts = parse_test_cuts(csv, "cuts.csv", 8.0);
  ASSERT_TRUE(cuts.ok()) << cuts.status().to_string();
  ASSERT_EQ(cuts->size(), 2u);
  EXPECT_EQ((*cuts)[0].mode, CutMode::kUp);
  EXPECT_EQ((*cuts)[1].mode, CutMode::kSlot);
  EXPECT_DOUBLE_EQ((*cuts)[1].mean_force_n.y, 21.0);
  const auto bad = parse_test_cuts(
      "spindle_rpm,feed_mm_min,axial_depth_mm,radial_depth_mm,fx_n,fy_n,fz_n\n1,2,x,4,5,6,7\n",
      "t.csv", 8.0);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find("t.csv:2"), std::string::npos);
  const auto k = parse_coefficients_json(coefficients_to_json(CuttingCoefficients{}), "k.json");
  ASSERT_TRUE(k.ok());
  EXPECT_DOUBLE_EQ(k->ktc_n_mm2, 935.62);
  EXPECT_DOUBLE_EQ(k->kae_n_mm, 3.32e-06);
}

}  // namespace
}  // namespace swarf::sim
