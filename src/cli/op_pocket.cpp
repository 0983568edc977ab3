// `swarf pocket`: the adaptive pocket of seed 000 (swarf/pocket/adaptive.h).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "cli/operation.h"
#include "cli/pocket_params.h"
#include "swarf/pocket/adaptive.h"
#include "swarf/report/image.h"
#include "swarf/report/plot.h"
#include "swarf/report/pocket_picture.h"
#include "swarf/toolpath/postprocess.h"

namespace swarf::cli {
namespace {

using nlohmann::json;

double num(const json& p, const char* key) {
  return p.at(key).get<double>();
}

std::string engagement_chart(const AdaptiveResult& r) {
  Series eng{"engagement (deg)", {}, {}, "#1f77b4"};
  Series dev{"deviation (deg)", {}, {}, "#ff7f0e"};
  double s = 0.0;
  for (const AdaptiveStep& st : r.steps) {
    s += st.length_mm;
    eng.x.push_back(s);
    eng.y.push_back(st.engagement_deg);
    dev.x.push_back(s);
    dev.y.push_back(st.deviation_deg);
  }
  return line_chart_svg({eng, dev}, "Engagement and deviation along the path (seed 000 Fig. 8)",
                        "path length (mm)", "degrees");
}

Result<OperationOutput> run(const OperationInput& in) {
  const json& p = in.params;
  auto pocket = read_pocket(in.input_path);
  if (!pocket) return pocket.status();
  AdaptiveParams ap;
  if (!p.at("stepover").is_null()) ap.stepover_mm = num(p, "stepover");
  if (!p.at("engagement").is_null()) ap.engagement_deg = num(p, "engagement");
  ap.tolerance_pct = num(p, "tolerance");
  ap.step_mm = num(p, "step");
  ap.max_deviation_deg = num(p, "max_deviation");
  ap.resolution_mm = num(p, "resolution");
  ap.max_pixels = num(p, "max_pixels");
  ap.climb = !p.at("conventional").get<bool>();
  ap.depth_mm = num(p, "depth");
  ap.stepdown_mm = num(p, "stepdown");
  ap.floor_stock_mm = num(p, "floor_stock");
  ap.wall_stock_mm = num(p, "wall_stock");
  ap.top_z_mm = num(p, "top_z");
  ap.clearance_z_mm = num(p, "clearance_z");
  ap.feed_mm_min = num(p, "feed");
  ap.plunge_feed_mm_min = num(p, "plunge_feed");
  ap.ramp_feed_mm_min = num(p, "ramp_feed");
  ap.link_feed_mm_min = num(p, "link_feed");
  ap.ramp_angle_deg = num(p, "ramp_angle");
  ap.helix_radius_mm = num(p, "helix_radius");
  ap.plunge_candidates = p.at("plunge_candidates").get<int>();
  ap.straight_plunge = p.at("straight_plunge").get<bool>();
  ap.channel_plunge = p.at("channel_plunge").get<bool>();
  ap.one_way = p.at("one_way").get<bool>();
  ap.smooth_links = p.at("smooth_links").get<bool>();
  ap.smooth_corners = p.at("smooth_corners").get<bool>();
  ap.smoothing_iterations = p.at("smoothing").get<int>();
  ap.simplify_tolerance_mm = num(p, "simplify_tolerance");
  ap.wall_scallop_mm = num(p, "wall_scallop");
  ap.cut_map = in.wants_report;  // only the report's picture reads it
  auto r = adaptive_pocket(*pocket, *in.tool, ap, in.ctx ? *in.ctx : default_context());
  if (!r) return r.status();
  OperationOutput out;
  out.notes = pocket->notes;
  Toolpath tp = r->toolpath;
  if (p.at("arcs").get<bool>())
    tp = fit_pocket_arcs(tp, *pocket, in.tool->radius(), ap.wall_stock_mm);
  out.toolpaths.push_back(std::move(tp));
  const AdaptiveSummary s = summarize(*r, ap);
  out.summary["cutting_length_mm"] = s.cutting_length_mm;
  out.summary["air_length_mm"] = s.air_length_mm;
  out.summary["estimated_time_s"] = s.time_s;
  out.summary["engagement_target_deg"] = r->target_engagement_deg;
  out.summary["engagement_mean_deg"] = s.engagement_mean_deg;
  out.summary["engagement_p5_deg"] = s.engagement_p5_deg;
  out.summary["engagement_p95_deg"] = s.engagement_p95_deg;
  out.summary["engagement_within_20pct"] = s.within_20pct;
  out.summary["max_deviation_deg"] = s.max_deviation_deg;
  out.summary["resolution_mm"] = r->resolution_mm;
  // Said only when the pixel budget made the simulation coarser than the rule.
  if (r->rule_resolution_mm > 0.0 && r->resolution_mm > r->rule_resolution_mm)
    out.summary["resolution_rule_mm"] = r->rule_resolution_mm;
  out.summary["layers"] = r->layers;
  out.summary["retracts_per_layer"] = r->retracts_per_layer;
  out.summary["material_left_mm2"] = r->material_left_mm2;
  // Said when it is more than crumbs: the random pockets leave up to 0.5 mm^2 in corners.
  const double crumbs_mm2 = std::max(1.0, 1e-4 * area(pocket->region));
  if (r->material_left_mm2 > crumbs_mm2) {
    char text[200];
    std::snprintf(text, sizeof text,
                  "%.1f mm^2 that the tool reaches is left uncut (material_left_mm2; the "
                  "report's picture shows where)",
                  r->material_left_mm2);
    out.notes.push_back(text);
  }
  // Said only when there is one: it needs a centre-cutting end mill.
  if (r->straight_plunges > 0) {
    out.summary["straight_plunges"] = r->straight_plunges;
    out.notes.push_back(std::to_string(r->straight_plunges) +
                        " straight plunge(s) where no helix or ramp fits: the end mill must be "
                        "centre-cutting (--no-straight-plunge leaves that material instead)");
  }
  if (r->channels > 0) {
    out.summary["channels"] = r->channels;
    out.summary["channel_plunges"] = r->channel_plunges;
    out.notes.push_back(std::to_string(r->channels) +
                        " channel(s) a little wider than the tool "
                        "plunged along a wall in " +
                        std::to_string(r->channel_plunges) +
                        " crescent plunges a layer and side-milled");
  }
  if (r->neck_plunges > 0) {
    out.summary["neck_plunges"] = r->neck_plunges;
    out.summary["neck_length_mm"] = s.plunged_length_mm;
    char text[256];
    std::snprintf(text, sizeof text,
                  "%.1f mm of necks as wide as the tool and of moves out of straight plunges' "
                  "holes plunged through in %d crescent plunges a layer rather than slotted "
                  "(--no-straight-plunge slots them)",
                  s.plunged_length_mm, r->neck_plunges);
    out.notes.push_back(text);
  }
  // The adaptive pocket plans a flat end at the floor. A ball or bull-nose end mill cuts the
  // same path without a gouge (its disk at the walls is the full diameter), but leaves a
  // fillet of its corner radius where the floor meets the walls and, where a pass steps over
  // more than its flat, cusps on the floor: said, with their height, rather than refused.
  if (in.tool->kind != ToolKind::kFlat) {
    const double rc = in.tool->corner_radius_mm;
    const double flat = in.tool->diameter_mm - 2.0 * rc;
    const double ae = stepover_for_angle_mm(r->target_engagement_deg, in.tool->radius());
    const double over = std::min(std::max(0.0, 0.5 * (ae - flat)), rc);
    const double cusp = rc - std::sqrt(rc * rc - over * over);
    char text[240];
    std::snprintf(text, sizeof text,
                  "%s end mill: the path is planned for a flat end; the floor keeps a %.3g mm "
                  "fillet at the walls",
                  std::string(tool_kind_name(in.tool->kind)).c_str(), rc);
    std::string note = text;
    if (cusp > 0.0) {
      std::snprintf(text, sizeof text, " and cusps up to %.3g mm high between passes", cusp);
      note += text;
    }
    out.notes.push_back(note);
    out.summary["floor_cusp_mm"] = cusp;
  }
  if (r->candidate_time_s.size() > 1) {
    out.summary["plunge_candidate_time_s"] = r->candidate_time_s;
    out.summary["plunge_candidate_kept"] = r->chosen_candidate;
  }
  out.summary["summary"] = summary_line(s);
  if (in.wants_csv || in.wants_report) out.csv_override = steps_csv(*r);
  if (in.wants_report) {
    out.report_files["steps.csv"] = *out.csv_override;
    out.report_files["engagement.svg"] = engagement_chart(*r);
    out.report_files["engagement.png"] = png_bytes(pocket_engagement_picture(*r));
  }
  out.plot_background = pocket->region;
  return out;
}

const OperationRegistrar kRegistrar(Operation{
    "pocket", "adaptive (constant-engagement) pocket clearing, seed 000",
    "pocket outline: .json {outer, islands}, .svg or .dxf (mm)", true, true,
    with_pocket_layer_params(
        {
            Param{"stepover", ParamType::kNumber, nullptr,
                  "target radial stepover, mm (default 10 % of the tool diameter)", true},
            Param{"engagement", ParamType::kNumber, nullptr,
                  "target engagement angle instead of --stepover, degrees", true},
            number_param("tolerance", 10.0, "engagement band accepted without search, % of target"),
            number_param("step", 0.0,
                         "path step length, mm (0 = stepover / 4 within [D / 40, D / 20])"),
            number_param("max_deviation", 90.0, "largest turn between two steps, degrees"),
            number_param("resolution", 0.0, "simulation pixel size, mm (0 = automatic)"),
            number_param("max_pixels", 6e7,
                         "largest simulation image, pixels (the automatic resolution is "
                         "coarsened to fit)"),
            Param{"one_way", ParamType::kBool, false,
                  "every pass climb (conventional with --conventional): a pass that would "
                  "come back the other way ends and the next starts over the cleared floor; "
                  "slower to compute and to run",
                  false},
            Param{"smooth_links", ParamType::kBool, false,
                  "fly links that would turn back on a pass as loops over the cleared floor "
                  "(fewer reversals, a little more path)",
                  false},
            Param{"smooth_corners", ParamType::kBool, true,
                  "round a cutting pass's turns of a few degrees or more between two moves "
                  "by a curve through the same points (the contact arc then no longer jumps "
                  "by the turn at each move's end)",
                  false},
            number_param("link_feed", 0.0,
                         "feed of keep-tool-down links over cleared floor, mm/min (0 = 5000, "
                         "the rapid rate of the time estimates)"),
        },
        "helix and ramp",
        {
            number_param("helix_radius", 0.0,
                         "helix radius, mm (0 = 0.3 x diameter, or what fits)"),
            number_param("plunge_feed", 300.0,
                         "feed of straight plunges (necks, entries with no room for a helix "
                         "or ramp) and of descents through a cut hole, mm/min"),
            Param{"plunge_candidates", ParamType::kInteger, 1,
                  "plunge points tried along the medial axis (the fastest path wins)", false},
            Param{"straight_plunge", ParamType::kBool, true,
                  "where no helix or ramp fits, go straight down at the plunge feed (needs a "
                  "centre-cutting end mill), and plunge through necks as wide as the tool "
                  "rather than slot them; off: leave that material (material_left_mm2) and "
                  "slot the necks",
                  false},
            Param{"channel_plunge", ParamType::kBool, true,
                  "where the path would loop along a channel less than two stepovers wider "
                  "than the tool, plunge along one wall and side-mill the strip left along "
                  "the other in the band, where that is no slower than the loops; off: cut "
                  "the loops",
                  false},
            Param{"smoothing", ParamType::kInteger, 2, "Chaikin passes over link joins", false},
            number_param("simplify_tolerance", 0.0, "output simplification, mm (0 = pixel / 4)"),
            number_param("wall_scallop", 0.1,
                         "scallops higher than this (mm) where passes meet a wall at an angle "
                         "are taken off once the path is done, square to the wall (0 = leave "
                         "them); links along a wall keep twice this off it"),
            Param{"arcs", ParamType::kBool, false, "fit G2/G3 arcs to the output", false},
        }),
    run});

}  // namespace
}  // namespace swarf::cli
