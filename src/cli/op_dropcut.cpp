// `swarf dropcut`: the exact drop-cutter as a raster strategy, and the CL reference.
#include <chrono>
#include <limits>
#include <sstream>

#include "cli/operation.h"
#include "swarf/dropcut/dropcut.h"
#include "swarf/mesh/stl.h"
#include "swarf/toolpath/postprocess.h"

namespace swarf::cli {
namespace {

using nlohmann::json;

Result<OperationOutput> run_dropcut(const OperationInput& in) {
  const json& p = in.params;
  const Context& ctx = in.ctx != nullptr ? *in.ctx : default_context();
  auto stl = read_stl(in.input_path);
  if (!stl.ok()) return stl.status();
  const Tool& tool = *in.tool;
  const std::string dir = p["direction"].get<std::string>();
  if (dir != "x" && dir != "y")
    return bad_parameter("--direction must be x or y, not \"" + dir + "\"");
  const auto t0 = std::chrono::steady_clock::now();
  auto dc = DropCutter::build(stl->mesh, tool);
  if (!dc.ok()) return dc.status().with_context(in.input_path);
  ClGrid grid;
  grid.region = dc->mesh_bounds().xy();
  grid.direction = dir == "x" ? Axis::kX : Axis::kY;
  grid.stepover_mm = p["stepover"].get<double>();
  grid.sampling_mm = p["sampling"].get<double>();
  const double floor_z = dc->mesh_bounds().min.z;
  auto cl = drop_grid(*dc, grid, floor_z, ctx);
  if (!cl.ok()) return cl.status().with_context(in.input_path);
  OperationOutput out;
  out.summary["cl_points"] = cl->size();
  out.summary["dropcut_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.summary["index_entries"] = dc->index_entries();

  const std::size_t per_line = grid.point_positions().size();
  std::ostringstream csv;
  csv.precision(10);
  csv << "line,x,y,z\n";
  for (std::size_t k = 0; k < cl->size(); ++k)
    csv << k / per_line << ',' << (*cl)[k].x << ',' << (*cl)[k].y << ',' << (*cl)[k].z << '\n';
  out.csv_override = csv.str();

  // One-way raster: rapid over each line start, plunge, feed along, retract. The plunge is
  // safe: a CL point is the lowest collision-free height over its xy.
  Toolpath tp;
  tp.name = "drop-cutter raster";
  tp.tool_number = tool.number;
  tp.tool_description = tool.description();
  tp.tool_diameter_mm = tool.diameter_mm;
  tp.clearance_z_mm = dc->mesh_bounds().max.z + 5.0;
  const double feed = p["feed"].get<double>(), plunge = p["plunge_feed"].get<double>();
  for (std::size_t start = 0; start < cl->size(); start += per_line) {
    std::vector<Vec3> line(cl->begin() + static_cast<long>(start),
                           cl->begin() + static_cast<long>(start + per_line));
    // Steep stretches (a jump beside a wall) refined below the sampling with exact drops,
    // so no move runs through the wall's top; the CSV above keeps the grid.
    std::size_t hint = std::numeric_limits<std::size_t>::max();
    line = refine_steep_stretches(line, std::max(p["tolerance"].get<double>(), 1e-4), [&](Vec2 xy) {
      const DropResult r = dc->drop(xy, hint);
      if (r.hit()) hint = r.triangle;
      return r.hit() ? std::max(r.tip_z, floor_z) : floor_z;
    });
    line = simplify_polyline(line, p["tolerance"].get<double>());
    tp.rapid_to({line.front().x, line.front().y, tp.clearance_z_mm});
    tp.plunge_to(line.front().z, plunge);
    for (std::size_t k = 1; k < line.size(); ++k)
      tp.feed_to(line[k], feed);
    tp.retract();
  }
  out.toolpaths.push_back(std::move(tp));
  return out;
}

const OperationRegistrar kRegister{
    Operation{"dropcut",
              "exact drop-cutter raster over a mesh (ball, flat or bull-nose): the CL reference",
              "PART.stl",
              true,
              true,
              {
                  {"direction", ParamType::kString, "x", "lines along x or y"},
                  {"stepover", ParamType::kNumber, 0.25, "distance between lines, mm"},
                  {"sampling", ParamType::kNumber, 0.05, "CL point spacing along a line, mm"},
                  {"tolerance", ParamType::kNumber, 0.001, "path simplification tolerance, mm"},
                  {"feed", ParamType::kNumber, 1000.0, "cutting feed, mm/min"},
                  {"plunge_feed", ParamType::kNumber, 300.0, "plunge feed, mm/min"},
              },
              run_dropcut}};

}  // namespace
}  // namespace swarf::cli
