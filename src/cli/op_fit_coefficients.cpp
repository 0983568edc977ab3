// swarf fit-coefficients TESTCUTS.csv --tool ball:8 --flutes 2 --helix 30 -o K.json
// Identifies the six cutting coefficients of seed 001 Eq. (2) from measured mean forces.
#include "cli/operation.h"
#include "swarf/core/io.h"
#include "swarf/sim/coefficients.h"

namespace swarf::cli {
namespace {

Result<OperationOutput> run_fit(const OperationInput& in) {
  Result<std::string> text = read_file(in.input_path);
  if (!text.ok()) return text.status();
  const Tool& tool = *in.tool;
  Result<std::vector<sim::TestCut>> cuts =
      sim::parse_test_cuts(*text, in.input_path, tool.diameter_mm);
  if (!cuts.ok()) return cuts.status();
  sim::ForceModelOptions opt;
  opt.axial_step_mm = in.params["axial_step"].get<double>();
  opt.angle_step_deg = in.params["angle_step"].get<double>();
  Result<sim::CoefficientFit> fit = sim::fit_coefficients(*cuts, sim::cutter_from_tool(tool), opt);
  if (!fit.ok()) return fit.status().with_context(in.input_path);
  OperationOutput out;
  const sim::CuttingCoefficients& k = fit->coefficients;
  out.primary_output = sim::coefficients_to_json(k);
  out.summary["ktc_n_mm2"] = k.ktc_n_mm2;
  out.summary["kte_n_mm"] = k.kte_n_mm;
  out.summary["krc_n_mm2"] = k.krc_n_mm2;
  out.summary["kre_n_mm"] = k.kre_n_mm;
  out.summary["kac_n_mm2"] = k.kac_n_mm2;
  out.summary["kae_n_mm"] = k.kae_n_mm;
  out.summary["rms_residual_n"] = fit->rms_residual_n;
  out.summary["max_residual_n"] = fit->max_residual_n;
  out.summary["cuts"] = cuts->size();
  std::string csv =
      "cut,measured_fx_n,measured_fy_n,measured_fz_n,predicted_fx_n,predicted_fy_n,"
      "predicted_fz_n,residual_fx_n,residual_fy_n,residual_fz_n\n";
  for (std::size_t i = 0; i < cuts->size(); ++i) {
    const Vec3 m = (*cuts)[i].mean_force_n, p = fit->predicted_n[i], r = fit->residual_n[i];
    char buf[320];
    std::snprintf(buf, sizeof buf, "%zu,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f\n", i + 1, m.x,
                  m.y, m.z, p.x, p.y, p.z, r.x, r.y, r.z);
    csv += buf;
  }
  out.csv_override = csv;
  out.report_files["residuals.csv"] = csv;
  return out;
}

const OperationRegistrar kRegistrar(Operation{
    "fit-coefficients",
    "identify cutting coefficients Ktc Kte Krc Kre Kac Kae from test-cut mean forces",
    "CSV of test cuts: spindle_rpm,feed_mm_min,axial_depth_mm,radial_depth_mm,fx_n,fy_n,fz_n"
    "[,mode]",
    true,
    false,
    {{"axial_step", ParamType::kNumber, 0.1, "axial resolution of the force model, mm"},
     {"angle_step", ParamType::kNumber, 1.0, "rotation step of the force model, degrees"}},
    run_fit});

}  // namespace
}  // namespace swarf::cli
