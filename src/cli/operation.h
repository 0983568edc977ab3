// How an operation plugs into the command line and job files. Each operation lives in
// src/cli/op_<name>.cpp and registers itself with a static OperationRegistrar, so adding
// one touches no shared file. Its parameters are declared once: the CLI gets a flag for
// each (--stepover for key "stepover"), a job file's "operation" object uses the same keys,
// and both arrive at run() as one JSON object with defaults filled in and types checked.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "swarf/core/context.h"
#include "swarf/core/status.h"
#include "swarf/polygon/polygon.h"
#include "swarf/tool/tool.h"
#include "swarf/toolpath/toolpath.h"

namespace swarf::cli {

enum class ParamType { kNumber, kInteger, kString, kBool, kNumberList };

struct Param {
  std::string key;  ///< JSON key, snake_case; the flag is --key-with-dashes
  ParamType type = ParamType::kNumber;
  nlohmann::json default_value;  ///< null: required unless `optional`
  std::string help;              ///< what it means to a machinist, with units
  bool optional = false;         ///< may be absent (run() sees null)
};

/// A number parameter with a default, the common case: number_param("stepover", 1.0, "mm").
inline Param number_param(std::string key, double default_value, std::string help) {
  return Param{std::move(key), ParamType::kNumber, default_value, std::move(help), false};
}

/// What run() gets.
struct OperationInput {
  std::string input_path;    ///< the positional input (pocket, STL, G-code, CSV), as given
  std::optional<Tool> tool;  ///< from --tool / --tool-library, when the operation takes one
  nlohmann::json params;     ///< every declared key, defaults filled in
  const Context* ctx = nullptr;
  /// Whether a --report folder / --csv file was asked for: operations may skip building
  /// report files (pictures, tables) nobody will read. Set by execute().
  bool wants_report = true;
  bool wants_csv = true;
};

/// What run() returns; the framework writes it (atomically) where the user asked.
struct OperationOutput {
  std::vector<Toolpath> toolpaths;  ///< G-code (-o) and CSV (--csv) come from these
  nlohmann::json summary =
      nlohmann::json::object();  ///< report/summary.json, and one line on stderr
  /// Extra report files, name -> bytes, written into the --report folder.
  std::map<std::string, std::string> report_files;
  /// Replaces the toolpath CSV when the operation's natural table is not the toolpath
  /// (CL points of a drop-cutter, forces of a simulation).
  std::optional<std::string> csv_override;
  /// Files the operation writes instead of G-code (for example fit-coefficients' JSON).
  std::optional<std::string> primary_output;
  /// Drawn under the toolpath in the SVG plot.
  PolygonSet plot_background;
  /// What the user must not miss, one line each, printed after the summary line.
  std::vector<std::string> notes;
};

struct Operation {
  std::string name;        ///< subcommand and job "type"
  std::string help;        ///< one line for --help
  std::string input_help;  ///< what the positional input is
  bool takes_tool = true;
  bool writes_gcode = true;
  std::vector<Param> params;
  std::function<Result<OperationOutput>(const OperationInput&)> run;
};

/// All registered operations, sorted by name.
const std::vector<Operation>& operations();
const Operation* find_operation(const std::string& name);

struct OperationRegistrar {
  explicit OperationRegistrar(Operation op);
};

}  // namespace swarf::cli
