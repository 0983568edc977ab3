// swarf simulate PROGRAM.nc --stock box:XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX|STOCK.stl --tool ball:8
//   --flutes 2 --helix 30 --rpm 3600 --coefficients K.json --pitch 0.1 --forces forces.csv
//   --report out/
// Material removal and cutting forces of a G-code program (seed 001 section 3.3).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "cli/op_simulate.h"
#include "swarf/core/io.h"
#include "swarf/gcode/gcode.h"
#include "swarf/mesh/stl.h"
#include "swarf/sim/coefficients.h"
#include "swarf/sim/simulate.h"
#include "swarf/toolpath/metrics.h"

namespace swarf::cli {

using nlohmann::json;

std::vector<Param> simulate_params() {
  return {
      {"stock", ParamType::kString, nullptr,
       "stock: box:XMIN,YMIN,ZMIN,XMAX,YMAX,ZMAX (mm) or a closed STL file"},
      {"rpm", ParamType::kNumber, 0.0, "spindle speed, rpm (0: the program's S word)"},
      {"coefficients", ParamType::kString, "",
       "cutting coefficients JSON from fit-coefficients (empty: the paper's Table 4)"},
      {"pitch", ParamType::kNumber, 0.1, "slice pitch of the stock, mm"},
      {"axial_step", ParamType::kNumber, 0.1, "axial resolution of the cutting edge, mm"},
      {"angle_step", ParamType::kNumber, 1.0, "rotation step, degrees"},
      {"step", ParamType::kNumber, 0.0, "tool advance per engagement evaluation, mm (0: pitch)"},
      {"batch", ParamType::kNumber, 3.0, "tool advance per stock update, mm"},
      {"batch_turn", ParamType::kNumber, 45.0,
       "a stock update also follows a turn of the path by this much, degrees"},
      {"engagement", ParamType::kString, "majority",
       "how the three slice families vote on an edge point: majority or any (the paper)"},
      {"force_limit", ParamType::kNumber, 0.0,
       "force limit for the summary's time above it, N (0: none)"},
      {"sample_stride", ParamType::kInteger, 0,
       "keep every n-th rotation step in the waveform (0: every step up to 2 million samples, "
       "then evenly thinned; peaks and means always use every step)"},
      {"rapid", ParamType::kNumber, 5000.0, "rapid traverse rate, mm/min"},
      {"forces", ParamType::kString, "", "write the force waveform CSV here"},
      {"height_map_cell", ParamType::kNumber, 0.25, "cell of the height map and picture, mm"},
      {"stock_stl", ParamType::kBool, false,
       "also write the machined stock as report/stock.stl (from the height map)"},
  };
}

Result<SimulationSetup> prepare_simulation(const OperationInput& in) {
  const json& p = in.params;

  sim::CuttingCoefficients k;
  const std::string kpath = p["coefficients"].get<std::string>();
  if (!kpath.empty()) {
    Result<std::string> text = read_file(kpath);
    if (!text.ok()) return text.status();
    Result<sim::CuttingCoefficients> kk = sim::parse_coefficients_json(*text, kpath);
    if (!kk.ok()) return kk.status();
    k = *kk;
  }
  sim::SimulationOptions o;
  const double pitch = p["pitch"].get<double>();
  o.spindle_rpm = p["rpm"].get<double>();
  o.force.axial_step_mm = p["axial_step"].get<double>();
  o.force.angle_step_deg = p["angle_step"].get<double>();
  o.step_mm = p["step"].get<double>() > 0.0 ? p["step"].get<double>() : pitch;
  o.batch_mm = std::max(o.step_mm, p["batch"].get<double>());
  o.batch_turn_deg = p["batch_turn"].get<double>();
  const std::string rule = p["engagement"].get<std::string>();
  if (rule == "majority") {
    o.engagement = sim::EngagementRule::kMajority;
  } else if (rule == "any") {
    o.engagement = sim::EngagementRule::kAny;
  } else {
    return bad_parameter("--engagement must be majority or any, not \"" + rule + "\"");
  }
  o.force_limit_n = p["force_limit"].get<double>();
  o.sample_stride = p["sample_stride"].get<int>();
  o.rapid_mm_min = p["rapid"].get<double>();
  const Context& ctx = in.ctx != nullptr ? *in.ctx : default_context();
  Result<sim::Stock> stock = sim::Stock::from_spec(p["stock"].get<std::string>(), pitch, ctx);
  if (!stock.ok()) return stock.status();
  // The machine starts 10 mm above the stock at the origin, so a program whose first block
  // positions only X and Y does not drag the tool through the stock.
  GcodeReadOptions ro;
  ro.start = {0.0, 0.0, stock->bounds().max.z + 10.0};
  Result<Toolpath> program = read_gcode(in.input_path, ro);
  if (!program.ok()) return program.status();
  if (o.sample_stride == 0) {
    // Keep the waveform in memory and on disk bounded: about 2 million rows (~80 MB CSV).
    const double rpm = o.spindle_rpm > 0.0 ? o.spindle_rpm : program->spindle_rpm;
    const double steps =
        compute_metrics(*program).machining_time_s * rpm / 60.0 * 360.0 / o.force.angle_step_deg;
    o.sample_stride = static_cast<int>(std::clamp(std::ceil(steps / 2e6), 1.0, 1e9));
  }
  return SimulationSetup{std::move(program).value(), *in.tool, std::move(stock).value(), k, o};
}

json simulation_summary(const sim::SimulationResult& r) {
  json s;
  s["peak_force_n"] = r.peak_force_n;
  s["mean_force_n"] = r.mean_force_n;
  s["time_above_limit_s"] = r.time_above_limit_s;
  s["removed_mm3"] = r.removed_mm3;
  s["simulated_time_s"] = r.machining_time_s;
  s["cutting_time_s"] = r.cutting_time_s;
  s["collisions"] = r.collisions.size();
  s["peak_fx_n"] = r.peak_abs_n.x;
  s["peak_fy_n"] = r.peak_abs_n.y;
  s["peak_fz_n"] = r.peak_abs_n.z;
  s["removed_by_family_mm3"] = {r.removed_by_family_mm3[0], r.removed_by_family_mm3[1],
                                r.removed_by_family_mm3[2]};
  s["collision_list"] = r.collisions;
  return s;
}

namespace {

// write_png writes a file; the framework wants bytes. Encode into a scratch file and read it
// back so that the report is still written atomically with the rest.
Result<std::string> png_bytes(const sim::HeightMap& map) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path dir = fs::temp_directory_path(ec);
  if (ec) return Status{Error::kIo, "no temporary folder for the stock picture"};
  const fs::path tmp =
      dir / ("swarf-stock-" + std::to_string(reinterpret_cast<std::uintptr_t>(&map)) + ".png");
  SWARF_RETURN_IF_ERROR(sim::write_height_map_png(tmp.string(), map, 2));
  Result<std::string> bytes = read_file(tmp.string());
  fs::remove(tmp, ec);
  return bytes;
}

Result<OperationOutput> run_simulate(const OperationInput& in) {
  Result<SimulationSetup> setup = prepare_simulation(in);
  if (!setup.ok()) return setup.status();
  SimulationSetup& s = *setup;
  const Context& ctx = in.ctx != nullptr ? *in.ctx : default_context();
  Result<sim::SimulationResult> r =
      sim::simulate(s.stock, s.program, s.tool, s.coefficients, s.options, ctx);
  if (!r.ok()) return r.status().with_context(in.input_path);
  OperationOutput out;
  out.summary = simulation_summary(*r);
  const std::string forces = sim::forces_csv(*r);
  const std::string fpath = in.params["forces"].get<std::string>();
  if (!fpath.empty()) SWARF_RETURN_IF_ERROR(write_file_atomic(fpath, forces));
  out.csv_override = forces;
  out.toolpaths.push_back(r->annotated);
  out.report_files["forces.svg"] = sim::forces_svg(*r, "Cutting forces: " + in.input_path);
  out.report_files["moves.csv"] = sim::moves_csv(*r);
  const double cell = in.params["height_map_cell"].get<double>();
  const Vec3 size = s.stock.bounds().size();
  if (!(cell > 0.0) || size.x / cell * (size.y / cell) > 1e8) {
    return bad_parameter("--height-map-cell " + std::to_string(cell) +
                         " mm must be positive and give at most 1e8 cells over the stock");
  }
  const sim::HeightMap hm = s.stock.height_map(cell);
  out.report_files["stock_height.csv"] = sim::height_map_csv(hm);
  Result<std::string> png = png_bytes(hm);
  if (!png.ok()) return png.status();
  out.report_files["stock_top.png"] = std::move(png).value();
  if (in.params["stock_stl"].get<bool>()) {
    out.report_files["stock.stl"] =
        stl_binary_bytes(sim::height_map_mesh(hm, s.stock.bounds().min.z));
  }
  return out;
}

const OperationRegistrar kRegistrar(Operation{
    "simulate", "material removal and cutting forces of a G-code program on a tri-slice stock",
    "G-code program", true, false, simulate_params(), run_simulate});

}  // namespace
}  // namespace swarf::cli
