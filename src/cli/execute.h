// Runs one operation and writes its outputs; shared by the subcommands and `swarf run`.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "cli/operation.h"
#include "swarf/core/status.h"
#include "swarf/gcode/gcode.h"
#include "swarf/toolpath/metrics.h"

namespace swarf::cli {

/// Where the user wants the results; empty paths are not written.
struct OutputSpec {
  std::string gcode;   ///< -o
  std::string csv;     ///< --csv
  std::string svg;     ///< --svg (also written into the report folder)
  std::string report;  ///< --report folder
  GcodeOptions gcode_options;
  /// The machine the summary's times are for (--rapid-rate, --accel, --junction-deviation).
  MetricsOptions machine;
};

/// How the tool was given: a spec ("flat:10"), a library and number, plus overrides.
struct ToolSpec {
  std::string spec;
  std::string library;
  std::optional<int> number;
  std::optional<int> flutes;
  std::optional<double> helix_angle_deg;
  std::optional<double> flute_length_mm;
};

Result<Tool> resolve_tool(const ToolSpec& spec);

/// Checks the types of `given` against the operation's declared parameters, rejects unknown
/// keys, and fills in defaults. `where` names the source in messages ("job.json: operation").
Result<nlohmann::json> complete_params(const Operation& op, const nlohmann::json& given,
                                       const std::string& where);

/// Runs op and writes everything; returns the summary line for stderr.
Result<std::string> execute(const Operation& op, OperationInput input, const OutputSpec& out);

}  // namespace swarf::cli
