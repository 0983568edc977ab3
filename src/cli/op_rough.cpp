// swarf rough: voxel zig-zag roughing with region sequencing (seed 003).
#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include "cli/operation.h"
#include "swarf/mesh/stl.h"
#include "swarf/voxel/rough.h"

namespace swarf::cli {
namespace {

nlohmann::json metrics_json(const RoughMetrics& m) {
  return {{"lift_offs", m.lift_offs},
          {"air_length_mm", m.air_length_mm},
          {"cutting_length_mm", m.cutting_length_mm},
          {"total_length_mm", m.total_length_mm},
          {"regions", m.regions},
          {"layers", m.layers},
          {"machinable_cells", m.machinable_cells}};
}

Result<OperationOutput> run_rough(const OperationInput& in) {
  const nlohmann::json& p = in.params;
  if (!in.tool) return bad_parameter("rough needs a tool (--tool flat:10)");
  if (in.tool->kind != ToolKind::kFlat) {
    return bad_parameter("rough: the voxel model assumes a flat end mill; got " +
                         in.tool->description());
  }
  auto stl = read_stl(in.input_path);
  if (!stl.ok()) return stl.status();

  RoughParams rp;
  rp.tool_diameter_mm = in.tool->diameter_mm;
  // Seed 003 section 3.1 steps over 6.6 mm with its ø10 mm cutter: 66 % of the diameter,
  // which is the default for any cutter (a fixed 6.6 mm would refuse every tool under it).
  rp.stepover_mm =
      p["stepover"].is_null() ? 0.66 * in.tool->diameter_mm : p["stepover"].get<double>();
  rp.stepdown_mm = p["stepdown"].get<double>();
  rp.stock_to_leave_mm = p["stock_to_leave"].get<double>();
  rp.margin_mm = p["margin"].get<double>();
  rp.top_margin_mm = p["top_margin"].get<double>();
  rp.clearance_mm = p["clearance"].get<double>();
  rp.feed_mm_min = p["feed"].get<double>();
  rp.plunge_feed_mm_min = p["plunge_feed"].get<double>();
  rp.lift_penalty_mm = p["lift_penalty"].get<double>();
  rp.repair_open_mesh = p["repair"].get<bool>();
  rp.ga.seed = static_cast<std::uint64_t>(p["seed"].get<long long>());
  rp.ga.population = static_cast<int>(p["population"].get<long long>());
  rp.ga.max_generations = static_cast<int>(p["generations"].get<long long>());
  auto seq = parse_rough_sequence(p["sequence"].get<std::string>());
  if (!seq.ok()) return seq.status();
  rp.sequence = *seq;
  const std::string offset = p["offset"].get<std::string>();
  if (offset == "disk") {
    rp.offset = OffsetRule::kDisk;
  } else if (offset == "paper") {
    rp.offset = OffsetRule::kPaperSquare;
  } else {
    return bad_parameter("--offset: '" + offset + "' is not disk or paper");
  }
  if (!p["stock"].is_null()) {
    const std::string spec = p["stock"].get<std::string>();
    if (spec.rfind("box:", 0) == 0) {
      // "box:x0,y0,z0,x1,y1,z1", mm.
      double v[6];
      char tail = 0;
      if (std::sscanf(spec.c_str() + 4, "%lf,%lf,%lf,%lf,%lf,%lf%c", &v[0], &v[1], &v[2], &v[3],
                      &v[4], &v[5], &tail) != 6 ||
          !(v[0] < v[3] && v[1] < v[4] && v[2] < v[5])) {
        return bad_parameter("--stock: '" + spec + "' is not box:x0,y0,z0,x1,y1,z1 with x0 < x1, " +
                             "y0 < y1, z0 < z1");
      }
      rp.stock = Box3{{v[0], v[1], v[2]}, {v[3], v[4], v[5]}};
    } else {
      // A stock STL: its bounding box is the stock (the voxel model machines box stock).
      auto stock = read_stl(spec);
      if (!stock.ok()) return stock.status();
      rp.stock = bounds(stock->mesh);
    }
  }
  std::vector<double> angles;
  for (const auto& a : p["rotate"])
    angles.push_back(a.get<double>());
  if (angles.empty()) angles.push_back(0.0);

  const Context& ctx = in.ctx != nullptr ? *in.ctx : default_context();
  auto study = rough_orientations(stl->mesh, rp, angles, ctx);
  if (!study.ok()) return study.status().with_context(in.input_path);
  RoughResult& best = study->best_result;

  OperationOutput out;
  Toolpath tp = std::move(best.toolpath);
  tp.tool_number = in.tool->number;
  tp.tool_description = in.tool->description();
  out.toolpaths.push_back(std::move(tp));

  nlohmann::json& s = out.summary;
  s = metrics_json(best.metrics);
  s["sequence"] = std::string(rough_sequence_name(rp.sequence));
  s["offset"] = offset;
  s["zigzag_angle_deg"] = best.rotation_deg;
  s["timings_s"] = {{"voxelize", best.timings.voxelize_s},
                    {"preprocess", best.timings.preprocess_s},
                    {"segment", best.timings.segment_s},
                    {"sequence", best.timings.sequence_s},
                    {"total", best.timings.total_s}};
  nlohmann::json per_angle = nlohmann::json::array();
  for (std::size_t i = 0; i < study->angles_deg.size(); ++i) {
    nlohmann::json row = metrics_json(study->metrics[i]);
    row["zigzag_angle_deg"] = study->angles_deg[i];
    per_angle.push_back(row);
  }
  s["orientations"] = per_angle;
  std::vector<std::string> warnings = stl->warnings;
  warnings.insert(warnings.end(), best.warnings.begin(), best.warnings.end());
  if (!warnings.empty()) s["warnings"] = warnings;

  // Tables 1-2 of the paper: the three strategies on the same part at the chosen angle.
  std::ostringstream table;
  table << "strategy,lift_offs,air_length_mm,total_length_mm,regions\n";

  nlohmann::json strategies = nlohmann::json::object();
  for (RoughSequence q :
       {RoughSequence::kZigzag, RoughSequence::kTrappedArea, RoughSequence::kGa}) {
    RoughMetrics m = best.metrics;
    if (q != rp.sequence) {
      RoughParams other = rp;
      other.sequence = q;
      other.zigzag_angle_deg = best.rotation_deg;
      auto r = rough(stl->mesh, other, ctx);
      if (!r.ok()) return r.status().with_context(in.input_path);
      m = r->metrics;
    }
    strategies[std::string(rough_sequence_name(q))] = metrics_json(m);
    table << rough_sequence_name(q) << ',' << m.lift_offs << ',' << m.air_length_mm << ','
          << m.total_length_mm << ',' << m.regions << '\n';
  }
  s["strategies"] = strategies;
  out.report_files["strategies.csv"] = table.str();
  return out;
}

const OperationRegistrar kRegistrar{Operation{
    "rough",
    "voxel zig-zag roughing with Trapped Area regions sequenced by a GA (seed 003)",
    "part STL (closed solid, mm)",
    true,
    true,
    {
        {"stepover", ParamType::kNumber, nullptr,
         "sidestep = voxel width, mm (default 66 % of the tool diameter: 6.6 for ø10)", true},
        {"stepdown", ParamType::kNumber, 2.0, "depth of cut = voxel height, mm"},
        {"stock_to_leave", ParamType::kNumber, 3.0, "finishing allowance, mm"},
        {"sequence", ParamType::kString, "ga",
         "region order: ga (GA + local search), none (Trapped Area order) or zigzag (plain)"},
        {"rotate", ParamType::kNumberList, nlohmann::json::array({0.0}),
         "feed directions to compare, degrees from x; the shortest path wins"},
        {"seed", ParamType::kInteger, 1, "GA random seed"},
        {"population", ParamType::kInteger, 0, "GA population (0 = 20-100 by size)"},
        {"generations", ParamType::kInteger, 1000, "GA generation limit"},
        {"offset", ParamType::kString, "disk",
         "tool offset: disk (exact) or paper (n0-voxel square, Eq. 3.1)"},
        {"margin", ParamType::kNumber, 0.0, "stock beyond the part's box sideways, mm"},
        {"top_margin", ParamType::kNumber, 0.0, "stock above the part's top, mm"},
        {"stock", ParamType::kString, nullptr,
         "stock: box:x0,y0,z0,x1,y1,z1 or an STL (its bounding box is used)", true},
        {"clearance", ParamType::kNumber, 5.0, "clearance plane above the stock, mm"},
        {"feed", ParamType::kNumber, 1000.0, "cutting feed, mm/min"},
        {"plunge_feed", ParamType::kNumber, 300.0, "plunge feed, mm/min"},
        {"lift_penalty", ParamType::kNumber, 300.0,
         "extra cost of a lift-off against a stay-down link, mm of path"},
        {"repair", ParamType::kBool, false, "accept open meshes (filled conservatively)"},
    },
    run_rough,
}};

}  // namespace
}  // namespace swarf::cli
