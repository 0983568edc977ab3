// `swarf rest`: regions a ball of the tool's radius cannot reach (seed 001 section 3.2).
#include <chrono>
#include <sstream>

#include "cli/operation.h"
#include "swarf/mesh/stl.h"
#include "swarf/report/image.h"
#include "swarf/trislice/rest.h"

namespace swarf::cli {
namespace {

using nlohmann::json;

Result<OperationOutput> run_rest(const OperationInput& in) {
  const json& p = in.params;
  const Context& ctx = in.ctx != nullptr ? *in.ctx : default_context();
  auto stl = read_stl(in.input_path);
  if (!stl.ok()) return stl.status();
  const Tool& tool = *in.tool;
  const double pitch = p["pitch"].get<double>();
  // Inflate-then-shrink compares solids: an open surface has no inside to compare.
  const MeshCheck check = check_mesh(stl->mesh);
  if (check.open_edges > 0) {
    return Status{Error::kBadInput, in.input_path + ": the mesh is not a closed solid (" +
                                        std::to_string(check.open_edges) + " open edges, " +
                                        std::to_string(check.non_manifold_edges) +
                                        " non-manifold edges): rest regions need its inside"};
  }
  const auto t0 = std::chrono::steady_clock::now();
  auto model = build_trislice(stl->mesh, pitch, {}, ctx);
  if (!model.ok()) return model.status().with_context(in.input_path);
  RestOptions o;
  // A ball reaches as a ball; a flat or bull-nose end mill is judged by its corner radius
  // only where that is the tighter constraint, which this analysis does not model: refuse.
  if (tool.kind != ToolKind::kBall)
    return bad_parameter("rest regions are computed for a ball end mill (seed 001 section 3.2)");
  o.tool_radius_mm = tool.radius();
  o.min_thickness_mm = p["min_thickness"].get<double>();
  o.convolution.arc_tolerance_mm = p["arc_tolerance"].get<double>();
  auto rest = unmachinable_regions(*model, o, ctx);
  if (!rest.ok()) return rest.status().with_context(in.input_path);
  const ThicknessMap map = thickness_map(*rest, pitch);
  OperationOutput out;
  out.summary["rest_s"] =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  out.summary["pitch_mm"] = pitch;
  out.summary["max_thickness_mm"] = map.max();
  std::size_t cells = 0;
  std::ostringstream csv;
  csv.precision(8);
  csv << "x,y,thickness_mm\n";
  for (int j = 0; j < map.ny; ++j) {
    for (int i = 0; i < map.nx; ++i) {
      const double t = map.mm[static_cast<std::size_t>(j) * static_cast<std::size_t>(map.nx) +
                              static_cast<std::size_t>(i)];
      if (t < o.min_thickness_mm || t <= 0.0) continue;
      ++cells;
      csv << map.origin.x + (i + 0.5) * map.cell_mm << ',' << map.origin.y + (j + 0.5) * map.cell_mm
          << ',' << t << '\n';
    }
  }
  out.summary["residue_area_mm2"] = static_cast<double>(cells) * map.cell_mm * map.cell_mm;
  out.csv_override = csv.str();
  out.report_files["rest_map.png"] = png_bytes(thickness_image(map, o.min_thickness_mm));
  out.report_files["rest_points.ply"] = residue_points_ply(*rest, pitch);
  return out;
}

const OperationRegistrar kRegister{Operation{
    "rest",
    "unmachinable regions for a ball end mill: map (PNG), points (PLY), CSV",
    "PART.stl",
    true,
    false,
    {
        {"pitch", ParamType::kNumber, 0.1, "slice pitch of the tri-slice model, mm"},
        {"min_thickness", ParamType::kNumber, 0.02, "residues thinner than this are ignored, mm"},
        {"arc_tolerance", ParamType::kNumber, 0.005, "2D offset arc tolerance, mm"},
    },
    run_rest}};

}  // namespace
}  // namespace swarf::cli
