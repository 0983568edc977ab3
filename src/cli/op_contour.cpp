// `swarf contour`: contour-parallel pocket clearing (swarf/pocket/contour_parallel.h), the
// baseline for the adaptive pocket.
#include "cli/operation.h"
#include "cli/pocket_params.h"
#include "swarf/pocket/contour_parallel.h"
#include "swarf/toolpath/metrics.h"

namespace swarf::cli {
namespace {

using nlohmann::json;

Result<OperationOutput> run(const OperationInput& in) {
  const json& p = in.params;
  auto pocket = read_pocket(in.input_path);
  if (!pocket) return pocket.status();
  ContourParallelParams cp;
  cp.stepover_mm = p.at("stepover").get<double>();
  cp.inside_out = !p.at("outside_in").get<bool>();
  cp.climb = !p.at("conventional").get<bool>();
  cp.depth_mm = p.at("depth").get<double>();
  cp.stepdown_mm = p.at("stepdown").get<double>();
  cp.floor_stock_mm = p.at("floor_stock").get<double>();
  cp.wall_stock_mm = p.at("wall_stock").get<double>();
  cp.top_z_mm = p.at("top_z").get<double>();
  cp.clearance_z_mm = p.at("clearance_z").get<double>();
  cp.feed_mm_min = p.at("feed").get<double>();
  cp.ramp_feed_mm_min = p.at("ramp_feed").get<double>();
  cp.ramp_angle_deg = p.at("ramp_angle").get<double>();
  auto r = contour_parallel_pocket(*pocket, *in.tool, cp, in.ctx ? *in.ctx : default_context());
  if (!r) return r.status();
  OperationOutput out;
  out.notes = pocket->notes;
  out.summary["rings_per_layer"] = r->rings;
  out.summary["retracts_per_layer"] = r->retracts_per_layer;
  out.toolpaths.push_back(std::move(r->toolpath));
  out.plot_background = pocket->region;
  return out;
}

const OperationRegistrar kRegistrar(Operation{
    "contour", "contour-parallel pocket clearing (offset rings, helix entry)",
    "pocket outline: .json {outer, islands}, .svg or .dxf (mm)", true, true,
    with_pocket_layer_params(
        {
            number_param("stepover", 0.0,
                         "radial stepover between rings, mm (0 = 10 % of the diameter)"),
            Param{"outside_in", ParamType::kBool, false, "cut from the wall inwards", false},
        },
        "helix and ramp", {}),
    run});

}  // namespace
}  // namespace swarf::cli
