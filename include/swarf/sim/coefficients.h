// Identification of the six cutting coefficients from the mean forces of test cuts
// (seed 001 section 4.2, Table 5, Fig. 17). The paper matches simulated means by iterative
// search; the mean forces are linear in the coefficients, so here one linear least-squares
// solve (Householder QR on a column-scaled matrix) gives the same answer directly, with
// residuals.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "swarf/core/status.h"
#include "swarf/core/vec.h"
#include "swarf/sim/force.h"

namespace swarf::sim {

/// Which side of the tool the material of a test cut lies on (feed along +x).
enum class CutMode {
  kSlot,  ///< full immersion
  kUp,    ///< conventional: material on +y, chips start thin
  kDown,  ///< climb: material on -y, chips start thick
};

/// One straight test cut at steady state: the tool tip at depth `axial_depth_mm` below a
/// flat top face, `radial_depth_mm` into a vertical side wall (>= diameter: a slot).
struct TestCut {
  double spindle_rpm = 3600.0;
  double feed_mm_min = 200.0;
  double axial_depth_mm = 2.0;
  double radial_depth_mm = 7.0;
  CutMode mode = CutMode::kDown;
  Vec3 mean_force_n;  ///< measured mean Fx, Fy, Fz on the tool (feed along +x)
};

/// Reads a CSV with a header naming the columns spindle_rpm, feed_mm_min, axial_depth_mm,
/// radial_depth_mm, fx_n, fy_n, fz_n and optionally mode (slot, up or down; default: slot
/// when the radial depth reaches the diameter, else down). Other columns are ignored;
/// '#' lines are comments. Errors name the source and line.
Result<std::vector<TestCut>> parse_test_cuts(std::string_view csv, std::string_view source,
                                             double tool_diameter_mm);

/// Predicted mean force of a test cut with the model's coefficients.
Vec3 predicted_mean_force(const ForceModel& model, const TestCut& cut);

struct CoefficientFit {
  CuttingCoefficients coefficients;
  std::vector<Vec3> predicted_n;  ///< per cut
  std::vector<Vec3> residual_n;   ///< measured - predicted, per cut
  double rms_residual_n = 0.0;    ///< over all cuts and axes
  double max_residual_n = 0.0;
};

/// Least-squares fit of Ktc, Kte, Krc, Kre, Kac, Kae. Needs cuts at two feeds or more
/// (to separate cutting from edge terms): kBadInput when the cuts leave a coefficient
/// undetermined.
Result<CoefficientFit> fit_coefficients(const std::vector<TestCut>& cuts,
                                        const CutterGeometry& cutter,
                                        const ForceModelOptions& options = {});

/// {"ktc_n_mm2": ..., "kte_n_mm": ..., ...} and back (missing keys keep Table 4 defaults).
std::string coefficients_to_json(const CuttingCoefficients& k);
Result<CuttingCoefficients> parse_coefficients_json(std::string_view text, std::string_view source);

}  // namespace swarf::sim
