// Job files: one JSON file naming the part, the tool, the operation with its parameters
// and the outputs, run by `swarf run JOB.json`.
//
//   {
//     "part": "l-pocket.json",                      // relative to the job file's folder
//     "tool": "flat:10",                            // or {"kind": "flat", "diameter": 10, ...}
//                                                   // or {"library": "tools.json", "number": 3}
//     "stock": "box:0,0,-10,100,80,0",              // for operations that take one
//     "operation": {"type": "pocket", "stepover": 1.0, ...},
//     "outputs": {"gcode": "pocket.nc", "dialect": "linuxcnc", "csv": "pocket.csv",
//                 "svg": "pocket.svg", "report": "pocket-report",
//                 "program_number": 1000, "line_numbers": false}
//   }
#pragma once

#include <string>

#include "cli/execute.h"

namespace swarf::cli {

struct JobOptions {
  /// Folder the outputs' relative paths are resolved against; the job's folder when empty.
  std::string output_dir;
};

/// Parses and validates a job; on success fills `op`, `input` and `out`.
Status load_job(const std::string& job_path, const JobOptions& options, const Operation*& op,
                OperationInput& input, OutputSpec& out);
/// Same, from the job's text; `job_path` names it in messages and anchors relative paths.
Status parse_job(std::string_view text, const std::string& job_path, const JobOptions& options,
                 const Operation*& op, OperationInput& input, OutputSpec& out);

}  // namespace swarf::cli
