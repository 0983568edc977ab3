// `swarf contour`: contour-parallel pocket clearing (swarf/pocket/contour_parallel.h), the
// baseline for the adaptive pocket.
#include "cli/operation.h"
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
  cp.plunge_feed_mm_min = p.at("plunge_feed").get<double>();
  cp.ramp_angle_deg = p.at("ramp_angle").get<double>();
  auto r = contour_parallel_pocket(*pocket, *in.tool, cp, in.ctx ? *in.ctx : default_context());
  if (!r) return r.status();
  OperationOutput out;
  out.summary["rings_per_layer"] = r->rings;
  out.summary["retracts_per_layer"] = r->retracts_per_layer;
  out.toolpaths.push_back(std::move(r->toolpath));
  out.plot_background = pocket->region;
  return out;
}

const OperationRegistrar kRegistrar(Operation{
    "contour",
    "contour-parallel pocket clearing (offset rings, helix entry)",
    "pocket outline: .json {outer, islands}, .svg or .dxf (mm)",
    true,
    true,
    {
        number_param("stepover", 0.0,
                     "radial stepover between rings, mm (0 = 10 % of the diameter)"),
        Param{"outside_in", ParamType::kBool, false, "cut from the wall inwards", false},
        Param{"conventional", ParamType::kBool, false, "conventional instead of climb milling",
              false},
        number_param("depth", 6.0, "pocket depth below the top, mm"),
        number_param("stepdown", 0.0, "depth per layer, mm (0 = whole depth)"),
        number_param("floor_stock", 0.0, "stock left on the floor, mm"),
        number_param("wall_stock", 0.0, "stock left on walls and islands, mm"),
        number_param("top_z", 0.0, "top of the stock, mm"),
        number_param("clearance_z", 5.0, "rapid plane, mm"),
        number_param("feed", 1000.0, "cutting feed, mm/min"),
        number_param("plunge_feed", 300.0, "helix feed, mm/min"),
        number_param("ramp_angle", 3.0, "helix descent angle, degrees"),
    },
    run});

}  // namespace
}  // namespace swarf::cli
