#include "cli/job.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>

#include "swarf/core/io.h"
#include "swarf/tool/library.h"

namespace swarf::cli {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

Result<Tool> tool_from_json(const json& j, const std::string& where, const fs::path& base) {
  ToolSpec spec;
  if (j.is_string()) {
    spec.spec = j.get<std::string>();
  } else if (j.is_object() && j.contains("library")) {
    if (!j["library"].is_string() || !j.contains("number") || !j["number"].is_number_integer())
      return bad_input(where + ": a library tool needs \"library\" (path) and \"number\"");
    spec.library = (base / j["library"].get<std::string>()).string();
    spec.number = j["number"].get<int>();
  } else if (j.is_object()) {
    json lib = {{"tools", json::array({j})}};
    if (!lib["tools"][0].contains("number")) lib["tools"][0]["number"] = 1;
    Result<ToolLibrary> parsed = parse_tool_library(lib.dump(), where);
    if (!parsed.ok()) return parsed.status();
    return parsed->tools.front();
  } else {
    return bad_input(where + ": expected \"flat:10\"-style text or an object");
  }
  Result<Tool> t = resolve_tool(spec);
  if (!t.ok()) return t.status().with_context(where);
  return t;
}

// The machine the summary's times are for: {"rapid_mm_min": > 0, "accel_mm_s2": >= 0,
// "junction_deviation_mm": >= 0}, each optional.
Status parse_machine(const json& m, const std::string& job_path, MetricsOptions& out) {
  if (!m.is_object()) return bad_input(job_path + ": \"machine\" must be an object");
  struct Field {
    const char* key;
    double* value;
    bool zero_ok;
  };
  const Field fields[] = {{"rapid_mm_min", &out.rapid_mm_min, false},
                          {"accel_mm_s2", &out.accel_mm_s2, true},
                          {"junction_deviation_mm", &out.junction_deviation_mm, true}};
  for (auto it = m.begin(); it != m.end(); ++it) {
    const Field* f = std::find_if(std::begin(fields), std::end(fields),
                                  [&](const Field& q) { return it.key() == q.key; });
    if (f == std::end(fields)) {
      return bad_input(job_path + ": unknown machine key \"" + it.key() +
                       "\" (rapid_mm_min, accel_mm_s2, junction_deviation_mm)");
    }
    const double v = it.value().is_number() ? it.value().get<double>() : -1.0;
    if (!std::isfinite(v) || v < 0.0 || (v == 0.0 && !f->zero_ok)) {
      return bad_input(job_path + ": machine." + it.key() + " must be a number " +
                       (f->zero_ok ? "0 or more" : "over 0"));
    }
    *f->value = v;
  }
  return {};
}

}  // namespace

Status load_job(const std::string& job_path, const JobOptions& options, const Operation*& op,
                OperationInput& input, OutputSpec& out) {
  Result<std::string> text = read_file(job_path);
  if (!text.ok()) return text.status();
  return parse_job(*text, job_path, options, op, input, out);
}

Status parse_job(std::string_view text, const std::string& job_path, const JobOptions& options,
                 const Operation*& op, OperationInput& input, OutputSpec& out) {
  json job;
  try {
    job = json::parse(text);
  } catch (const json::out_of_range& e) {
    // A number too large for a double ("1E999") is not a syntax error but is as bad.
    return bad_input(job_path + ": " + e.what());
  } catch (const json::parse_error& e) {
    // Name the line and column where the syntax breaks.
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    return bad_input(job_path + ":" + std::to_string(line) + ":" + std::to_string(column) +
                     ": not valid JSON");
  }
  if (!job.is_object()) return bad_input(job_path + ": expected a JSON object");
  for (auto it = job.begin(); it != job.end(); ++it) {
    static const char* kKeys[] = {"part",    "tool",    "stock",  "operation",
                                  "outputs", "machine", "comment"};
    bool known = false;
    for (const char* k : kKeys)
      known = known || it.key() == k;
    if (!known)
      return bad_input(job_path + ": unknown key \"" + it.key() +
                       "\" (part, tool, stock, operation, outputs, machine)");
  }
  const fs::path base = fs::path(job_path).parent_path();
  const fs::path out_base = options.output_dir.empty() ? base : fs::path(options.output_dir);

  if (!job.contains("operation") || !job["operation"].is_object() ||
      !job["operation"].contains("type") || !job["operation"]["type"].is_string())
    return bad_input(job_path + ": \"operation\" must be an object with a \"type\"");
  const std::string type = job["operation"]["type"].get<std::string>();
  op = find_operation(type);
  if (op == nullptr) {
    std::string known;
    for (const Operation& o : operations())
      known += (known.empty() ? "" : ", ") + o.name;
    return bad_input(job_path + ": unknown operation type \"" + type + "\" (" + known + ")");
  }
  json given = job["operation"];
  if (job.contains("stock")) {
    bool takes_stock = false;
    for (const Param& p : op->params)
      takes_stock = takes_stock || p.key == "stock";
    if (!takes_stock) return bad_input(job_path + ": operation " + type + " takes no stock");
    if (job["stock"].is_string() && !given.contains("stock")) {
      std::string stock = job["stock"].get<std::string>();
      // A stock file is relative to the job like the part; "box:..." is not a path.
      if (stock.rfind("box:", 0) != 0) stock = (base / stock).string();
      given["stock"] = stock;
    }
  }
  Result<json> params = complete_params(*op, given, job_path + ": operation");
  if (!params.ok()) return params.status();
  input.params = *params;

  if (!job.contains("part") || !job["part"].is_string())
    return bad_input(job_path + ": \"part\" must name the input file");
  input.input_path = (base / job["part"].get<std::string>()).string();

  if (op->takes_tool) {
    if (!job.contains("tool")) return bad_input(job_path + ": \"tool\" is missing");
    Result<Tool> tool = tool_from_json(job["tool"], job_path + ": tool", base);
    if (!tool.ok()) return tool.status();
    input.tool = *tool;
  }

  const json outputs = job.value("outputs", json::object());
  if (!outputs.is_object()) return bad_input(job_path + ": \"outputs\" must be an object");
  auto path_of = [&](const char* key, std::string& dst) -> Status {
    if (!outputs.contains(key)) return {};
    if (!outputs[key].is_string())
      return bad_input(job_path + ": outputs." + key + " must be a path");
    dst = (out_base / outputs[key].get<std::string>()).string();
    return {};
  };
  for (auto it = outputs.begin(); it != outputs.end(); ++it) {
    static const char* kKeys[] = {"gcode",  "dialect",        "csv",         "svg",
                                  "report", "program_number", "line_numbers"};
    bool known = false;
    for (const char* k : kKeys)
      known = known || it.key() == k;
    if (!known) return bad_input(job_path + ": unknown output \"" + it.key() + "\"");
  }
  SWARF_RETURN_IF_ERROR(path_of("gcode", out.gcode));
  SWARF_RETURN_IF_ERROR(path_of("csv", out.csv));
  SWARF_RETURN_IF_ERROR(path_of("svg", out.svg));
  SWARF_RETURN_IF_ERROR(path_of("report", out.report));
  if (outputs.contains("dialect")) {
    if (!outputs["dialect"].is_string())
      return bad_input(job_path + ": outputs.dialect must be iso, fanuc, linuxcnc or grbl");
    Result<Dialect> d = parse_dialect(outputs["dialect"].get<std::string>());
    if (!d.ok()) return d.status().with_context(job_path);
    out.gcode_options.dialect = *d;
  }
  if (outputs.contains("program_number")) {
    if (!outputs["program_number"].is_number_integer() ||
        outputs["program_number"].get<long long>() < 1 ||
        outputs["program_number"].get<long long>() > 9999)
      return bad_input(job_path + ": outputs.program_number must be a whole number 1 to 9999");
    out.gcode_options.program_number = outputs["program_number"].get<int>();
  }
  if (outputs.contains("line_numbers")) {
    if (!outputs["line_numbers"].is_boolean())
      return bad_input(job_path + ": outputs.line_numbers must be true or false");
    out.gcode_options.line_numbers = outputs["line_numbers"].get<bool>();
  }
  SWARF_RETURN_IF_ERROR(parse_machine(job.value("machine", json::object()), job_path, out.machine));
  out.gcode_options.title = fs::path(job_path).filename().string();
  return {};
}

}  // namespace swarf::cli
