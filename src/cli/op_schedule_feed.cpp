// swarf schedule-feed PROGRAM.nc --stock ... --tool ball:8 --max-force 300 -o faster.nc
// Rescales the feed of every move so that the predicted peak cutting force stays under a
// limit (beyond seed 001): slower where the tool is overloaded, faster where it is idle.
#include "cli/op_simulate.h"

namespace swarf::cli {
namespace {

using nlohmann::json;

std::vector<Param> schedule_params() {
  std::vector<Param> p = simulate_params();
  p.push_back({"max_force", ParamType::kNumber, 300.0, "largest peak cutting force allowed, N"});
  p.push_back({"max_increase", ParamType::kNumber, 2.0,
               "largest factor a feed may be raised by (1: only slow down)"});
  p.push_back({"min_feed", ParamType::kNumber, 1.0, "lowest feed written, mm/min"});
  p.push_back({"max_feed", ParamType::kNumber, 0.0, "highest raised feed, mm/min (0: no cap)"});
  p.push_back({"max_chip", ParamType::kNumber, 0.0,
               "chip-load limit, mm per tooth (0: none): no feed above it"});
  p.push_back({"verify", ParamType::kBool, true,
               "simulate the new program again and report its predicted peak"});
  return p;
}

Result<OperationOutput> run_schedule(const OperationInput& in) {
  Result<SimulationSetup> setup = prepare_simulation(in);
  if (!setup.ok()) return setup.status();
  SimulationSetup& s = *setup;
  const Context& ctx = in.ctx != nullptr ? *in.ctx : default_context();
  sim::SimulationOptions opt = s.options;
  opt.sample_stride = 1 << 20;  // the waveform is not needed here, only per-move peaks
  sim::FeedScheduleOptions fo;
  fo.max_force_n = in.params["max_force"].get<double>();
  fo.max_increase = in.params["max_increase"].get<double>();
  fo.min_feed_mm_min = in.params["min_feed"].get<double>();
  fo.max_feed_mm_min = in.params["max_feed"].get<double>();
  fo.max_chip_mm = in.params["max_chip"].get<double>();
  fo.spindle_rpm = s.options.spindle_rpm > 0.0 ? s.options.spindle_rpm : s.program.spindle_rpm;
  fo.flutes = s.tool.flutes;
  if (!(fo.max_force_n > 0.0)) return bad_parameter("--max-force must be positive");
  if (!(fo.max_increase >= 1.0)) return bad_parameter("--max-increase must be at least 1");
  opt.force_limit_n = fo.max_force_n;
  // Keep a pristine copy of the stock for the verification run.
  sim::Stock fresh = s.stock;
  Result<sim::SimulationResult> r =
      sim::simulate(s.stock, s.program, s.tool, s.coefficients, opt, ctx);
  if (!r.ok()) return r.status().with_context(in.input_path);
  sim::FeedSchedule fs = sim::schedule_feed(s.program, *r, fo);
  OperationOutput out;
  out.summary["max_force_n"] = fo.max_force_n;
  out.summary["peak_force_before_n"] = r->peak_force_n;
  out.summary["time_above_limit_before_s"] = r->time_above_limit_s;
  out.summary["feed_time_before_s"] = fs.time_before_s;
  out.summary["feed_time_after_s"] = fs.time_after_s;
  out.summary["time_gained_s"] = fs.time_before_s - fs.time_after_s;
  out.summary["moves_slowed"] = fs.slowed;
  out.summary["moves_raised"] = fs.raised;
  if (in.params["verify"].get<bool>()) {
    Result<sim::SimulationResult> v =
        sim::simulate(fresh, fs.path, s.tool, s.coefficients, opt, ctx);
    if (!v.ok()) return v.status().with_context(in.input_path);
    out.summary["peak_force_after_n"] = v->peak_force_n;
    out.summary["time_above_limit_after_s"] = v->time_above_limit_s;
  }
  fs.path.name = s.program.name.empty() ? "feed-scheduled" : s.program.name + " (feed-scheduled)";
  out.toolpaths.push_back(std::move(fs.path));
  return out;
}

const OperationRegistrar kRegistrar(Operation{
    "schedule-feed", "rescale feeds so the predicted peak cutting force stays under --max-force",
    "G-code program", true, true, schedule_params(), run_schedule});

}  // namespace
}  // namespace swarf::cli
