// Shared by the simulate and schedule-feed operations: their common parameters and the
// set-up of a simulation from them.
#pragma once

#include <vector>

#include <nlohmann/json.hpp>

#include "cli/operation.h"
#include "swarf/sim/simulate.h"

namespace swarf::cli {

std::vector<Param> simulate_params();

struct SimulationSetup {
  Toolpath program;
  Tool tool;
  sim::Stock stock;
  sim::CuttingCoefficients coefficients;
  sim::SimulationOptions options;
};

/// Reads the program, builds the stock and coefficients, and validates the options.
Result<SimulationSetup> prepare_simulation(const OperationInput& in);

/// Peak, mean, time above limit, removed volume, collisions.
nlohmann::json simulation_summary(const sim::SimulationResult& r);

}  // namespace swarf::cli
