#pragma once
// Import of BicycleParameters benchmark parameter files (Moore et al. 2010; `name = value+/-sigma`),
// given in the Meijaard et al. (2007) frame: x forward, y right, z down, origin at the rear contact.
#include <map>
#include <string>

namespace motostab {

/// Reads `name = value+/-sigma` lines (several comma-separated repeats are averaged).
/// A malformed line is an InputError naming file and line.
std::map<std::string, double> readBicycleParameters(const std::string& file);

/// A scenario YAML text for the bicycle in `file`, with the rolling_no_slip contact. Missing
/// required parameters are InputErrors naming the parameter.
std::string convertBicycleParametersToScenario(const std::string& file, const std::string& name);

}  // namespace motostab
