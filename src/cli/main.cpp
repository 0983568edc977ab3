// swarf: the command-line front end, a thin layer over libswarf. Each operation's
// subcommand is generated from its declared parameters (src/cli/operation.h), so the flags
// mirror the job file's keys exactly.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <exception>
#include <map>
#include <memory>
#include <string>

#include "cli/execute.h"
#include "cli/job.h"
#include "cli/operation.h"

namespace swarf::cli {
namespace {

constexpr int kExitOk = 0;
constexpr int kExitInternal = 1;
constexpr int kExitBadInput = 2;

std::string flag_of(const std::string& key) {
  std::string f = "--" + key;
  for (char& c : f)
    if (c == '_') c = '-';
  return f;
}

bool parse_double(const std::string& s, double& out) {
  const char* end = s.data() + s.size();
  auto [ptr, ec] = std::from_chars(s.data(), end, out);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

/// A flag whose value must be a number over 0 (or 0 as well, with or_zero).
CLI::Validator number_over_zero(bool or_zero) {
  return CLI::Validator(
      [or_zero](const std::string& text) {
        double v = 0.0;
        if (parse_double(text, v) && (v > 0.0 || (or_zero && v == 0.0))) return std::string();
        return "'" + text + "' must be a number " + (or_zero ? "0 or more" : "over 0");
      },
      or_zero ? "NUMBER>=0" : "NUMBER>0");
}

/// Turns the text a user typed for a parameter into its JSON value.
Result<nlohmann::json> value_from_flag(const Param& p, const std::string& text) {
  const std::string flag = flag_of(p.key);
  switch (p.type) {
    case ParamType::kNumber: {
      double v;
      if (!parse_double(text, v)) return bad_parameter(flag + ": '" + text + "' is not a number");
      return nlohmann::json(v);
    }
    case ParamType::kInteger: {
      long long v;
      const char* end = text.data() + text.size();
      auto [ptr, ec] = std::from_chars(text.data(), end, v);
      if (ec != std::errc() || ptr != end)
        return bad_parameter(flag + ": '" + text + "' is not a whole number");
      return nlohmann::json(v);
    }
    case ParamType::kString:
      return nlohmann::json(text);
    case ParamType::kBool:
      return nlohmann::json(text == "true" || text == "1" || text == "yes");
    case ParamType::kNumberList: {
      nlohmann::json list = nlohmann::json::array();
      std::size_t start = 0;
      while (start <= text.size()) {
        const std::size_t comma = text.find(',', start);
        const std::string item =
            text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        double v;
        if (!parse_double(item, v))
          return bad_parameter(flag + ": '" + item + "' in '" + text + "' is not a number");
        list.push_back(v);
        if (comma == std::string::npos) break;
        start = comma + 1;
      }
      return list;
    }
  }
  return bad_parameter(flag + ": unsupported parameter type");
}

struct Globals {
  bool quiet = false;
  int threads = 0;
};

/// A one-line progress bar on stderr, only when stderr is a terminal and not --quiet.
Context make_context(const Globals& g) {
  Context ctx;
  ctx.threads = g.threads;
  if (!g.quiet && isatty(STDERR_FILENO)) {
    ctx.progress = [](std::string_view stage, double fraction) {
      const int width = 30;
      const int filled = static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * width));
      std::fprintf(stderr, "\r%-24.*s [%.*s%*s] %3d%%", static_cast<int>(stage.size()),
                   stage.data(), filled, "##############################", width - filled, "",
                   static_cast<int>(std::lround(fraction * 100)));
      if (fraction >= 1.0) std::fprintf(stderr, "\r%*s\r", 70, "");
      std::fflush(stderr);
    };
  }
  return ctx;
}

int report_failure(const Status& s) {
  std::fprintf(stderr, "swarf: %s\n", s.to_string().c_str());
  return s.code() == Error::kInternal ? kExitInternal : kExitBadInput;
}

/// State bound to one operation's subcommand.
struct OperationFlags {
  const Operation* op = nullptr;
  std::string input;
  ToolSpec tool;
  int tool_number = -1;
  int flutes = -1;
  double helix = -1, flute_length = -1;
  OutputSpec out;
  std::string dialect = "iso";
  std::map<std::string, std::string> values;  // param key -> text typed
  std::map<std::string, bool> switches;       // bool param key -> --key / --no-key
  std::map<std::string, CLI::Option*> options;
};

int run_operation(OperationFlags& f, const Globals& g) {
  nlohmann::json given = nlohmann::json::object();
  for (const Param& p : f.op->params) {
    CLI::Option* o = f.options.at(p.key);
    if (o->count() == 0) continue;
    if (p.type == ParamType::kBool) {
      given[p.key] = f.switches[p.key];
      continue;
    }
    Result<nlohmann::json> v = value_from_flag(p, f.values[p.key]);
    if (!v.ok()) return report_failure(v.status());
    given[p.key] = *v;
  }
  Result<nlohmann::json> params = complete_params(*f.op, given, "swarf " + f.op->name);
  if (!params.ok()) return report_failure(params.status());
  Result<Dialect> dialect = parse_dialect(f.dialect);
  if (!dialect.ok()) return report_failure(dialect.status());
  f.out.gcode_options.dialect = *dialect;

  const Context ctx = make_context(g);
  OperationInput input;
  input.input_path = f.input;
  input.params = *params;
  input.ctx = &ctx;
  if (f.op->takes_tool) {
    if (f.tool_number >= 0) f.tool.number = f.tool_number;
    if (f.flutes > 0) f.tool.flutes = f.flutes;
    if (f.helix >= 0) f.tool.helix_angle_deg = f.helix;
    if (f.flute_length > 0) f.tool.flute_length_mm = f.flute_length;
    Result<Tool> tool = resolve_tool(f.tool);
    if (!tool.ok()) return report_failure(tool.status());
    input.tool = *tool;
  }
  Result<std::string> line = execute(*f.op, std::move(input), f.out);
  if (!line.ok()) return report_failure(line.status());
  if (!g.quiet) std::fprintf(stderr, "%s\n", line->c_str());
  return kExitOk;
}

void add_operation(CLI::App& app, const Operation& op, OperationFlags& f, Globals& g,
                   int& exit_code) {
  f.op = &op;
  CLI::App* sub = app.add_subcommand(op.name, op.help);
  sub->add_option("input", f.input, op.input_help)->required();
  if (op.takes_tool) {
    auto* grp = sub->add_option_group("Tool");
    grp->add_option("--tool", f.tool.spec,
                    "cutter as KIND:DIAMETER[:CORNER_RADIUS], mm; KIND flat, ball or bull");
    grp->add_option("--tool-library", f.tool.library, "tool library JSON file");
    grp->add_option("--tool-number", f.tool_number, "tool number (T word; in the library)");
    grp->add_option("--flutes", f.flutes, "number of flutes (default 2)");
    grp->add_option("--helix", f.helix, "helix angle, degrees (default 30)");
    grp->add_option("--flute-length", f.flute_length, "flute length, mm (default 30)");
  }
  auto* outg = sub->add_option_group("Output");
  if (op.writes_gcode) {
    outg->add_option("-o,--output", f.out.gcode, "G-code program to write");
    outg->add_option("--dialect", f.dialect, "iso, fanuc, linuxcnc or grbl (default iso)");
    outg->add_option("--program-number", f.out.gcode_options.program_number,
                     "Fanuc O-number (default 1000)");
    outg->add_flag("--line-numbers", f.out.gcode_options.line_numbers, "write N-words");
    outg->add_option("--svg", f.out.svg, "top-view SVG plot of the toolpath");
  } else {
    outg->add_option("-o,--output", f.out.gcode, "output file");
  }
  outg->add_option("--csv", f.out.csv, "table of the result as CSV");
  // The machine the summary's times are estimated for (machining_time_s at the feeds,
  // machine_time_s also with its acceleration and cornering).
  auto* mg = sub->add_option_group("Machine");
  mg->add_option("--rapid-rate", f.out.machine.rapid_mm_min,
                 "rapid traverse, mm/min (default 5000)")
      ->check(number_over_zero(false));
  mg->add_option("--accel", f.out.machine.accel_mm_s2,
                 "acceleration, mm/s^2, for machine_time_s (default 1000; 0 = none)")
      ->check(number_over_zero(true));
  mg->add_option("--junction-deviation", f.out.machine.junction_deviation_mm,
                 "corner rounding allowed at speed, mm (grbl $11; default 0.01; 0 = exact stop)")
      ->check(number_over_zero(true));
  outg->add_option("--report", f.out.report, "folder for the summary JSON and pictures");
  auto* pg = sub->add_option_group("Operation");
  for (const Param& p : op.params) {
    std::string help = p.help;
    if (!p.default_value.is_null()) help += " (default " + p.default_value.dump() + ")";
    if (p.type == ParamType::kBool) {
      // A switch: --zigzag turns it on, --no-zigzag off; absent keeps the default.
      const std::string off = "!--no-" + flag_of(p.key).substr(2);
      f.options[p.key] = pg->add_flag(flag_of(p.key) + "," + off, f.switches[p.key], help);
    } else {
      static const char* kTypeNames[] = {"NUMBER", "INT", "TEXT", "", "N,N,..."};
      f.options[p.key] = pg->add_option(flag_of(p.key), f.values[p.key], help)
                             ->type_name(kTypeNames[static_cast<int>(p.type)]);
    }
  }
  sub->callback([&f, &g, &exit_code] {
    f.out.gcode_options.title = f.op->name + " " + f.input;
    exit_code = run_operation(f, g);
  });
}

int run_main(int argc, char** argv) {
  CLI::App app{"swarf: toolpaths and G-code from parts and pockets, and simulation of them"};
  app.set_version_flag("--version", std::string("swarf ") + SWARF_VERSION);
  app.require_subcommand(1);
  app.fallthrough();
  Globals g;
  app.add_flag("-q,--quiet", g.quiet, "print nothing but errors");
  app.add_option("--threads", g.threads, "worker threads (default: all cores)");
  int exit_code = kExitOk;

  std::string job_path;
  JobOptions job_options;
  CLI::App* run =
      app.add_subcommand("run", "run a job file (JSON: part, tool, operation, outputs)");
  run->add_option("job", job_path, "job file")->required();
  run->add_option("--output-dir", job_options.output_dir,
                  "write the job's outputs here (default: beside the job file)");
  run->callback([&] {
    const Operation* op = nullptr;
    OperationInput input;
    OutputSpec out;
    Status s = load_job(job_path, job_options, op, input, out);
    if (!s.ok()) {
      exit_code = report_failure(s);
      return;
    }
    const Context ctx = make_context(g);
    input.ctx = &ctx;
    Result<std::string> line = execute(*op, std::move(input), out);
    if (!line.ok()) {
      exit_code = report_failure(line.status());
      return;
    }
    if (!g.quiet) std::fprintf(stderr, "%s\n", line->c_str());
  });

  std::vector<std::unique_ptr<OperationFlags>> flags;
  for (const Operation& op : operations()) {
    flags.push_back(std::make_unique<OperationFlags>());
    add_operation(app, op, *flags.back(), g, exit_code);
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::fprintf(stderr, "swarf: %s\n", e.what());
    std::fprintf(stderr, "Run with --help for more information.\n");
    return kExitBadInput;
  }
  return exit_code;
}

}  // namespace
}  // namespace swarf::cli

int main(int argc, char** argv) {
  try {
    return swarf::cli::run_main(argc, argv);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "swarf: internal error: %s\n", e.what());
    return 1;
  }
}
