#include "cli/execute.h"

#include <cmath>
#include <filesystem>
#include <sstream>

#include "swarf/core/io.h"
#include "swarf/report/plot.h"
#include "swarf/tool/library.h"
#include "swarf/toolpath/metrics.h"

namespace swarf::cli {

using nlohmann::json;

Result<Tool> resolve_tool(const ToolSpec& spec) {
  Tool tool;
  if (!spec.library.empty()) {
    if (!spec.spec.empty()) return bad_parameter("give either --tool or --tool-library, not both");
    if (!spec.number) return bad_parameter("--tool-library needs --tool-number");
    Result<ToolLibrary> lib = read_tool_library(spec.library);
    if (!lib.ok()) return lib.status();
    const Tool* t = lib->find(*spec.number);
    if (t == nullptr)
      return bad_parameter(spec.library + ": no tool number " + std::to_string(*spec.number));
    tool = *t;
  } else if (!spec.spec.empty()) {
    Result<Tool> t = parse_tool_spec(spec.spec);
    if (!t.ok()) return t.status();
    tool = *t;
    if (spec.number) tool.number = *spec.number;
  } else {
    return bad_parameter("this operation needs a tool: --tool KIND:DIAMETER[:CORNER_RADIUS]");
  }
  if (spec.flutes) tool.flutes = *spec.flutes;
  if (spec.helix_angle_deg) tool.helix_angle_deg = *spec.helix_angle_deg;
  if (spec.flute_length_mm) tool.flute_length_mm = *spec.flute_length_mm;
  SWARF_RETURN_IF_ERROR(validate(tool));
  return tool;
}

namespace {

const char* type_name(ParamType t) {
  switch (t) {
    case ParamType::kNumber:
      return "a number";
    case ParamType::kInteger:
      return "a whole number";
    case ParamType::kString:
      return "a string";
    case ParamType::kBool:
      return "true or false";
    case ParamType::kNumberList:
      return "a list of numbers";
  }
  return "?";
}

bool type_matches(ParamType t, const json& v) {
  switch (t) {
    case ParamType::kNumber:
      return v.is_number() && std::isfinite(v.get<double>());
    case ParamType::kInteger:
      return v.is_number_integer();
    case ParamType::kString:
      return v.is_string();
    case ParamType::kBool:
      return v.is_boolean();
    case ParamType::kNumberList:
      if (!v.is_array()) return false;
      for (const json& e : v)
        if (!e.is_number()) return false;
      return true;
  }
  return false;
}

}  // namespace

Result<json> complete_params(const Operation& op, const json& given, const std::string& where) {
  if (!given.is_object()) return bad_input(where + ": expected an object of parameters");
  json out = json::object();
  for (auto it = given.begin(); it != given.end(); ++it) {
    if (it.key() == "type") continue;
    const Param* p = nullptr;
    for (const Param& q : op.params)
      if (q.key == it.key()) p = &q;
    if (p == nullptr) {
      std::string known;
      for (const Param& q : op.params)
        known += (known.empty() ? "" : ", ") + q.key;
      return bad_input(where + ": unknown parameter \"" + it.key() + "\" for " + op.name +
                       " (known: " + known + ")");
    }
    if (!type_matches(p->type, it.value()))
      return bad_input(where + ": \"" + p->key + "\" must be " + type_name(p->type));
    out[p->key] = it.value();
  }
  for (const Param& p : op.params) {
    if (out.contains(p.key)) continue;
    if (p.default_value.is_null() && !p.optional)
      return bad_input(where + ": missing required parameter \"" + p.key + "\"");
    out[p.key] = p.default_value;
  }
  return out;
}

namespace {

std::string format_summary(const std::string& name, const json& summary) {
  std::ostringstream o;
  o << name << ":";
  int shown = 0;
  for (auto it = summary.begin(); it != summary.end() && shown < 12; ++it) {
    if (!it->is_number() && !it->is_string() && !it->is_boolean()) continue;
    o << " " << it.key() << "=";
    if (it->is_number_float()) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.4g", it->get<double>());
      o << buf;
    } else if (it->is_string()) {
      o << it->get<std::string>();
    } else {
      o << it->dump();
    }
    ++shown;
  }
  return o.str();
}

}  // namespace

Result<std::string> execute(const Operation& op, OperationInput input, const OutputSpec& out) {
  input.wants_report = !out.report.empty();
  input.wants_csv = !out.csv.empty();
  Result<OperationOutput> result = op.run(input);
  if (!result.ok()) return result.status();
  OperationOutput& res = *result;

  if (!res.toolpaths.empty()) {
    ToolpathMetrics total;
    for (const Toolpath& tp : res.toolpaths) {
      const ToolpathMetrics m = compute_metrics(tp, out.machine);
      total.cutting_length_mm += m.cutting_length_mm;
      total.air_length_mm += m.air_length_mm;
      total.lift_offs += m.lift_offs;
      total.machining_time_s += m.machining_time_s;
      total.machine_time_s += m.machine_time_s;
      total.moves += m.moves;
    }
    json& s = res.summary;
    if (!s.contains("cutting_length_mm")) s["cutting_length_mm"] = total.cutting_length_mm;
    if (!s.contains("air_length_mm")) s["air_length_mm"] = total.air_length_mm;
    if (!s.contains("lift_offs")) s["lift_offs"] = total.lift_offs;
    if (!s.contains("machining_time_s")) s["machining_time_s"] = total.machining_time_s;
    if (!s.contains("machine_time_s")) s["machine_time_s"] = total.machine_time_s;
    if (!s.contains("moves")) s["moves"] = total.moves;
  }

  // Everything is computed before the first byte is written; each file is written to a
  // temporary name and renamed, so a failure never leaves a partial output.
  std::vector<std::pair<std::string, std::string>> files;
  if (!out.gcode.empty()) {
    if (res.primary_output) {
      files.emplace_back(out.gcode, *res.primary_output);
    } else if (op.writes_gcode) {
      if (res.toolpaths.empty())
        return Status{Error::kEmptyResult, op.name + " produced no toolpath to write"};
      files.emplace_back(out.gcode, write_gcode(res.toolpaths, out.gcode_options));
    } else {
      return bad_parameter(op.name + " writes no G-code; drop -o");
    }
  }
  std::string svg;
  if ((!out.svg.empty() || !out.report.empty()) && !res.toolpaths.empty()) {
    ToolpathPlotOptions plot;
    plot.background = res.plot_background;
    plot.title = op.name + ": " + input.input_path;
    Toolpath all;
    for (const Toolpath& tp : res.toolpaths)
      all.moves.insert(all.moves.end(), tp.moves.begin(), tp.moves.end());
    svg = toolpath_svg(all, plot);
  }
  if (!out.svg.empty() && !svg.empty()) files.emplace_back(out.svg, svg);
  if (!out.csv.empty()) {
    if (res.csv_override) {
      files.emplace_back(out.csv, *res.csv_override);
    } else {
      Toolpath all;
      for (const Toolpath& tp : res.toolpaths)
        all.moves.insert(all.moves.end(), tp.moves.begin(), tp.moves.end());
      files.emplace_back(out.csv, toolpath_csv(all));
    }
  }
  if (!out.report.empty()) {
    namespace fs = std::filesystem;
    const fs::path dir(out.report);
    json summary = res.summary;
    summary["operation"] = op.name;
    summary["input"] = input.input_path;
    if (input.tool) summary["tool"] = input.tool->description();
    files.emplace_back((dir / "summary.json").string(), summary.dump(2) + "\n");
    if (!svg.empty()) files.emplace_back((dir / "toolpath.svg").string(), svg);
    for (const auto& [name, bytes] : res.report_files)
      files.emplace_back((dir / name).string(), bytes);
  }
  for (const auto& [path, bytes] : files)
    SWARF_RETURN_IF_ERROR(write_file_atomic(path, bytes));

  std::string line = format_summary(op.name, res.summary);
  for (const std::string& note : res.notes)
    line += "\n  note: " + note;
  if (!out.gcode.empty()) line += "\n  wrote " + out.gcode;
  if (!out.csv.empty()) line += "\n  wrote " + out.csv;
  if (!out.report.empty()) line += "\n  wrote " + out.report + "/summary.json";
  return line;
}

}  // namespace swarf::cli
