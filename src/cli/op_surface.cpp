// `swarf surface`: ball-end scanning or contour paths from the tri-slice model (seed 001).
#include <chrono>
#include <cmath>
#include <sstream>

#include "cli/operation.h"
#include "swarf/dropcut/dropcut.h"
#include "swarf/mesh/stl.h"
#include "swarf/toolpath/postprocess.h"
#include "swarf/trislice/envelope.h"
#include "swarf/trislice/surface_paths.h"

namespace swarf::cli {
namespace {

using nlohmann::json;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

std::string cl_csv(const std::vector<std::vector<Vec3>>& lines) {
  std::ostringstream os;
  os.precision(10);
  os << "line,x,y,z\n";
  for (std::size_t i = 0; i < lines.size(); ++i) {
    for (const Vec3& p : lines[i])
      os << i << ',' << p.x << ',' << p.y << ',' << p.z << '\n';
  }
  return os.str();
}

// A mesh with open edges (a relief surface, a broken export) has no inside: its slices
// are open chains, which the slicer closes by their chords, and the tri-slice top then floats
// above the surface or dips into it (OpenCAMLib's mount_rush.stl: up to 17 mm above and
// 0.28 mm below the exact drop, a gouge). Scanning such a mesh uses the exact drop-cutter on
// the same grid instead (every grid point, with the stock to leave as a larger ball); it is
// exact on any triangle soup. Roughing layers and contour paths need the solid: refused.
Result<OperationOutput> scan_open_mesh(const OperationInput& in, const Mesh& mesh,
                                       const MeshCheck& check, const ScanParams& sp,
                                       OperationOutput out) {
  const Context& ctx = in.ctx != nullptr ? *in.ctx : default_context();
  const Tool& tool = *in.tool;
  SWARF_RETURN_IF_ERROR(validate(sp));  // before the drop (scan_finishing_from_cl checks too)
  const double s = sp.stock_to_leave_mm;
  const auto t0 = std::chrono::steady_clock::now();
  auto dc = DropCutter::build(mesh, CutterShape{tool.radius() + s, tool.radius() + s});
  if (!dc.ok()) return dc.status().with_context(in.input_path);
  ClGrid grid;
  grid.region = dc->mesh_bounds().xy();
  grid.direction = sp.direction;
  grid.stepover_mm = sp.stepover_mm;
  grid.sampling_mm = sp.sampling_mm;
  // The larger ball's tip lies s below the real tool's tip.
  const double floor_z = dc->mesh_bounds().min.z;
  auto cl = drop_grid(*dc, grid, floor_z - s, ctx);
  if (!cl.ok()) return cl.status().with_context(in.input_path);
  const std::size_t per_line = grid.point_positions().size();
  std::vector<std::vector<Vec3>> lines;
  for (std::size_t start = 0; start < cl->size(); start += per_line) {
    lines.emplace_back(cl->begin() + static_cast<std::ptrdiff_t>(start),
                       cl->begin() + static_cast<std::ptrdiff_t>(start + per_line));
    for (Vec3& q : lines.back())
      q.z += s;
  }
  std::string csv = cl_csv(lines);
  if (sp.refine_steep && sp.adaptive)  // as the tri-slice scan (the CSV keeps the grid)
    for (auto& line : lines)
      line = refine_steep_stretches(line, sp.adaptive_tolerance_mm, [&](Vec2 xy) {
        return std::max(dc->drop_z(xy), floor_z - s) + s;
      });
  auto tp = scan_finishing_from_cl(
      std::move(lines), tool, sp, dc->mesh_bounds().max.z + s + 5.0,
      "drop-cutter scan finishing (open mesh)",
      [&](Vec2 xy) { return std::max(dc->drop_z(xy), floor_z - s) + s; }, ctx);
  if (!tp.ok()) return tp.status().with_context(in.input_path);
  out.summary["open_mesh"] = true;
  out.summary["open_edges"] = check.open_edges;
  out.summary["non_manifold_edges"] = check.non_manifold_edges;
  out.summary["cl_source"] = "exact drop-cutter (the mesh is not a closed solid)";
  out.summary["finishing_s"] = seconds_since(t0);
  out.summary["cl_points"] = cl->size();
  out.toolpaths.push_back(std::move(tp).value());
  out.csv_override = std::move(csv);
  return out;
}

Result<OperationOutput> run_surface(const OperationInput& in) {
  const json& p = in.params;
  const Context& ctx = in.ctx != nullptr ? *in.ctx : default_context();
  auto stl = read_stl(in.input_path);
  if (!stl.ok()) return stl.status();
  const Tool& tool = *in.tool;
  const std::string pattern = p["pattern"].get<std::string>();
  const std::string dir = p["direction"].get<std::string>();
  if (pattern != "scan" && pattern != "contour")
    return bad_parameter("--pattern must be scan or contour, not \"" + pattern + "\"");
  if (dir != "x" && dir != "y")
    return bad_parameter("--direction must be x or y, not \"" + dir + "\"");
  const double pitch = p["pitch"].get<double>();

  OperationOutput out;
  const MeshCheck check = check_mesh(stl->mesh);
  // Open edges mean no inside; non-manifold edges alone (solids touching along an edge)
  // slice as usual.
  const bool solid = check.open_edges == 0;
  if (!solid && (pattern == "contour" || p["rough_layers"].get<int>() > 0)) {
    return Status{Error::kBadInput,
                  in.input_path + ": the mesh is not a closed solid (" +
                      std::to_string(check.open_edges) + " open edges, " +
                      std::to_string(check.non_manifold_edges) +
                      " non-manifold edges): tri-slice " +
                      (pattern == "contour" ? "contour paths" : "roughing") +
                      " need its inside; repair it, or use --pattern scan without "
                      "--rough-layers (exact drop-cutter on open meshes)"};
  }
  const double feed = p["feed"].get<double>(), plunge = p["plunge_feed"].get<double>();
  ScanParams sp;
  sp.direction = dir == "x" ? Axis::kX : Axis::kY;
  sp.zigzag = p["zigzag"].get<bool>();
  sp.stepover_mm = p["stepover"].get<double>();
  sp.sampling_mm = p["sampling"].get<double>();
  sp.stock_to_leave_mm = p["stock_to_leave"].get<double>();
  sp.tolerance_mm = p["tolerance"].get<double>();
  // Adaptive sampling along the lines unless --uniform (the CSV then holds the full grid).
  sp.adaptive = !p["uniform"].get<bool>();
  sp.adaptive_max_step_mm = p["max_step"].get<double>();
  sp.adaptive_tolerance_mm = p["adaptive_tolerance"].get<double>();
  sp.adaptive_model_fraction = p["adaptive_model_fraction"].get<double>();
  sp.feed_mm_min = feed;
  sp.plunge_feed_mm_min = plunge;
  // The mesh's vertices and fold edges are exact contacts too: the slices pass a convex corner
  // up to a pitch away and can miss a grazed fold altogether (docs/trislice.md). Steep
  // stretches are refined below the lattice, so no move runs through a wall's top.
  sp.vertex_mesh = &stl->mesh;
  sp.refine_steep = true;
  if (!solid) return scan_open_mesh(in, stl->mesh, check, sp, std::move(out));
  const auto t0 = std::chrono::steady_clock::now();
  // Scanning reads all three families (the xy one holds steep walls), waterlines only z.
  const std::array<bool, 3> families = pattern == "scan" ? std::array<bool, 3>{true, true, true}
                                                         : std::array<bool, 3>{false, false, true};
  auto model = build_trislice_families(stl->mesh, pitch, families, {}, ctx);
  if (!model.ok()) return model.status().with_context(in.input_path);
  out.summary["model_s"] = seconds_since(t0);
  out.summary["pitch_mm"] = pitch;
  std::size_t slices = 0;
  for (const SliceFamily& f : model->families)
    slices += f.size();
  out.summary["slices"] = slices;

  if (pattern == "contour") {
    ContourParams cp;
    cp.stepdown_mm = p["stepdown"].get<double>();
    cp.stock_to_leave_mm = p["stock_to_leave"].get<double>();
    cp.radial_passes = std::max(1, p["radial_passes"].get<int>());
    cp.radial_step_mm = p["stepover"].get<double>();
    cp.feed_mm_min = feed;
    cp.plunge_feed_mm_min = plunge;
    // Steps and peaks between two levels count exactly (first-order error otherwise).
    cp.critical_mesh = &stl->mesh;
    const auto t1 = std::chrono::steady_clock::now();
    auto tp = contour_paths(*model, tool, cp, ctx);
    if (!tp.ok()) return tp.status().with_context(in.input_path);
    out.summary["contour_s"] = seconds_since(t1);
    // Waterlines are planar: arcs where they fit.
    out.toolpaths.push_back(fit_arcs(simplify(*tp, p["tolerance"].get<double>())));
    return out;
  }

  if (sp.adaptive) {
    out.summary["adaptive_tolerance_mm"] =
        effective_adaptive_tolerance_mm(sp, model->pitch_mm, tool.radius() + sp.stock_to_leave_mm);
  }
  const auto t1 = std::chrono::steady_clock::now();
  const TriSliceTop top = TriSliceTop::build(*model, 0.0, 1, ctx.threads);  // bins from the pitch
  const int layers = p["rough_layers"].get<int>();
  if (layers > 0) {
    RoughingParams rp;
    rp.layers = layers;
    rp.stepdown_mm = p["stepdown"].get<double>();
    rp.stepover_mm = p["rough_stepover"].get<double>();
    rp.margin_mm = p["margin"].get<double>();
    if (!p["stock_top"].is_null()) rp.stock_top_mm = p["stock_top"].get<double>();
    auto rough = scan_roughing(*model, top, tool, sp, rp, ctx);
    if (!rough.ok()) return rough.status().with_context(in.input_path);
    out.summary["roughing_s"] = seconds_since(t1);
    out.toolpaths.push_back(std::move(rough).value());
  }
  const auto t2 = std::chrono::steady_clock::now();
  auto lines = scan_cl_lines(top, model->bounds, tool.radius(), sp.stock_to_leave_mm, sp, ctx);
  if (!lines.ok()) return lines.status().with_context(in.input_path);
  std::string csv = cl_csv(*lines);
  std::size_t n = 0;
  for (const auto& l : *lines)
    n += l.size();
  auto fin = scan_finishing_from_lines(*model, top, tool, sp, std::move(lines).value(), ctx);
  if (!fin.ok()) return fin.status().with_context(in.input_path);
  out.summary["finishing_s"] = seconds_since(t2);
  out.summary["cl_points"] = n;
  out.toolpaths.push_back(std::move(fin).value());
  // The CSV holds the finishing CL points (tool tips) before simplification, for comparison
  // with a drop-cutter on the same grid (with --uniform: every grid point).
  out.csv_override = std::move(csv);
  return out;
}

const OperationRegistrar kRegister{Operation{
    "surface",
    "ball-end scanning or contour paths from the tri-slice model (seed 001)",
    "PART.stl",
    true,
    true,
    {
        {"pattern", ParamType::kString, "scan", "scan (raster) or contour (waterline)"},
        {"direction", ParamType::kString, "x", "scan lines along x or y"},
        {"zigzag", ParamType::kBool, false, "alternate line directions (default one-way)"},
        {"stepover", ParamType::kNumber, 0.25, "distance between scan lines / contour rings, mm"},
        {"sampling", ParamType::kNumber, 0.1, "CL point spacing along a scan line, mm"},
        {"uniform", ParamType::kBool, false,
         "evaluate every sampling point (default: adaptive, refined where the path bends)"},
        {"max_step", ParamType::kNumber, 1.6, "adaptive: first-pass CL spacing, mm"},
        {"adaptive_tolerance", ParamType::kNumber, 0.001,
         "adaptive: refine while a midpoint leaves the chord by more, mm"},
        {"adaptive_model_fraction", ParamType::kNumber, 1.0,
         "adaptive: raise the tolerance to this fraction of the model's error bound at the pitch "
         "(3 sqrt(3) pitch^2 / (16 r)); 0 = off"},
        {"pitch", ParamType::kNumber, 0.05, "slice pitch of the tri-slice model, mm"},
        {"stock_to_leave", ParamType::kNumber, 0.0, "material left on the part, mm"},
        {"rough_layers", ParamType::kInteger, 0, "roughing layers before finishing (Table 1: 5)"},
        {"stepdown", ParamType::kNumber, 2.0, "roughing axial depth / contour level spacing, mm"},
        {"rough_stepover", ParamType::kNumber, 2.0, "roughing radial depth of cut, mm"},
        {"margin", ParamType::kNumber, 0.1, "roughing margin left for finishing, mm"},
        {"stock_top", ParamType::kNumber, nullptr, "stock top for roughing, mm (default part top)",
         true},
        {"radial_passes", ParamType::kInteger, 1, "contour rings per level"},
        {"tolerance", ParamType::kNumber, 0.001, "path simplification tolerance, mm"},
        {"feed", ParamType::kNumber, 1000.0, "cutting feed, mm/min"},
        {"plunge_feed", ParamType::kNumber, 300.0, "plunge feed, mm/min"},
    },
    run_surface}};

}  // namespace
}  // namespace swarf::cli
