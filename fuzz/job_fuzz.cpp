// libFuzzer target: job files. parse_job must reject any input cleanly, never crash.
// A stand-in operation with a parameter of every type lets the fuzzer reach the
// parameter checks behind the operation lookup.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "cli/job.h"

namespace {

const swarf::cli::OperationRegistrar kFuzzOperation{swarf::cli::Operation{
    "pocket",
    "stand-in for fuzzing",
    "input",
    true,
    true,
    {{"stepover", swarf::cli::ParamType::kNumber, 1.0, "mm"},
     {"layers", swarf::cli::ParamType::kInteger, 1, "count"},
     {"pattern", swarf::cli::ParamType::kString, "scan", "name"},
     {"climb", swarf::cli::ParamType::kBool, true, "flag"},
     {"rotate", swarf::cli::ParamType::kNumberList, nlohmann::json::array({0.0}), "deg"},
     {"stock", swarf::cli::ParamType::kString, nullptr, "stock", true}},
    [](const swarf::cli::OperationInput&) -> swarf::Result<swarf::cli::OperationOutput> {
      return swarf::cli::OperationOutput{};
    }}};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const swarf::cli::Operation* op = nullptr;
  swarf::cli::OperationInput input;
  swarf::cli::OutputSpec out;
  (void)swarf::cli::parse_job(text, "/nonexistent/job.json", {}, op, input, out);
  return 0;
}
