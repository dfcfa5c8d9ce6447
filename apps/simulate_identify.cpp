#include "apps/simulate_identify.h"

#include <algorithm>

#include "io/input_error.h"
#include "io/result_error.h"
#include "output/response_output.h"

namespace motostab::cli {
namespace {

response::ResponseRecord makeRecord(const simulation::SimulationResult& result, const std::vector<std::string>& signals) {
  response::ResponseRecord record;
  record.source = "simulation";
  record.timeColumn = "time";
  record.signalColumns = signals;
  record.time = result.getColumn("time");
  for (const auto& s : signals) record.signals.push_back(result.getColumn(s));
  return record;
}

}  // namespace

response::IdentificationResult identifySimulatedModes(const simulation::SimulationResult& result, double windowStart,
                                                      const std::vector<std::string>& signals,
                                                      response::IdentificationOptions options) {
  const auto record = makeRecord(result, signals);
  options.windowStart = std::max(options.windowStart, windowStart);
  try {
    return response::identifyModes(record.time, record.signals, options);
  } catch (const io::InputError& e) {  // the simulated response, not the user's input, cannot be fitted
    throw io::ResultError("--identify: the simulated free response from " + std::to_string(options.windowStart) +
                          " s cannot be fitted: " + e.getReason() + " (lengthen --duration or enlarge the perturbation)");
  }
}

response::IdentificationResult writeSimulatedModes(const std::filesystem::path& dir,
                                                   const simulation::SimulationResult& result, double windowStart,
                                                   const nlohmann::json& settings,
                                                   const std::vector<std::string>& signals) {
  const auto record = makeRecord(result, signals);
  const auto modes = identifySimulatedModes(result, windowStart, signals);
  output::writeResponseReport(dir, record, modes, {{"simulation", settings}});
  return modes;
}

}  // namespace motostab::cli
