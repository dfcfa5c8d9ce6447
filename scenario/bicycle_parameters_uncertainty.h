#pragma once
// The `+/-sigma` of a BicycleParameters benchmark file (Moore et al. 2010) as the scenario's
// `uncertainty:` section (docs/uncertainty.md, "Imported uncertainties", lists the mapping).
#include <map>
#include <string>

namespace motostab::scenario {

/// Standard deviation of each parameter that states one (`name = value+/-sigma`), in the file's
/// units (lam in rad). Several comma-separated repeats are averaged by readBicycleParameters, so
/// their sigma is sqrt(sum sigma_k^2) / n. Parameters without a positive `+/-` sigma are absent.
std::map<std::string, double> readBicycleParameterSigmas(const std::string& file);

/// Scenario key path and factor (scenario unit per file unit) of a benchmark parameter name, e.g.
/// "c" -> ("geometry.trail_m", 1), "lam" -> ("geometry.steer_axis_tilt_deg", 180/pi); an empty
/// path for names that have no scenario key (v, IRzz, IFzz).
std::pair<std::string, double> getScenarioPathOfBicycleParameter(const std::string& name);

/// The `uncertainty:` section (YAML text, ending in a newline) of the nonzero sigmas that map to a
/// scenario key, in the scenario's units; empty if there is none.
std::string formatBicycleParametersUncertainty(const std::map<std::string, double>& sigmas);

}  // namespace motostab::scenario
